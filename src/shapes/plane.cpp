// `[[planes]]`: an infinite plane, declared, read and registered here like every shape kind
// (docs/extending.md). Unbounded (ShapeOps::bounded false): the accelerator tests it apart, on
// every ray, and its area is infinite, so it is never sampled as an area light.
#include "geometry/builtin_shapes.h"

#include <algorithm>
#include <limits>

#include "geometry/intersect.h"
#include "scene/shape_type.h"

namespace lightpath {

ShapeRecord planeRecord(const Plane& plane) {
    ShapeRecord record;
    record.ops = &kPlaneOps;
    std::copy_n(&plane.point.x, 3, record.data.begin());
    std::copy_n(&plane.normal.x, 3, record.data.begin() + 3);
    record.object = plane.object;
    return record;
}

Plane planeOf(const ShapeRecord& r) {
    Plane plane;
    plane.point = {r.data[0], r.data[1], r.data[2]};
    plane.normal = {r.data[3], r.data[4], r.data[5]};
    plane.object = r.object;
    return plane;
}

namespace {

Bounds planeBounds(const ShapeRecord&) {
    constexpr float kInfinity = std::numeric_limits<float>::infinity();
    return {Vec3(-kInfinity), Vec3(kInfinity)};
}

float intersectPlaneRecord(const Ray& ray, const ShapeRecord& record, float tMin, const NumericsOptions&) {
    return intersectPlane(ray, planeOf(record), tMin);
}

void describePlane(const ShapeRecord& record, SurfaceHit& hit) {
    hit.normal = planeOf(record).normal;
    hit.shadingNormal = hit.normal;
}

double planeArea(const ShapeRecord&) { return std::numeric_limits<double>::infinity(); }

void addPlane(const ParameterValues& values, SceneBuilder& scene) {
    Plane plane;
    plane.point = values.vec3("point");
    // In double: the squared length of a tiny float vector (1e-30) underflows to 0 in float.
    plane.normal = Vec3(glm::normalize(glm::dvec3(values.vec3("normal"))));
    plane.object = scene.addShapeObject(values);
    scene.addPlane(plane);
}

}  // namespace

// No area sampling and no tessellation: an infinite surface has neither (radiosity clips planes
// to the scene's bounds itself, integrators/radiosity_mesh.cpp).
const ShapeOps kPlaneOps{"plane", false, planeBounds, intersectPlaneRecord, describePlane, planeArea,
                         nullptr, nullptr, false};

}  // namespace lightpath

// Rank 1: planes are numbered after the spheres, before every other kind.
LIGHTPATH_REGISTER_SHAPE(lightpath::ShapeType{
    {"shape", "plane", "an infinite plane, seen from both sides",
     {lightpath::kShapeNameParameter,
      {"point", lightpath::ParameterType::Point, "m", "", {}, "a point on the plane", true},
      {"normal", lightpath::ParameterType::Vector, "", "", {}, "the side it faces (normalised)", true},
      lightpath::kShapeMaterialParameter},
     ""},
    1, "planes", lightpath::addPlane})
