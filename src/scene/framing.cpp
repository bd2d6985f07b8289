#include "scene/framing.h"

#include <algorithm>
#include <cmath>

#include "geometry/shape.h"

namespace lightpath {

Bounds sceneBounds(const Scene& scene) {
    Bounds box;
    for (const Sphere& s : scene.spheres) {
        box.grow(s.center - Vec3(s.radius));
        box.grow(s.center + Vec3(s.radius));
    }
    for (const ShapeRecord& record : scene.shapes)
        if (record.ops->bounded) box.grow(record.ops->bounds(record));
    for (const Triangle& t : scene.triangles) {
        box.grow(t.a);
        box.grow(t.b);
        box.grow(t.c);
    }
    return box;
}

CameraDescription framingCamera(const Bounds& bounds, CameraDescription camera) {
    const Vec3 centre = bounds.empty() ? Vec3(0.0f) : bounds.centroid();
    float radius = bounds.empty() ? 1.0f : 0.5f * glm::length(bounds.hi - bounds.lo);
    if (!(radius > 0.0f)) radius = 1.0f;  // a single point: frame the unit sphere around it
    const double aspect = static_cast<double>(camera.width) / camera.height;
    const Vec3 back = glm::normalize(camera.eye - camera.lookAt);
    if (camera.projection == Projection::Orthographic) {
        // The film, where its rays start, outside the sphere; a view of the sphere's diameter
        // (times the margin) across the image's shorter side.
        camera.orthographicHeight = static_cast<float>(2.0 * kFramingMargin * radius / std::min(1.0, aspect));
        camera.lookAt = centre;
        camera.eye = centre + static_cast<float>(2.0 * kFramingMargin * radius) * back;
        return camera;
    }
    const double halfVertical = 0.5 * static_cast<double>(camera.verticalFovDegrees) * kPi / 180.0;
    const double halfHorizontal = std::atan(std::tan(halfVertical) * aspect);
    const double distance = kFramingMargin * radius / std::sin(std::min(halfVertical, halfHorizontal));
    camera.lookAt = centre;
    camera.eye = centre + static_cast<float>(distance) * back;
    return camera;
}

}  // namespace lightpath
