#pragma once
// Lambert's diffuse lobe f = kd / pi, sampled in proportion to cos theta (Malley's method): one
// reading for every material with a diffuse part. Directions are on the side of side.normal.
#include <optional>

#include "materials/lobe.h"
#include "sampling/warp.h"

namespace lightpath::lambert {

// f |cos theta_i|; the caller has checked that wo and wi are above the surface.
inline Rgb eval(const Rgb& kd, const SurfaceSide& side, const Vec3& wi) {
    return kd * (glm::dot(wi, side.normal) / kPi);
}

inline float pdf(const SurfaceSide& side, const Vec3& wi) { return cosineHemispherePdf(glm::dot(wi, side.normal)); }

// Nothing when wo is below the shading normal, where eval() is 0 (a smooth mesh seen at a grazing
// angle: the geometric side and the shading normal disagree), so BSDF sampling and light sampling
// add the same light.
inline std::optional<LobeSample> sample(const Rgb& kd, const SurfaceSide& side, const Vec3& wo, Vec2 u) {
    if (!(glm::dot(wo, side.normal) > 0.0f)) return std::nullopt;
    LobeSample s;
    s.wi = Frame(side.normal).toWorld(sampleCosineHemisphere(u));
    const float cosIn = glm::dot(s.wi, side.normal);
    if (cosIn <= 0.0f) return std::nullopt;
    s.pdf = cosineHemispherePdf(cosIn);
    s.weight = kd;  // (kd/pi) cos / (cos/pi)
    return s;
}

// kd and N.L, whose product is pi f |cos theta_i|: the lecture's kd (N.L) under a point light.
inline NamedFactors factors(const Rgb& kd, const SurfaceSide& side, const Vec3& wi) {
    return {{{"kd", kd}, {"N.L", Rgb{glm::dot(side.normal, wi)}}}};
}

}  // namespace lightpath::lambert
