#pragma once
// The physically based reading of PhongMaterial used by the path tracer (DESIGN.md):
//   diffuse     Lambert, f = kd / pi                                            event D
//   glossy      normalised Phong lobe around the mirror direction,
//               f = ks (n + 2) / (2 pi) cos^n(alpha) (Lafortune and Willems 1994) event G
//   mirror      perfect mirror weighted by kr                                    event <RS>
//   dielectric  smooth interface weighted by kt, reflecting with the Fresnel
//               probability F and refracting otherwise                           events <RS>, <TS>
// No ambient term: the path tracer computes the light that ambient fakes.
#include <cstdint>
#include <optional>

#include "math/types.h"
#include "scene/material.h"

namespace lightpath {

enum class Lobe : std::uint8_t { Diffuse, Glossy, Mirror, Dielectric };
inline constexpr int kLobeCount = 4;

struct BsdfSample {
    Vec3 direction{0.0f};   // wi, unit, world space
    Rgb weight{0.0f};       // f cos(theta_i) / pdf: what the path throughput is multiplied by
    float pdf = 0.0f;       // solid-angle density including the lobe choice; 0 for delta lobes
    Lobe lobe = Lobe::Diffuse;
    bool transmitted = false;  // crossed the surface (a T event)
};

class PhongBsdf {
public:
    // `normal`: unit shading normal on the side of wo. `entering`: wo is outside the material.
    PhongBsdf(const PhongMaterial& material, const Vec3& normal, bool entering);

    // Probability that sample() picks `lobe`: proportional to the lobe's largest RGB weight.
    float lobeProbability(Lobe lobe) const { return lobeProbability_[static_cast<int>(lobe)]; }
    bool hasSmoothLobe() const { return lobeProbability_[0] > 0.0f || lobeProbability_[1] > 0.0f; }

    // f(wo, wi) of one non-delta lobe (Diffuse or Glossy); zero below the surface.
    Rgb evaluate(Lobe lobe, const Vec3& wo, const Vec3& wi) const;
    // Density of sample() returning wi through `lobe` (Diffuse or Glossy), lobe choice included.
    float pdf(Lobe lobe, const Vec3& wo, const Vec3& wi) const;

    // One direction by importance: a lobe by lobeProbability, then a direction within it.
    // nullopt when the material reflects nothing or the sampled direction is below the surface.
    std::optional<BsdfSample> sample(const Vec3& wo, float uLobe, Vec2 u) const;

private:
    const PhongMaterial& material_;
    Vec3 normal_;
    float eta_;  // n_incident / n_transmitted for a ray arriving from the side of wo
    float lobeProbability_[kLobeCount] = {};
};

// Fresnel reflectance of a smooth dielectric for unpolarised light; cosIncident >= 0 and
// eta = n_incident / n_transmitted. 1 on total internal reflection.
float fresnelDielectric(float cosIncident, float eta);

}  // namespace lightpath
