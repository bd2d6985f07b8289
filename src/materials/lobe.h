#pragma once
// The vocabulary every material speaks: its lobes, and the event of Heckbert's alphabet each lobe
// scatters by (pbrt-v4's BxDFFlags play this role). An integrator never maps lobes to events by hand.
#include <array>
#include <cstdint>

#include "lpe/event.h"
#include "math/types.h"

namespace lightpath {

// A lobe names the kind of scattering, not the formula behind it: a material provides the formula.
//   Diffuse     <RD>   e.g. Lambert's kd / pi
//   Highlight   <RG>   a glossy reflection, e.g. Phong's highlight ks (H.N)^n / pi
//   Mirror      <RS>   a perfect reflection, a delta
//   Refraction  <TS>   a perfect refraction, a delta
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

// Which side of a surface a path is on, as a material needs it to scatter.
struct SurfaceSide {
    Vec3 normal{0.0f, 0.0f, 1.0f};  // unit shading normal on the side of the outgoing direction wo
    bool entering = true;           // that side is the material's outside
    TransportMode mode = TransportMode::Radiance;

    // Both directions leave the surface on this side: a reflection lobe can connect them.
    bool bothAbove(const Vec3& wo, const Vec3& wi) const {
        return glm::dot(wi, normal) > 0.0f && glm::dot(wo, normal) > 0.0f;
    }
};

// A direction sampled within one smooth lobe.
struct LobeSample {
    Vec3 wi{0.0f};     // unit, world space, away from the surface
    Rgb weight{0.0f};  // f |cos theta_i| / pdf, the pdf of this lobe alone
    float pdf = 0.0f;  // solid-angle density within the lobe
};

// One deterministic branch of a delta lobe, with its exact weight: Whitted traces every branch,
// the path tracer picks one in proportion to its weight.
struct SpecularBranch {
    Vec3 wi{0.0f};
    Rgb weight{0.0f};
    Lobe lobe = Lobe::Mirror;
    float albedo = 0.0f;  // the share of energy it carries (weight without radiance compression)
};
using SpecularBranches = std::array<SpecularBranch, 2>;

// A lobe's term as the product of factors named as the lecture names them (`explain`: kd and
// N.L, ks and (H.N)^n).
struct NamedFactor {
    const char* name = "";
    Rgb value{0.0f};
};
using NamedFactors = std::array<NamedFactor, 2>;

}  // namespace lightpath
