#include "media/henyey_greenstein.h"

#include <algorithm>
#include <cmath>

#include "sampling/warp.h"

namespace lightpath {
namespace {

// Below this |g| the inversion's 1/g loses precision: sample the sphere uniformly (pbrt-v4).
constexpr float kIsotropicG = 1e-3f;

float henyeyGreenstein(float cosTheta, float g) {
    const float denominator = 1.0f + g * g + 2.0f * g * cosTheta;
    return (1.0f - g * g) / (4.0f * kPi * denominator * std::sqrt(std::max(denominator, 0.0f)));
}

}  // namespace

float HenyeyGreensteinPhase::eval(const Vec3& wo, const Vec3& wi) const {
    return henyeyGreenstein(glm::dot(wo, wi), g_);
}

PhaseSample HenyeyGreensteinPhase::sample(const Vec3& wo, Vec2 u) const {
    float cosTheta;
    if (std::abs(g_) < kIsotropicG) {
        cosTheta = 1.0f - 2.0f * u.x;
    } else {
        const float s = (1.0f - g_ * g_) / (1.0f + g_ - 2.0f * g_ * u.x);
        cosTheta = -(1.0f + g_ * g_ - s * s) / (2.0f * g_);
    }
    cosTheta = std::clamp(cosTheta, -1.0f, 1.0f);
    const float sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
    const float phi = 2.0f * kPi * u.y;
    const Frame frame(wo);
    const Vec3 wi = glm::normalize(frame.toWorld({sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta}));
    return {wi, henyeyGreenstein(cosTheta, g_)};
}

}  // namespace lightpath
