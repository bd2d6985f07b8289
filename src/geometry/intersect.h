#pragma once
// Ray-primitive intersection tests (Szymczak, "Ray-primitive intersections"; Magnusson,
// "Intersection testing"). Each returns the smallest t in (tMin, tMax), or a negative number for
// no hit. Only intersection: normals and hit points are the caller's job.
#include "geometry/shapes.h"
#include "math/ray.h"

namespace lightpath {

inline constexpr float kNoHit = -1.0f;

// Higham's gamma_n = n u / (1 - n u), u = 2^-24: the relative error bound of n float operations.
constexpr float roundingGamma(int n) {
    constexpr float u = 0x1p-24f;
    return static_cast<float>(n) * u / (1.0f - static_cast<float>(n) * u);
}

// Numerically careful ray/sphere: the discriminant from r^2 - |f - (f.d/d.d)d|^2 instead of
// b^2 - 4ac, and the stable pair of roots q = -(b + sign(b) sqrt(disc)), t0 = q/a, t1 = c/q
// (Haines et al., "Precision Improvements for Ray/Sphere Intersection", Ray Tracing Gems 2019).
// Evaluated in double from the float ray and sphere: in float, f - (f.d)d loses as many bits as
// log2(distance/radius), so a sphere 1e5 radii away gets a visibly wrong silhouette.
float intersectSphere(const Ray& ray, const Sphere& sphere, float tMin);

// The lecture's first derivation: b^2 - 4ac and (-b +- sqrt(disc)) / 2a. Kept to show its failures.
float intersectSphereNaive(const Ray& ray, const Sphere& sphere, float tMin);

// Both parameters t0 <= t1 where the ray's line meets the sphere (any sign), by the method of
// intersectSphere / intersectSphereNaive; false when the line misses.
bool sphereRoots(const Ray& ray, const Sphere& sphere, float& t0, float& t1);
bool sphereRootsNaive(const Ray& ray, const Sphere& sphere, float& t0, float& t1);

float intersectPlane(const Ray& ray, const Plane& plane, float tMin);

// Watertight ray/triangle (Woop, Benthin and Wald, JCGT 2013): no edge is ever missed between two
// triangles that share it, and no scale-dependent determinant threshold. A hit closer than the
// bound of t's rounding error is rejected (pbrt-v4, section 6.8.4), so a ray leaving a surface
// cannot find that surface again at a t that is only rounding noise.
// With `barycentrics`, also returns the hit's barycentric weights of (a, b, c), from which the
// hit point is formed: more accurate than origin + t * direction.
float intersectTriangle(const Ray& ray, const Triangle& triangle, float tMin, Vec3* barycentrics = nullptr);

// The per-ray half of the watertight test: the axis permutation that makes the ray's largest
// direction component z, and the shear that maps the ray onto that axis. A traversal computes it
// once per ray instead of once per triangle (it holds the test's three divisions).
struct WatertightRay {
    int kx = 0, ky = 1, kz = 2;
    float sx = 0.0f, sy = 0.0f, sz = 1.0f;

    explicit WatertightRay(const Vec3& direction);
};

float intersectTriangle(const Ray& ray, const WatertightRay& sheared, const Triangle& triangle, float tMin,
                        Vec3* barycentrics = nullptr);

// Moller and Trumbore 1997 with the common |det| < 1e-6 parallel test. Kept to show its failures:
// rays through shared edges and vertices slip through, and a small mesh becomes invisible.
float intersectTriangleMollerTrumbore(const Ray& ray, const Triangle& triangle, float tMin);

Vec3 sphereNormal(const Sphere& sphere, const Vec3& point);
Vec3 triangleNormal(const Triangle& triangle);

}  // namespace lightpath
