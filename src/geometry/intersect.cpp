#include "geometry/intersect.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include <glm/gtc/type_ptr.hpp>

#include "util/hot_path.h"

namespace lightpath {
namespace {

// Indexed loads, not glm's operator[] (a switch): the axes vary from ray to ray.
Vec3 permute(const Vec3& v, int x, int y, int z) {
    const float* p = glm::value_ptr(v);
    return {p[x], p[y], p[z]};
}

}  // namespace

bool sphereRoots(const Ray& ray, const Sphere& sphere, float& t0, float& t1) {
    // a t^2 + 2 b t + c = 0 with f = origin - centre, a = d.d, b = f.d, c = f.f - r^2.
    const glm::dvec3 f = glm::dvec3(ray.origin) - glm::dvec3(sphere.center);  // exact: float inputs
    const glm::dvec3 d(ray.direction);
    const double a = glm::dot(d, d);
    if (!(a > 0.0)) return false;  // zero or NaN direction
    const double b = glm::dot(f, d);
    const double r = sphere.radius;
    // b^2 - a c = a (r^2 - |f - (b/a) d|^2): the distance of the centre from the line, without the
    // cancellation of two large squares (Haines et al. 2019, eq. 7.5).
    const glm::dvec3 perpendicular = f - (b / a) * d;
    const double discriminant = a * (r * r - glm::dot(perpendicular, perpendicular));
    if (!(discriminant >= 0.0)) return false;
    const double c = glm::dot(f, f) - r * r;
    // The root that adds magnitudes first, the other from Vieta's t0 t1 = c / a (Haines eq. 7.6).
    const double q = -(b + std::copysign(std::sqrt(discriminant), b));
    double r0 = q / a;
    double r1 = q != 0.0 ? c / q : r0;
    if (r0 > r1) std::swap(r0, r1);
    t0 = static_cast<float>(r0);
    t1 = static_cast<float>(r1);
    return true;
}

bool sphereRootsNaive(const Ray& ray, const Sphere& sphere, float& t0, float& t1) {
    const Vec3 co = ray.origin - sphere.center;
    const float a = glm::dot(ray.direction, ray.direction);
    const float b = 2.0f * glm::dot(co, ray.direction);
    const float c = glm::dot(co, co) - sphere.radius * sphere.radius;
    const float discriminant = b * b - 4.0f * a * c;
    if (!(discriminant >= 0.0f)) return false;
    const float root = std::sqrt(discriminant);
    t0 = (-b - root) / (2.0f * a);
    t1 = (-b + root) / (2.0f * a);
    return true;
}

namespace {

// The nearer of the roots t0 <= t1 inside (tMin, ray.tMax): the first hit along the ray.
float nearestRootInRange(float t0, float t1, const Ray& ray, float tMin) {
    if (t0 > tMin && t0 < ray.tMax) return t0;
    if (t1 > tMin && t1 < ray.tMax) return t1;
    return kNoHit;
}

}  // namespace

float intersectSphere(const Ray& ray, const Sphere& sphere, float tMin) {
    float t0 = 0.0f, t1 = 0.0f;
    return sphereRoots(ray, sphere, t0, t1) ? nearestRootInRange(t0, t1, ray, tMin) : kNoHit;
}

float intersectSphereNaive(const Ray& ray, const Sphere& sphere, float tMin) {
    float t0 = 0.0f, t1 = 0.0f;
    return sphereRootsNaive(ray, sphere, t0, t1) ? nearestRootInRange(t0, t1, ray, tMin) : kNoHit;
}

float intersectPlane(const Ray& ray, const Plane& plane, float tMin) {
    // In double, so the sign of the origin's distance from the plane is right even for an origin
    // a few ulps off it (a spawned ray), however far the plane's anchor point is.
    const glm::dvec3 normal(plane.normal);
    const double denominator = glm::dot(normal, glm::dvec3(ray.direction));
    if (!(denominator != 0.0)) return kNoHit;  // parallel: no single point in common (or NaN)
    const double t = glm::dot(glm::dvec3(plane.point) - glm::dvec3(ray.origin), normal) / denominator;
    if (!(t > 0.0)) return kNoHit;  // behind, even if it rounds to a float t of 0
    const auto tf = static_cast<float>(t);
    return (tf > tMin && tf < ray.tMax) ? tf : kNoHit;
}

LIGHTPATH_HOT_PATH
WatertightRay::WatertightRay(const Vec3& direction) {
    // Shear and scale so the ray becomes the +z axis through the origin; then the three edge
    // functions are 2D cross products evaluated identically for a shared edge.
    // No branch on the direction: an incoherent ray's signs and largest axis are coin flips, and
    // as branches they cost 2.4 mispredictions per ray (callgrind --branch-sim, dragon, random).
    const float* axis = glm::value_ptr(direction);
    const float ax = std::fabs(axis[0]), ay = std::fabs(axis[1]), az = std::fabs(axis[2]);
    const int xy = ax > ay, xz = ax > az, yz = ay > az;
    kz = 2 - 2 * (xy & xz) - ((1 - xy) & yz);  // the largest |component|: x if above both, else y if above z
    // kx, ky follow kz cyclically, swapped when the ray runs down the kz axis (to keep the winding)
    static constexpr int kFollowing[2][3][2] = {{{1, 2}, {2, 0}, {0, 1}}, {{2, 1}, {0, 2}, {1, 0}}};
    const int down = axis[kz] < 0.0f;
    kx = kFollowing[down][kz][0];
    ky = kFollowing[down][kz][1];
    const Vec3 d(axis[kx], axis[ky], axis[kz]);
    sx = -d.x / d.z;
    sy = -d.y / d.z;
    sz = 1.0f / d.z;
}

float intersectTriangle(const Ray& ray, const Triangle& tri, float tMin, Vec3* barycentrics) {
    return intersectTriangle(ray, WatertightRay(ray.direction), tri, tMin, barycentrics);
}

float intersectTriangle(const Ray& ray, const WatertightRay& sheared, const Triangle& tri, float tMin,
                        Vec3* barycentrics) {
    const int kx = sheared.kx, ky = sheared.ky, kz = sheared.kz;
    const float sx = sheared.sx, sy = sheared.sy, sz = sheared.sz;
    const Vec3 a = permute(tri.a - ray.origin, kx, ky, kz);
    const Vec3 b = permute(tri.b - ray.origin, kx, ky, kz);
    const Vec3 c = permute(tri.c - ray.origin, kx, ky, kz);
    const float ax = a.x + sx * a.z, ay = a.y + sy * a.z;
    const float bx = b.x + sx * b.z, by = b.y + sy * b.z;
    const float cx = c.x + sx * c.z, cy = c.y + sy * c.z;

    float u = cx * by - cy * bx;
    float v = ax * cy - ay * cx;
    float w = bx * ay - by * ax;
    // An edge function that rounds to exactly zero is recomputed in double: that is the case
    // where float cannot tell on which side of the edge the ray passes.
    if (u == 0.0f || v == 0.0f || w == 0.0f) {
        u = static_cast<float>(double(cx) * double(by) - double(cy) * double(bx));
        v = static_cast<float>(double(ax) * double(cy) - double(ay) * double(cx));
        w = static_cast<float>(double(bx) * double(ay) - double(by) * double(ax));
    }
    if ((u < 0.0f || v < 0.0f || w < 0.0f) && (u > 0.0f || v > 0.0f || w > 0.0f)) return kNoHit;
    const float det = u + v + w;
    if (det == 0.0f) return kNoHit;  // the ray lies in the triangle's plane

    const float az = sz * a.z, bz = sz * b.z, cz = sz * c.z;
    const float t = (u * az + v * bz + w * cz) / det;
    if (!(t > tMin && t < ray.tMax)) return kNoHit;
    // Conservative bound of t's rounding error (pbrt-v4, section 6.8.4): a t this small may be
    // the surface the ray starts on, seen through rounding, so it is no hit.
    const float maxZ = std::max({std::fabs(az), std::fabs(bz), std::fabs(cz)});
    const float maxX = std::max({std::fabs(ax), std::fabs(bx), std::fabs(cx)});
    const float maxY = std::max({std::fabs(ay), std::fabs(by), std::fabs(cy)});
    const float deltaZ = roundingGamma(3) * maxZ;
    const float deltaX = roundingGamma(5) * (maxX + maxZ);
    const float deltaY = roundingGamma(5) * (maxY + maxZ);
    const float deltaE = 2.0f * (roundingGamma(2) * maxX * maxY + deltaY * maxX + deltaX * maxY);
    const float maxE = std::max({std::fabs(u), std::fabs(v), std::fabs(w)});
    const float deltaT = 3.0f * (roundingGamma(3) * maxE * maxZ + deltaE * maxZ + deltaZ * maxE) / std::fabs(det);
    if (t <= deltaT) return kNoHit;
    if (barycentrics != nullptr) *barycentrics = Vec3{u, v, w} / det;
    return t;
}

float intersectTriangleMollerTrumbore(const Ray& ray, const Triangle& tri, float tMin) {
    constexpr float kDeterminantEpsilon = 1e-6f;
    const Vec3 edge1 = tri.b - tri.a, edge2 = tri.c - tri.a;
    const Vec3 p = glm::cross(ray.direction, edge2);
    const float det = glm::dot(edge1, p);
    if (std::fabs(det) < kDeterminantEpsilon) return kNoHit;
    const float inverse = 1.0f / det;
    const Vec3 s = ray.origin - tri.a;
    const float u = glm::dot(s, p) * inverse;
    if (u < 0.0f || u > 1.0f) return kNoHit;
    const Vec3 q = glm::cross(s, edge1);
    const float v = glm::dot(ray.direction, q) * inverse;
    if (v < 0.0f || u + v > 1.0f) return kNoHit;
    const float t = glm::dot(edge2, q) * inverse;
    return (t > tMin && t < ray.tMax) ? t : kNoHit;
}

Vec3 sphereNormal(const Sphere& sphere, const Vec3& point) {
    // Normalised rather than divided by the radius: a point off the sphere by the rounding of t
    // still gets a unit normal, so centre + radius * normal puts the point back on the sphere.
    const Vec3 v = point - sphere.center;
    const float length = glm::length(v);
    return length > 0.0f ? v / length : Vec3{0.0f, 1.0f, 0.0f};
}

Vec3 triangleNormal(const Triangle& tri) {
    const Vec3 cross = glm::cross(tri.b - tri.a, tri.c - tri.a);
    if (glm::dot(cross, cross) >= std::numeric_limits<float>::min()) return glm::normalize(cross);
    // A sliver's squared cross product underflows float (edges of 1e-19 and less): in double.
    return Vec3(glm::normalize(glm::cross(glm::dvec3(tri.b) - glm::dvec3(tri.a), glm::dvec3(tri.c) - glm::dvec3(tri.a))));
}

}  // namespace lightpath
