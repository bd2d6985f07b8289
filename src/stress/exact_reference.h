#pragma once
// Long-double references for float rays and spheres, shared by the stress suite and its unit
// tests: products of floats are exact in long double's 64-bit significand, and |f x d|^2 measures
// the line's distance from the centre without cancelling squares, so these decide hit or miss and
// t far beyond float's rounding. They never call the intersection code under test.
#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/shapes.h"
#include "math/ray.h"

namespace lightpath::stress {

struct ExactRoots {
    bool hit = false;
    long double t0 = 0, t1 = 0;
};

inline ExactRoots exactSphereRoots(const Ray& ray, const Sphere& s) {
    using L = long double;
    const L f[3] = {L(ray.origin.x) - s.center.x, L(ray.origin.y) - s.center.y, L(ray.origin.z) - s.center.z};
    const L d[3] = {ray.direction.x, ray.direction.y, ray.direction.z};
    const L a = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    const L b = f[0] * d[0] + f[1] * d[1] + f[2] * d[2];
    const L cx = f[1] * d[2] - f[2] * d[1], cy = f[2] * d[0] - f[0] * d[2], cz = f[0] * d[1] - f[1] * d[0];
    const L r = s.radius;
    const L discriminant = a * r * r - (cx * cx + cy * cy + cz * cz);
    ExactRoots roots;
    if (discriminant < 0) return roots;
    const L c = f[0] * f[0] + f[1] * f[1] + f[2] * f[2] - r * r;
    const L q = -(b + std::copysign(std::sqrt(discriminant), b));
    roots.hit = true;
    roots.t0 = q / a;
    roots.t1 = q != 0 ? c / q : roots.t0;
    if (roots.t0 > roots.t1) std::swap(roots.t0, roots.t1);
    return roots;
}

// |t - reference| in units of the float spacing at the reference.
inline double ulpsBetween(float t, long double reference) {
    const float r = static_cast<float>(reference);
    const float ulp = std::nextafter(std::fabs(r), std::numeric_limits<float>::infinity()) - std::fabs(r);
    return static_cast<double>(std::fabs(static_cast<long double>(t) - reference) / ulp);
}

}  // namespace lightpath::stress
