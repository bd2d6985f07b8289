#pragma once
// Ray-primitive intersection tests (Szymczak, "Ray-primitive intersections"; Magnusson,
// "Intersection testing"). Each returns the smallest t in (tMin, tMax), or a negative number for
// no hit. Only intersection: normals and hit points are the caller's job.
#include "geometry/shapes.h"
#include "math/ray.h"

namespace lightpath {

inline constexpr float kNoHit = -1.0f;

// Numerically careful ray/sphere: the discriminant from r^2 - |f - (f.d)d|^2 instead of
// b^2 - 4ac, and the stable pair of roots q = -(b + sign(b) sqrt(disc)), t0 = c/q, t1 = q
// (Haines et al., "Precision Improvements for Ray/Sphere Intersection", Ray Tracing Gems 2019).
float intersectSphere(const Ray& ray, const Sphere& sphere, float tMin);

// The lecture's first derivation: b^2 - 4ac and (-b +- sqrt(disc)) / 2a. Kept to show its failures.
float intersectSphereNaive(const Ray& ray, const Sphere& sphere, float tMin);

float intersectPlane(const Ray& ray, const Plane& plane, float tMin);

// Watertight ray/triangle (Woop, Benthin and Wald, JCGT 2013): no edge is ever missed between two
// triangles that share it, and no scale-dependent determinant threshold.
// With `barycentrics`, also returns the hit's barycentric weights of (a, b, c), from which the
// hit point is formed: more accurate than origin + t * direction.
float intersectTriangle(const Ray& ray, const Triangle& triangle, float tMin, Vec3* barycentrics = nullptr);

// Moller and Trumbore 1997 with the common |det| < 1e-6 parallel test. Kept to show its failures:
// rays through shared edges and vertices slip through, and a small mesh becomes invisible.
float intersectTriangleMollerTrumbore(const Ray& ray, const Triangle& triangle, float tMin);

Vec3 sphereNormal(const Sphere& sphere, const Vec3& point);
Vec3 triangleNormal(const Triangle& triangle);

}  // namespace lightpath
