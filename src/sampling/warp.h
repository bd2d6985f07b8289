#pragma once
// Maps from uniform samples in [0,1)^2 to directions and points with known densities (pbrt-v4
// ch. A.5; Shirley and Chiu 1997 for the concentric disk). Densities are per steradian or per
// unit area, as named.
#include <cmath>

#include "math/types.h"

namespace lightpath {

// An orthonormal basis around unit n (Duff et al., "Building an Orthonormal Basis, Revisited", 2017).
struct Frame {
    Vec3 s, t, n;

    explicit Frame(const Vec3& normal) : n(normal) {
        const float sign = std::copysign(1.0f, n.z);
        const float a = -1.0f / (sign + n.z);
        const float b = n.x * n.y * a;
        s = {1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x};
        t = {b, sign + n.y * n.y * a, -n.y};
    }
    Vec3 toWorld(const Vec3& v) const { return v.x * s + v.y * t + v.z * n; }
    Vec3 toLocal(const Vec3& v) const { return {glm::dot(v, s), glm::dot(v, t), glm::dot(v, n)}; }
};

Vec2 sampleConcentricDisk(Vec2 u);

// Cosine-weighted hemisphere around +z: pdf = cos(theta) / pi.
Vec3 sampleCosineHemisphere(Vec2 u);
inline float cosineHemispherePdf(float cosTheta) { return cosTheta > 0.0f ? cosTheta / kPi : 0.0f; }

// Around +z with pdf = (n + 1) / (2 pi) cos^n(alpha), alpha the angle to +z: the normalised
// Phong lobe's exact importance sampling (Lafortune and Willems 1994).
Vec3 samplePhongLobe(Vec2 u, float exponent);
inline float phongLobePdf(float cosAlpha, float exponent) {
    return cosAlpha > 0.0f ? (exponent + 1.0f) / (2.0f * kPi) * std::pow(cosAlpha, exponent) : 0.0f;
}

// Uniform on the unit sphere: pdf = 1 / (4 pi).
Vec3 sampleUniformSphere(Vec2 u);

// Uniform barycentrics on a triangle (Heitz 2019, "A Low-Distortion Map Between Triangle and Square").
Vec3 sampleUniformTriangle(Vec2 u);

}  // namespace lightpath
