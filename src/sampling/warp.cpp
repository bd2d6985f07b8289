#include "sampling/warp.h"

#include <algorithm>

namespace lightpath {

Vec2 sampleConcentricDisk(Vec2 u) {
    const Vec2 offset = 2.0f * u - Vec2{1.0f};
    if (offset.x == 0.0f && offset.y == 0.0f) return Vec2{0.0f};
    float r, theta;
    if (std::fabs(offset.x) > std::fabs(offset.y)) {
        r = offset.x;
        theta = (kPi / 4.0f) * (offset.y / offset.x);
    } else {
        r = offset.y;
        theta = kPi / 2.0f - (kPi / 4.0f) * (offset.x / offset.y);
    }
    return r * Vec2{std::cos(theta), std::sin(theta)};
}

Vec3 sampleCosineHemisphere(Vec2 u) {
    // Malley's method: project a uniform disk sample up onto the hemisphere.
    const Vec2 d = sampleConcentricDisk(u);
    const float z = std::sqrt(std::max(0.0f, 1.0f - d.x * d.x - d.y * d.y));
    return {d.x, d.y, z};
}

Vec3 samplePhongLobe(Vec2 u, float exponent) {
    const float cosAlpha = std::pow(1.0f - u.x, 1.0f / (exponent + 1.0f));
    const float sinAlpha = std::sqrt(std::max(0.0f, 1.0f - cosAlpha * cosAlpha));
    const float phi = 2.0f * kPi * u.y;
    return {sinAlpha * std::cos(phi), sinAlpha * std::sin(phi), cosAlpha};
}

Vec3 sampleUniformSphere(Vec2 u) {
    const float z = 1.0f - 2.0f * u.x;
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    const float phi = 2.0f * kPi * u.y;
    return {r * std::cos(phi), r * std::sin(phi), z};
}

Vec3 sampleUniformTriangle(Vec2 u) {
    float b0, b1;
    if (u.x < u.y) {
        b0 = u.x / 2.0f;
        b1 = u.y - b0;
    } else {
        b1 = u.y / 2.0f;
        b0 = u.x - b1;
    }
    return {b0, b1, 1.0f - b0 - b1};
}

}  // namespace lightpath
