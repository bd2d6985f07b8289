#include "geometry/intersect.h"

#include <cmath>
#include <utility>

namespace lightpath {
namespace {

int maxDimension(const Vec3& v) {
    return (v.x > v.y) ? (v.x > v.z ? 0 : 2) : (v.y > v.z ? 1 : 2);
}

Vec3 permute(const Vec3& v, int x, int y, int z) { return {v[x], v[y], v[z]}; }

}  // namespace

float intersectSphere(const Ray& ray, const Sphere& sphere, float tMin) {
    const Vec3 f = ray.origin - sphere.center;  // from the centre to the ray origin
    const Vec3& d = ray.direction;              // unit, so a = 1
    const float b = glm::dot(f, d);
    const Vec3 perpendicular = f - b * d;       // f minus its projection on the ray
    const float r2 = sphere.radius * sphere.radius;
    const float discriminant = r2 - glm::dot(perpendicular, perpendicular);
    if (discriminant < 0.0f) return kNoHit;
    const float c = glm::dot(f, f) - r2;
    const float q = -(b + std::copysign(std::sqrt(discriminant), b));
    float t0 = c / q;
    float t1 = q;
    if (q == 0.0f) t0 = t1 = 0.0f;  // ray origin at the centre of a degenerate sphere
    if (t0 > t1) std::swap(t0, t1);
    if (t0 > tMin && t0 < ray.tMax) return t0;
    if (t1 > tMin && t1 < ray.tMax) return t1;
    return kNoHit;
}

float intersectSphereNaive(const Ray& ray, const Sphere& sphere, float tMin) {
    const Vec3 co = ray.origin - sphere.center;
    const float a = glm::dot(ray.direction, ray.direction);
    const float b = 2.0f * glm::dot(co, ray.direction);
    const float c = glm::dot(co, co) - sphere.radius * sphere.radius;
    const float discriminant = b * b - 4.0f * a * c;
    if (discriminant < 0.0f) return kNoHit;
    const float root = std::sqrt(discriminant);
    const float t0 = (-b - root) / (2.0f * a);
    const float t1 = (-b + root) / (2.0f * a);
    if (t0 > tMin && t0 < ray.tMax) return t0;
    if (t1 > tMin && t1 < ray.tMax) return t1;
    return kNoHit;
}

float intersectPlane(const Ray& ray, const Plane& plane, float tMin) {
    const float denominator = glm::dot(plane.normal, ray.direction);
    if (denominator == 0.0f) return kNoHit;  // parallel: no single point in common
    const float t = glm::dot(plane.point - ray.origin, plane.normal) / denominator;
    return (t > tMin && t < ray.tMax) ? t : kNoHit;
}

float intersectTriangle(const Ray& ray, const Triangle& tri, float tMin, Vec3* barycentrics) {
    // Shear and scale so the ray becomes the +z axis through the origin; then the three edge
    // functions are 2D cross products evaluated identically for a shared edge.
    const Vec3 absDir = glm::abs(ray.direction);
    const int kz = maxDimension(absDir);
    int kx = (kz + 1) % 3;
    int ky = (kx + 1) % 3;
    if (ray.direction[kz] < 0.0f) std::swap(kx, ky);  // keep the winding
    const Vec3 d = permute(ray.direction, kx, ky, kz);
    const float sx = -d.x / d.z, sy = -d.y / d.z, sz = 1.0f / d.z;

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
    return (point - sphere.center) / sphere.radius;
}

Vec3 triangleNormal(const Triangle& tri) {
    return glm::normalize(glm::cross(tri.b - tri.a, tri.c - tri.a));
}

}  // namespace lightpath
