#pragma once
// The laws of a smooth interface, written once for every integrator: the mirror direction, Snell's
// law and Fresnel's equations (Hecht, Optics, ch. 4; pbrt-v4 9.3 and 9.5). Vectors point away from
// the surface; `n` is the unit normal on the side of wo.
#include <algorithm>
#include <cmath>
#include <complex>
#include <optional>

#include "math/types.h"

namespace lightpath {

inline Vec3 reflectAbout(const Vec3& wo, const Vec3& n) { return 2.0f * glm::dot(wo, n) * n - wo; }

// Snell's law, n_i sin(theta_i) = n_t sin(theta_t), with eta = n_i / n_t: the transmitted
// direction, or nullopt on total internal reflection.
inline std::optional<Vec3> refractThrough(const Vec3& wo, const Vec3& n, float eta) {
    const float cosIncident = glm::dot(wo, n);
    const float sin2Transmitted = eta * eta * std::max(0.0f, 1.0f - cosIncident * cosIncident);
    if (sin2Transmitted >= 1.0f) return std::nullopt;
    const float cosTransmitted = std::sqrt(1.0f - sin2Transmitted);
    return glm::normalize(-eta * wo + (eta * cosIncident - cosTransmitted) * n);
}

// Fresnel reflectance of a smooth dielectric for unpolarised light, cosIncident >= 0 and
// eta = n_i / n_t; 1 on total internal reflection.
inline float fresnelDielectric(float cosIncident, float eta) {
    const float sin2Transmitted = eta * eta * (1.0f - cosIncident * cosIncident);
    if (sin2Transmitted >= 1.0f) return 1.0f;
    const float cosTransmitted = std::sqrt(1.0f - sin2Transmitted);
    const float parallel = (cosIncident - eta * cosTransmitted) / (cosIncident + eta * cosTransmitted);
    const float perpendicular = (eta * cosIncident - cosTransmitted) / (eta * cosIncident + cosTransmitted);
    return 0.5f * (parallel * parallel + perpendicular * perpendicular);
}

// Fresnel reflectance of a conductor (a complex index of refraction eta + i k relative to the
// outside) for unpolarised light, cosIncident in [0, 1]: Fresnel's equations with Snell's law in
// complex numbers, sin^2 theta_t = sin^2 theta_i / (eta + i k)^2 (Born and Wolf, Principles of
// Optics, 14.2; pbrt-v4 9.3.6). k = 0 is fresnelDielectric(cosIncident, 1 / eta).
inline float fresnelConductor(float cosIncident, float eta, float k) {
    using Complex = std::complex<float>;
    const float cosI = std::clamp(cosIncident, 0.0f, 1.0f);
    const Complex index{eta, k};
    const Complex sin2Transmitted = (1.0f - cosI * cosI) / (index * index);
    const Complex cosTransmitted = std::sqrt(1.0f - sin2Transmitted);
    const Complex parallel = (index * cosI - cosTransmitted) / (index * cosI + cosTransmitted);
    const Complex perpendicular = (cosI - index * cosTransmitted) / (cosI + index * cosTransmitted);
    return 0.5f * (std::norm(parallel) + std::norm(perpendicular));
}

// Schlick's approximation F = F0 + (1 - F0) w with the weight w = (1 - cos)^5 (Schlick 1994);
// cos is clamped to [0, 1].
inline float schlickWeight(float cosine) {
    const float x = std::clamp(1.0f - cosine, 0.0f, 1.0f);
    const float x2 = x * x;
    return x2 * x2 * x;
}

}  // namespace lightpath
