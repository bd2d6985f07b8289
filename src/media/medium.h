#pragma once
// What a participating medium does with light along a ray (pbrt-v4 ch. 11 and 14): the interface
// every medium implements, next to Material (surfaces) and Light (emitters). A medium attenuates
// by its transmittance T, scatters in with sigma_s and its phase function; a scattering is the
// path event <V.> labelled with the medium's name. Adding a medium is its own file, which
// registers its MediumType (media/medium_type.h).
#include <cstdint>
#include <memory>
#include <string>

#include "math/ray.h"
#include "math/types.h"
#include "media/henyey_greenstein.h"
#include "util/polymorphic_value.h"

namespace lightpath {

// One free-flight sample along a ray segment [0, tMax): either a scattering at t < tMax or passing
// through to tMax. `weight` is what the path's throughput is multiplied by, so that
//   E[weight · f(t) | scattered] P(scattered) + E[weight | passed] P(passed) · g
//     = ∫_0^tMax T(t) sigma_s(t) f(t) dt + T(tMax) g
// for any in-scattered radiance f and radiance g beyond the segment (the volume rendering equation,
// pbrt-v4 eq. 14.3): a scattering's weight carries T(t) sigma_s / pdf(t), a pass's T(tMax) / P(pass).
struct MediumSample {
    bool scattered = false;
    float t = 0.0f;      // the scattering's distance along the ray; tMax when passed
    Rgb weight{1.0f};
};

class Medium {
public:
    virtual ~Medium() = default;

    std::string name;  // its [media.NAME], the label of its <V'NAME'> events

    virtual std::unique_ptr<Medium> clone() const = 0;

    // A free flight from the ray's origin along its unit direction, up to tMax (which may be
    // infinite: then it always scatters unless the medium is vacuum). uChannel chooses the
    // colour channel that drives the distance, uDistance the distance.
    virtual MediumSample sampleDistance(const Ray& ray, float tMax, float uChannel, float uDistance) const = 0;
    // Whether sampleDistance reads uChannel: false when no channel choice can change its result,
    // so the caller may skip computing that number (Sampler::skip1D keeps later ones the same).
    virtual bool choosesChannel() const { return true; }
    // Whether a ray can scatter in it (a `V` event): false for a medium that only absorbs (tinted
    // glass's interior), where no path has a V.
    virtual bool scatters() const { return true; }
    // T between distances t0 <= t1 along the ray, per channel.
    virtual Rgb transmittance(const Ray& ray, float t0, float t1) const = 0;
    virtual HenyeyGreensteinPhase phase(const Vec3& p) const = 0;

protected:
    Medium() = default;
    Medium(const Medium&) = default;
    Medium& operator=(const Medium&) = default;
};

// No medium (vacuum): an object without `interior`, a world without `medium`.
inline constexpr std::uint32_t kNoMedium = 0xffffffffu;

// A scene's medium: owned, polymorphic, copied with the scene.
using MediumSlot = PolymorphicValue<Medium>;

}  // namespace lightpath
