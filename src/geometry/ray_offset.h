#pragma once
#include <algorithm>
#include <cmath>

#include "math/float_bits.h"
#include "math/types.h"

namespace lightpath {

// e / (max_i |p_i| + 2 t) of offsetRayOrigin: 2^-18, 64 units of float roundoff, about ten times
// the gamma_5 of pbrt-v4's bounds for these points.
inline constexpr float kPointErrorScale = 0x1p-18f;

namespace detail {
// One float further along the normal's sign, so rounding of p + offset cannot undo the move.
inline float roundAway(float moved, float normal) {
    if (normal > 0.0f) return nextFloatUp(moved);
    if (normal < 0.0f) return nextFloatDown(moved);
    return moved;
}
}  // namespace detail

// Moves a computed hit point off its surface along the unit normal n (pointing to the side the
// new ray leaves into), so a secondary ray cannot hit the surface it starts on.
//
// pbrt-v4's method (Pharr, Jakob and Humphreys, "Physically Based Rendering", 4th ed., section
// 6.8.6): the point is moved by d = sum_i |n_i| e_i along n, where e_i bounds the rounding error
// of coordinate i, and each moved coordinate is rounded one more float away from the surface.
// lightpath's hit points come from o + t d (planes, spheres) or from barycentrics (triangles);
// both err by a few ulps of max(|o|, |p|) + t, and |o| <= |p| + t, so every coordinate gets
// e = kPointErrorScale (max_i |p_i| + 2 t), with `travelled` the t of the ray that found the
// point. The bound scales with the scene: nothing fixed in it makes a small scene leak contact
// shadows, which the absolute near-origin offset of Wachter and Binder (Ray Tracing Gems 2019,
// ch. 6) does in scenes of size 0.01 and below. Its limit: a point of a triangle far larger than
// both the point's distance from the origin and the ray's length (a huge floor through the origin
// seen from close by) carries its vertices' error, which this bound does not see.
// Inline: it runs for the first shadow ray on each side of every shading point.
inline Vec3 offsetRayOrigin(const Vec3& p, const Vec3& n, float travelled) {
    const Vec3 magnitude = glm::abs(p);
    const float t = std::isfinite(travelled) ? std::fabs(travelled) : 0.0f;
    const float error = kPointErrorScale * (std::max({magnitude.x, magnitude.y, magnitude.z}) + 2.0f * t);
    const float distance = error * (std::fabs(n.x) + std::fabs(n.y) + std::fabs(n.z));
    const Vec3 offset = distance * n;
    const Vec3 moved = p + offset;
    return {detail::roundAway(moved.x, n.x), detail::roundAway(moved.y, n.y), detail::roundAway(moved.z, n.z)};
}

// Wachter and Binder's integer-ulp offset: 256 ulps per unit of normal, and 1/65536 absolute for
// coordinates below 1/32. Kept selectable (RayOffset::WachterBinder) to show that limit.
Vec3 offsetRayOriginWachterBinder(const Vec3& point, const Vec3& n);

}  // namespace lightpath
