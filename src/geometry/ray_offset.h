#pragma once
#include "math/types.h"

namespace lightpath {

// Moves a computed hit point off its surface along the normal n (pointing to the side the new
// ray leaves into), so a secondary ray cannot hit the surface it starts on. The offset grows with
// the magnitude of the coordinates, as their rounding error does: a fixed number of float ulps,
// plus a small absolute offset near the origin where ulps vanish (Wächter and Binder, "A Fast and
// Robust Method for Avoiding Self-Intersection", Ray Tracing Gems 2019, ch. 6). Its known limit:
// it assumes the point's error is a few ulps of its coordinates, true for points computed from
// barycentrics or snapped onto a sphere, not for points far along a long ray.
Vec3 offsetRayOrigin(const Vec3& point, const Vec3& n);

}  // namespace lightpath
