#pragma once
// The sphere kind (shapes/sphere.cpp): its record (geometry/builtin_shapes.h), and the
// cone it subtends, which its area lights sample.
#include <optional>

#include "geometry/builtin_shapes.h"

namespace lightpath {

// The cone of directions a sphere subtends from a receiver outside it, in double: sin^2 of its
// half-angle is r^2/d^2, which underflows float for r/d below 1e-19.
struct SphereCone {
    Vec3 axis{0.0f};             // unit, from the centre towards the receiver
    double sin2ThetaMax = 0.0;
    double oneMinusCosThetaMax = 0.0;  // sin^2/(1 + cos): no cancellation for small cones
    float pdf = 0.0f;            // 1 / (2 pi (1 - cos theta_max)) per steradian; 0 when above float's range
};
// Empty when the receiver is inside the sphere or on it (within 8 float spacings of the centre's
// largest coordinate plus the radius): there light sampling samples by area.
std::optional<SphereCone> sphereCone(const Sphere& sphere, const Vec3& receiver);

}  // namespace lightpath
