#include "geometry/scene_geometry.h"

#include <utility>

#include "geometry/intersect.h"

namespace lightpath {

SceneGeometry::SceneGeometry(std::vector<Sphere> spheres, std::vector<Plane> planes,
                             std::vector<Triangle> triangles)
    : spheres_(std::move(spheres)), planes_(std::move(planes)), triangles_(std::move(triangles)) {}

std::optional<SurfaceHit> SceneGeometry::intersect(const Ray& ray) const {
    // The lecture's loop: test every primitive, keep the smallest t.
    Ray closest = ray;
    ShapeKind kind = ShapeKind::Sphere;
    std::uint32_t index = 0;
    bool found = false;
    auto consider = [&](float t, ShapeKind k, std::size_t i) {
        if (t == kNoHit) return;
        closest.tMax = t;
        kind = k;
        index = static_cast<std::uint32_t>(i);
        found = true;
    };
    for (std::size_t i = 0; i < spheres_.size(); ++i)
        consider(intersectSphere(closest, spheres_[i], 0.0f), ShapeKind::Sphere, i);
    for (std::size_t i = 0; i < planes_.size(); ++i)
        consider(intersectPlane(closest, planes_[i], 0.0f), ShapeKind::Plane, i);
    for (std::size_t i = 0; i < triangles_.size(); ++i)
        consider(intersectTriangle(closest, triangles_[i], 0.0f), ShapeKind::Triangle, i);
    if (!found) return std::nullopt;

    SurfaceHit hit;
    hit.t = closest.tMax;
    hit.point = ray.at(hit.t);
    hit.shape = kind;
    hit.primitive = index;
    switch (kind) {
        case ShapeKind::Sphere: {
            const Sphere& s = spheres_[index];
            hit.normal = sphereNormal(s, hit.point);
            // Snap the point back onto the sphere: ray.at(t) carries the rounding of t.
            hit.point = s.center + hit.normal * s.radius;
            hit.object = s.object;
            break;
        }
        case ShapeKind::Plane:
            hit.normal = planes_[index].normal;
            hit.object = planes_[index].object;
            break;
        case ShapeKind::Triangle:
            hit.normal = triangleNormal(triangles_[index]);
            hit.object = triangles_[index].object;
            break;
    }
    return hit;
}

bool SceneGeometry::occluded(const Ray& ray) const {
    for (const Sphere& s : spheres_)
        if (intersectSphere(ray, s, 0.0f) != kNoHit) return true;
    for (const Plane& p : planes_)
        if (intersectPlane(ray, p, 0.0f) != kNoHit) return true;
    for (const Triangle& t : triangles_)
        if (intersectTriangle(ray, t, 0.0f) != kNoHit) return true;
    return false;
}

}  // namespace lightpath
