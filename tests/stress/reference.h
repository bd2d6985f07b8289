#pragma once
// Long-double references for the float ray and primitives, independent of the code under test.
#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/shapes.h"
#include "stress/exact_reference.h"
#include "math/ray.h"

namespace lightpath::test {

// The sphere references are the stress suite's own (src/stress/exact_reference.h).
using stress::ExactRoots;
using stress::exactSphereRoots;
using stress::ulpsBetween;

// Signed distance of p from the plane of a triangle, in long double.
inline long double planeDistance(const Triangle& tri, const Vec3& p) {
    using L = long double;
    const L e1[3] = {L(tri.b.x) - tri.a.x, L(tri.b.y) - tri.a.y, L(tri.b.z) - tri.a.z};
    const L e2[3] = {L(tri.c.x) - tri.a.x, L(tri.c.y) - tri.a.y, L(tri.c.z) - tri.a.z};
    const L n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
    const L length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    return ((L(p.x) - tri.a.x) * n[0] + (L(p.y) - tri.a.y) * n[1] + (L(p.z) - tri.a.z) * n[2]) / length;
}

}  // namespace lightpath::test
