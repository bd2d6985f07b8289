#pragma once
// The Trowbridge-Reitz (GGX) microfacet distribution with Smith's height-correlated masking-
// shadowing and the sampling of its visible normals (Walter et al. 2007; Heitz 2014,
// "Understanding the masking-shadowing function"; Heitz 2018, "Sampling the GGX distribution of
// visible normals"; pbrt-v4 9.6). Directions are local: the macro normal is +z, all unit vectors.
#include <cmath>

#include "math/types.h"

namespace lightpath::ggx {

// The smallest alpha treated as rough: below it D overflows a float (pbrt-v4's EffectivelySmooth).
inline constexpr float kMinAlpha = 1e-3f;

// D(m) = alpha^2 / (pi ((alpha^2 - 1) cos^2 theta_m + 1)^2), m above the surface. The bracket is
// sin^2 + alpha^2 cos^2, with sin^2 from m's x and y: 1 - cos^2 would cancel near the pole, where a
// sharp lobe (alpha 0.02) is all of its mass and a rounding of cos moves D by 1e-3.
inline float distribution(const Vec3& m, float alpha) {
    if (m.z <= 0.0f) return 0.0f;
    const float a2 = alpha * alpha;
    const float t = (m.x * m.x + m.y * m.y) + a2 * m.z * m.z;
    return a2 / (kPi * t * t);
}

// Smith's Lambda(w) = (sqrt(1 + alpha^2 tan^2 theta) - 1) / 2.
inline float lambda(const Vec3& w, float alpha) {
    const float cos2 = w.z * w.z;
    if (cos2 <= 0.0f) return INFINITY;
    const float tan2 = std::max(0.0f, 1.0f - cos2) / cos2;
    return 0.5f * (std::sqrt(1.0f + alpha * alpha * tan2) - 1.0f);
}

// G1(w) = 1 / (1 + Lambda(w)): the fraction of microfacets visible from w.
inline float masking(const Vec3& w, float alpha) { return 1.0f / (1.0f + lambda(w, alpha)); }

// Height-correlated G2(wo, wi) = 1 / (1 + Lambda(wo) + Lambda(wi)) (Heitz 2014, eq. 99): symmetric.
inline float maskingShadowing(const Vec3& wo, const Vec3& wi, float alpha) {
    return 1.0f / (1.0f + lambda(wo, alpha) + lambda(wi, alpha));
}

// A visible normal from wo (wo.z > 0), distributed as D_wo(m) = G1(wo) max(0, wo.m) D(m) / wo.z
// (Heitz 2018, listing 1).
inline Vec3 sampleVisibleNormal(const Vec3& wo, float alpha, Vec2 u) {
    const Vec3 vh = glm::normalize(Vec3{alpha * wo.x, alpha * wo.y, wo.z});
    const float lensq = vh.x * vh.x + vh.y * vh.y;
    const Vec3 t1 = lensq > 0.0f ? Vec3{-vh.y, vh.x, 0.0f} / std::sqrt(lensq) : Vec3{1.0f, 0.0f, 0.0f};
    const Vec3 t2 = glm::cross(vh, t1);
    const float r = std::sqrt(u.x), phi = 2.0f * kPi * u.y;
    const float p1 = r * std::cos(phi);
    const float s = 0.5f * (1.0f + vh.z);
    const float p2 = (1.0f - s) * std::sqrt(std::max(0.0f, 1.0f - p1 * p1)) + s * r * std::sin(phi);
    const Vec3 nh = p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0f, 1.0f - p1 * p1 - p2 * p2)) * vh;
    return glm::normalize(Vec3{alpha * nh.x, alpha * nh.y, std::max(1e-6f, nh.z)});
}

// The density of reflecting wo into wi by a sampled visible normal, per solid angle of wi:
// D_wo(m) / (4 wo.m) = G1(wo) D(m) / (4 wo.z), m the half vector (pbrt-v4 9.6.4, eq. 9.29).
inline float reflectionPdf(const Vec3& wo, const Vec3& wi, float alpha) {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
    const Vec3 m = glm::normalize(wo + wi);
    return masking(wo, alpha) * distribution(m, alpha) / (4.0f * wo.z);
}

}  // namespace lightpath::ggx
