#include "geometry/scene_geometry.h"

#include <utility>

#include "geometry/intersect.h"

namespace lightpath {

SceneGeometry::SceneGeometry(std::vector<Sphere> spheres, std::vector<Plane> planes,
                             std::vector<Triangle> triangles, NumericsOptions numerics, Accelerator accelerator)
    : spheres_(std::move(spheres)), planes_(std::move(planes)), triangles_(std::move(triangles)),
      numerics_(numerics), accelerator_(accelerator) {}

float SceneGeometry::intersectPrimitive(const Ray& ray, std::uint32_t id) const {
    if (id == ray.ignoredPrimitive) return kNoHit;
    if (id < spheres_.size()) {
        const Sphere& s = spheres_[id];
        return numerics_.sphere == SphereTest::Stable ? intersectSphere(ray, s, ray.tMin)
                                                      : intersectSphereNaive(ray, s, ray.tMin);
    }
    id -= static_cast<std::uint32_t>(spheres_.size());
    if (id < planes_.size()) return intersectPlane(ray, planes_[id], ray.tMin);
    id -= static_cast<std::uint32_t>(planes_.size());
    const Triangle& t = triangles_[id];
    return numerics_.triangle == TriangleTest::Watertight ? intersectTriangle(ray, t, ray.tMin)
                                                          : intersectTriangleMollerTrumbore(ray, t, ray.tMin);
}

std::optional<SurfaceHit> SceneGeometry::intersect(const Ray& ray) const {
    // The lecture's loop: test every primitive, keep the smallest t.
    Ray closest = ray;
    std::uint32_t found = kNoPrimitive;
    const auto count = static_cast<std::uint32_t>(primitiveCount());
    for (std::uint32_t id = 0; id < count; ++id) {
        const float t = intersectPrimitive(closest, id);
        if (t == kNoHit) continue;
        closest.tMax = t;
        found = id;
    }
    if (found == kNoPrimitive) return std::nullopt;
    return describeHit(ray, closest.tMax, found);
}

bool SceneGeometry::occluded(const Ray& ray) const {
    const auto count = static_cast<std::uint32_t>(primitiveCount());
    for (std::uint32_t id = 0; id < count; ++id)
        if (intersectPrimitive(ray, id) != kNoHit) return true;
    return false;
}

SurfaceHit SceneGeometry::describeHit(const Ray& ray, float t, std::uint32_t id) const {
    SurfaceHit hit;
    hit.t = t;
    hit.point = ray.at(t);
    hit.primitive = id;
    if (id < spheres_.size()) {
        const Sphere& s = spheres_[id];
        hit.shape = ShapeKind::Sphere;
        hit.normal = sphereNormal(s, hit.point);
        // Snap the point back onto the sphere: ray.at(t) carries the rounding of t.
        hit.point = s.center + hit.normal * s.radius;
        hit.shadingNormal = hit.normal;
        hit.object = s.object;
        return hit;
    }
    id -= static_cast<std::uint32_t>(spheres_.size());
    if (id < planes_.size()) {
        hit.shape = ShapeKind::Plane;
        hit.normal = planes_[id].normal;
        hit.shadingNormal = hit.normal;
        hit.object = planes_[id].object;
        return hit;
    }
    id -= static_cast<std::uint32_t>(planes_.size());
    const Triangle& tri = triangles_[id];
    hit.shape = ShapeKind::Triangle;
    hit.normal = triangleNormal(tri);
    hit.shadingNormal = hit.normal;
    hit.object = tri.object;
    Vec3 weights;
    if (intersectTriangle(ray, tri, ray.tMin, &weights) != kNoHit)
        hit.point = weights.x * tri.a + weights.y * tri.b + weights.z * tri.c;
    return hit;
}

}  // namespace lightpath
