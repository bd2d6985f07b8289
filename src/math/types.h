#pragma once
// Value types for the renderer's math: GLM vectors in single precision.
#include <glm/glm.hpp>

namespace lightpath {

using Vec3 = glm::vec3;
using Vec2 = glm::vec2;
// Linear RGB radiance or reflectance, one float per channel.
using Rgb = glm::vec3;

inline constexpr float kPi = 3.14159265358979323846f;

inline float maxComponent(const Vec3& v) { return glm::max(v.x, glm::max(v.y, v.z)); }
inline bool isBlack(const Rgb& c) { return c.r == 0.0f && c.g == 0.0f && c.b == 0.0f; }

}  // namespace lightpath
