#pragma once
// The one reading of a material that every integrator shares (docs/design.md, "One light
// transport"). A PhongMaterial is four lobes, and every lobe is one event of Heckbert's alphabet:
//
//   lobe        f(wo, wi) |cos theta_i|               event   Szymczak's term under a point light
//   Diffuse     kd / pi |cos theta_i|                  <RD>    kd (N.L) I
//   Highlight   ks (H.N)^n / pi                        <RG>    ks (H.N)^n I
//   Mirror      kr (+ kt F with Fresnel), a delta      <RS>    kr * (light from the mirror ray)
//   Refraction  kt (kt (1 - F) with Fresnel), a delta  <TS>    kt * (light from the refracted ray)
//
// A point light of `intensity` I has radiant intensity pi I (lights/point_light.h), so ray casting's
// formula is this BSDF under that light, term by term, and the path tracer reading the same numbers
// produces the same light on the same paths. kd is an albedo (Lambert), emission a radiance.
// Results name their lobe, and so their event: an integrator never maps lobes to events by hand.
#include <array>
#include <cstdint>
#include <optional>

#include "lpe/event.h"
#include "math/types.h"
#include "scene/material.h"

namespace lightpath {

enum class Lobe : std::uint8_t { Diffuse, Highlight, Mirror, Refraction };
inline constexpr int kLobeCount = 4;
// The lobes with a density, which light sampling can reach: one shadow ray serves both.
inline constexpr std::array<Lobe, 2> kSmoothLobes{Lobe::Diffuse, Lobe::Highlight};

// The event a lobe scatters by: its type (reflection or transmission) and scattering letter.
struct ScatterEvent {
    lpe::EventType type;
    lpe::Scatter scatter;
};
constexpr ScatterEvent eventOf(Lobe lobe) {
    switch (lobe) {
        case Lobe::Diffuse: return {lpe::EventType::Reflection, lpe::Scatter::Diffuse};
        case Lobe::Highlight: return {lpe::EventType::Reflection, lpe::Scatter::Glossy};
        case Lobe::Mirror: return {lpe::EventType::Reflection, lpe::Scatter::Specular};
        case Lobe::Refraction: return {lpe::EventType::Transmission, lpe::Scatter::Specular};
    }
    return {lpe::EventType::Reflection, lpe::Scatter::Diffuse};
}
constexpr bool isDelta(Lobe lobe) { return lobe == Lobe::Mirror || lobe == Lobe::Refraction; }

// Light arriving at the camera (radiance) or importance arriving at a light (light tracing): only
// refraction's 1/eta^2 radiance compression tells them apart (Veach 1997, 5.2; pbrt-v4 9.5.2).
enum class TransportMode : std::uint8_t { Radiance, Importance };

struct BsdfSample {
    Vec3 wi{0.0f};      // unit, world space, away from the surface
    Rgb weight{0.0f};   // f |cos theta_i| / pdf: what the path throughput is multiplied by
    float pdf = 0.0f;   // solid-angle density, the lobe choice included; 0 for a delta lobe
    Lobe lobe = Lobe::Diffuse;
};

// One deterministic branch of a delta lobe, with its exact weight: Whitted traces every branch,
// the path tracer picks one in proportion to its weight.
struct SpecularBranch {
    Vec3 wi{0.0f};
    Rgb weight{0.0f};
    Lobe lobe = Lobe::Mirror;
    float albedo = 0.0f;  // the share of energy it carries (weight without radiance compression)
};

class Bsdf {
public:
    // `normal`: unit shading normal on the side of the path's outgoing direction. `entering`: that
    // side is the outside of the material (it refracts from 1 into `ior`).
    Bsdf(const PhongMaterial& material, const Vec3& normal, bool entering,
         TransportMode mode = TransportMode::Radiance);

    bool has(Lobe lobe) const;
    bool hasSmoothLobe() const { return has(Lobe::Diffuse) || has(Lobe::Highlight); }

    // f(wo, wi) |cos theta_i| of a smooth lobe; zero when either direction is below the surface.
    Rgb eval(Lobe lobe, const Vec3& wo, const Vec3& wi) const;
    // The density of sample() returning wi through `lobe` (a smooth one), its choice included.
    float pdf(Lobe lobe, const Vec3& wo, const Vec3& wi) const;
    // One lobe in proportion to its weight, then a direction within it; nullopt when the material
    // scatters nothing or the direction falls below the surface.
    std::optional<BsdfSample> sample(const Vec3& wo, float uLobe, Vec2 u) const;

    // The delta lobes' branches from wo: the mirror ray, then the refracted ray (none on total
    // internal reflection, whose share the mirror ray carries). Returns how many were written.
    int specularBranches(const Vec3& wo, std::array<SpecularBranch, 2>& branches) const;

    const Vec3& normal() const { return normal_; }

private:
    // Probability of choosing each lobe for wo: proportional to its (estimated) albedo.
    std::array<float, kLobeCount> lobeProbabilities(const Vec3& wo) const;

    const PhongMaterial& material_;
    Vec3 normal_;
    float eta_;  // n_incident / n_transmitted for light arriving from the side of the normal
    TransportMode mode_;
};

}  // namespace lightpath
