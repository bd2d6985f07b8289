#pragma once
// Value types for the renderer's math: GLM vectors in single precision.
#include <glm/glm.hpp>
#include <numbers>

namespace lightpath {

using Vec3 = glm::vec3;
using Vec2 = glm::vec2;
using Vec4 = glm::vec4;
// Linear RGB radiance or reflectance, one float per channel.
using Rgb = glm::vec3;

inline constexpr float kPi = std::numbers::pi_v<float>;

inline float maxComponent(const Vec3& v) { return glm::max(v.x, glm::max(v.y, v.z)); }
inline bool isBlack(const Rgb& c) { return c.r == 0.0f && c.g == 0.0f && c.b == 0.0f; }
// Relative luminance of linear RGB with Rec. 709 primaries (ITU-R BT.709 weights).
inline float luminance(const Rgb& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

// The cross product of two parallel vectors vanishes; compare against their lengths so the test
// does not depend on how long the student wrote them (a camera's up, a triangle's edges).
inline bool areParallel(const Vec3& a, const Vec3& b) {
    const glm::dvec3 da(a), db(b);
    return glm::length(glm::cross(da, db)) <= 1e-6 * glm::length(da) * glm::length(db);
}

}  // namespace lightpath
