#pragma once
#include "math/types.h"

namespace lightpath {

// Moves a computed hit point off its surface along the unit normal n (pointing to the side the
// new ray leaves into), so a secondary ray cannot hit the surface it starts on.
//
// pbrt-v4's method (Pharr, Jakob and Humphreys, "Physically Based Rendering", 4th ed., section
// 6.8.6): the point is moved by d = sum_i |n_i| e_i along n, where e_i bounds the rounding error
// of coordinate i, and each moved coordinate is rounded one more float away from the surface.
// lightpath's hit points are formed from barycentrics or snapped onto the sphere, whose error is
// a few ulps of the point itself, so e_i = kPointErrorScale |p_i| (section 6.8.5's sphere bound
// with a wide margin). The bound scales with the scene: nothing fixed in it makes a small scene
// leak contact shadows, which the absolute near-origin offset of Wachter and Binder (Ray Tracing
// Gems 2019, ch. 6) does below a scene size of about 0.01. Its limit: a point much closer to the
// origin than the vertices it was interpolated from (a huge triangle through the origin) carries
// the vertices' error, not its own.
Vec3 offsetRayOrigin(const Vec3& point, const Vec3& n);

// Wachter and Binder's integer-ulp offset: 256 ulps per unit of normal, and 1/65536 absolute for
// coordinates below 1/32. Kept selectable (RayOffset::WachterBinder) to show that limit.
Vec3 offsetRayOriginWachterBinder(const Vec3& point, const Vec3& n);

// e_i / |p_i| of offsetRayOrigin: 2^-16, about 128 float ulps.
inline constexpr float kPointErrorScale = 0x1p-16f;

}  // namespace lightpath
