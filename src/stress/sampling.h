#pragma once
// Fixed-seed sampling shared by the stress rows: every run draws the same rays.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <random>
#include <string>
#include <numbers>

#include "math/types.h"

namespace lightpath::stress {

using Rng = std::mt19937_64;

inline double uniform(Rng& rng) { return std::uniform_real_distribution<double>(0.0, 1.0)(rng); }

inline Vec3 randomUnitVector(Rng& rng) {
    const double z = 2.0 * uniform(rng) - 1.0;
    const double phi = 2.0 * std::numbers::pi * uniform(rng);
    const double s = std::sqrt(std::max(0.0, 1.0 - z * z));
    return {static_cast<float>(s * std::cos(phi)), static_cast<float>(s * std::sin(phi)), static_cast<float>(z)};
}

// Two unit vectors completing unit `n` to an orthonormal basis (Duff et al. 2017).
inline void orthonormalBasis(const Vec3& n, Vec3& b1, Vec3& b2) {
    const float sign = std::copysign(1.0f, n.z);
    const float a = -1.0f / (sign + n.z);
    const float b = n.x * n.y * a;
    b1 = {1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x};
    b2 = {b, sign + n.y * n.y * a, -n.y};
}

// A unit vector making an angle with unit `axis` whose cosine is uniform in [cosMin, cosMax].
inline Vec3 randomInCone(Rng& rng, const Vec3& axis, double cosMin, double cosMax) {
    const double c = cosMin + (cosMax - cosMin) * uniform(rng);
    const double s = std::sqrt(std::max(0.0, 1.0 - c * c));
    const double phi = 2.0 * std::numbers::pi * uniform(rng);
    Vec3 b1, b2;
    orthonormalBasis(axis, b1, b2);
    const Vec3 v = static_cast<float>(c) * axis + static_cast<float>(s * std::cos(phi)) * b1 +
                   static_cast<float>(s * std::sin(phi)) * b2;
    return glm::normalize(v);
}

// "1e3" for the powers of ten the rows sweep.
inline std::string powerLabel(double v) {
    char buffer[16];
    std::snprintf(buffer, sizeof buffer, "%.0e", v);
    std::string s = buffer;
    const auto e = s.find("e+0");
    if (e != std::string::npos) s.erase(e + 1, 2);
    const auto m = s.find("e-0");
    if (m != std::string::npos) s.erase(m + 2, 1);
    const auto p = s.find("e+");
    if (p != std::string::npos) s.erase(p + 1, 1);
    return s;
}

// "3 (0.012%)" style detail entries.
inline std::string percent(double part, double whole) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.3g%%", whole > 0 ? 100.0 * part / whole : 0.0);
    return buffer;
}

}  // namespace lightpath::stress
