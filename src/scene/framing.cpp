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
    const double halfVertical = 0.5 * static_cast<double>(camera.verticalFovDegrees) * kPi / 180.0;
    const double aspect = static_cast<double>(camera.width) / camera.height;
    const double halfHorizontal = std::atan(std::tan(halfVertical) * aspect);
    const double distance = kFramingMargin * radius / std::sin(std::min(halfVertical, halfHorizontal));
    const Vec3 back = glm::normalize(camera.eye - camera.lookAt);
    camera.lookAt = centre;
    camera.eye = centre + static_cast<float>(distance) * back;
    return camera;
}

}  // namespace lightpath
