#pragma once
// The vocabulary every material speaks: its lobes, and the event of Heckbert's alphabet each lobe
// scatters by (pbrt-v4's BxDFFlags play this role). An integrator never maps lobes to events by hand.
#include <array>
#include <cstdint>
#include <span>

#include "lpe/event.h"
#include "math/types.h"

namespace lightpath {

// The event a lobe scatters by: its type (reflection or transmission) and scattering letter.
struct ScatterEvent {
    lpe::EventType type;
    lpe::Scatter scatter;

    friend constexpr bool operator==(const ScatterEvent&, const ScatterEvent&) = default;
};

// A lobe is data its material declares (pbrt-v4's BxDFFlags play this role): the event it scatters
// by, from which an integrator reads all it needs (a delta lobe is S, a transmission lobe passes to
// the other side), and the names `explain` and the stats print. A material lists its lobes once
// (Material::lobes()); everything else names a lobe by its index in that list.
struct LobeInfo {
    ScatterEvent event;
    const char* name = "";         // "diffuse", "highlight": for messages
    const char* coefficient = "";  // the parameter whose zero removes it ("kd", "ks"): `explain`'s reasons

    // A Dirac: Heckbert's S is the specular (delta) scattering that light sampling cannot reach.
    constexpr bool delta() const { return event.scatter == lpe::Scatter::Specular; }
    constexpr bool transmits() const { return event.type == lpe::EventType::Transmission; }
};

// The most lobes a material may declare: per-hit arrays (lobe probabilities, direct lighting's
// events) are this size, so the hot loop never allocates.
inline constexpr int kMaxLobes = 6;
using Lobes = std::span<const LobeInfo>;

// The lobes of the lecture's materials, for materials to list (each material picks its own order).
namespace lobes {
//   diffuse     <RD>   e.g. Lambert's kd / pi
inline constexpr LobeInfo kDiffuse{{lpe::EventType::Reflection, lpe::Scatter::Diffuse}, "diffuse", "kd"};
//   highlight   <RG>   a glossy reflection, e.g. Phong's highlight ks (H.N)^n / pi
inline constexpr LobeInfo kHighlight{{lpe::EventType::Reflection, lpe::Scatter::Glossy}, "highlight", "ks"};
//   mirror      <RS>   a perfect reflection, a delta
inline constexpr LobeInfo kMirror{{lpe::EventType::Reflection, lpe::Scatter::Specular}, "mirror", "kr"};
//   refraction  <TS>   a perfect refraction, a delta
inline constexpr LobeInfo kRefraction{{lpe::EventType::Transmission, lpe::Scatter::Specular}, "refraction", "kt"};
}  // namespace lobes

// Light arriving at the camera (radiance) or importance arriving at a light (light tracing): only
// refraction's 1/eta^2 radiance compression tells them apart (Veach 1997, 5.2; pbrt-v4 9.5.2).
enum class TransportMode : std::uint8_t { Radiance, Importance };

// Where on a texture a surface point is and the area about it one pixel covers: its texture
// coordinates and their change from one pixel to the next in x and in y (the filter's footprint,
// pbrt-v4 10.1). All zero where the material has no texture (nothing reads it there).
struct TextureFootprint {
    Vec2 uv{0.0f};
    Vec2 dUVdx{0.0f};
    Vec2 dUVdy{0.0f};
};

// Which side of a surface a path is on, as a material needs it to scatter.
struct SurfaceSide {
    Vec3 normal{0.0f, 0.0f, 1.0f};  // unit shading normal on the side of the outgoing direction wo
    bool entering = true;           // that side is the material's outside
    TransportMode mode = TransportMode::Radiance;
    TextureFootprint texture;       // what its textured parameters are looked up at (texture.h)
    Rgb vertexColor{1.0f};          // the mesh's colour there (glTF's COLOR_0), for parameters it multiplies

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

// A sample of a material that chooses its own lobe (Material::choosesLobe): the lobe, and the
// direction with the choice folded into its weight and density.
struct ChosenLobeSample {
    int lobe = 0;
    LobeSample sample;
};

// One deterministic branch of a delta lobe, with its exact weight: Whitted traces every branch,
// the path tracer picks one in proportion to its weight.
struct SpecularBranch {
    Vec3 wi{0.0f};
    Rgb weight{0.0f};
    int lobe = 0;         // the delta lobe's index in the material's lobes()
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
