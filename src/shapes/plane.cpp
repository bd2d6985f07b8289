// `[[planes]]`: an infinite plane, declared, read and registered here like every shape kind
// (docs/extending.md). Unbounded (ShapeOps::bounded false): the accelerator tests it apart, on
// every ray, and its area is infinite, so it is never sampled as an area light.
#include "geometry/builtin_shapes.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/intersect.h"
#include "sampling/warp.h"
#include "scene/shape_type.h"

namespace lightpath {

namespace {

// The plane a record holds: a point, the unit normal.
Plane planeOf(const ShapeRecord& r) {
    Plane plane;
    plane.point = {r.data[0], r.data[1], r.data[2]};
    plane.normal = {r.data[3], r.data[4], r.data[5]};
    plane.object = r.object;
    return plane;
}

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

// Metres from the plane's point along its frame (s, t) (sampling/warp.h; a floor with normal +y:
// u along x, v along -z).
SurfaceParameters parametrisePlane(const ShapeRecord& record, const Vec3& point) {
    const Plane plane = planeOf(record);
    const Frame frame(plane.normal);
    const Vec3 d = point - plane.point;
    return {Vec2(glm::dot(d, frame.s), glm::dot(d, frame.t)), frame.s, frame.t};
}

double planeArea(const ShapeRecord&) { return std::numeric_limits<double>::infinity(); }

void tessellatePlaneRegion(const ShapeRecord& record, const Bounds& region, std::vector<Triangle>& out) {
    // The rectangle over the region and the plane's own point, grown by half their diagonal (at
    // least 1) on every side: it reaches past everything the scene holds, so every hit a ray of the
    // scene finds on the plane near the scene lies on it.
    const Plane plane = planeOf(record);
    Bounds box = region;
    box.grow(plane.point);
    const Vec3 margin{std::max(0.5f * glm::length(box.hi - box.lo), 1.0f)};
    const Vec3 lo = box.lo - margin, hi = box.hi + margin;

    // The box's corners projected onto the plane, in a basis (s, t) with s x t = normal.
    const Frame frame(plane.normal);
    float sMin = std::numeric_limits<float>::max(), sMax = -sMin, tMin = sMin, tMax = -sMin;
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3 p{corner & 1 ? hi.x : lo.x, corner & 2 ? hi.y : lo.y, corner & 4 ? hi.z : lo.z};
        const Vec3 d = p - plane.point;
        sMin = std::min(sMin, glm::dot(d, frame.s));
        sMax = std::max(sMax, glm::dot(d, frame.s));
        tMin = std::min(tMin, glm::dot(d, frame.t));
        tMax = std::max(tMax, glm::dot(d, frame.t));
    }
    const auto at = [&](float s, float t) { return plane.point + s * frame.s + t * frame.t; };
    const Vec3 a = at(sMin, tMin), b = at(sMax, tMin), c = at(sMax, tMax), d = at(sMin, tMax);
    out.push_back({a, b, c, plane.object});
    out.push_back({a, c, d, plane.object});
}

// The rasteriser's depth: n.(s D - (p - eye)) = 0 at s = n.(p - eye) / n.D, in front of the eye
// where positive. The eye in the plane sees it edge-on: 0, no depth.
float planeDepthAlong(const ShapeRecord& record, const Vec3& eye, const Vec3& direction) {
    const Plane plane = planeOf(record);
    const float offset = glm::dot(plane.normal, plane.point - eye);
    if (!(std::fabs(offset) > 0.0f)) return 0.0f;
    return offset / glm::dot(plane.normal, direction);
}

void addPlane(const ParameterValues& values, SceneBuilder& scene) {
    Plane plane;
    plane.point = values.vec3("point");
    // In double: the squared length of a tiny float vector (1e-30) underflows to 0 in float.
    plane.normal = Vec3(glm::normalize(glm::dvec3(values.vec3("normal"))));
    plane.object = scene.addShapeObject(values);
    scene.addPlane(plane);
}

// No area sampling and no tessellation of the whole: an infinite surface has neither; radiosity
// meshes the rectangle over the scene (tessellateRegion).
const ShapeOps kPlaneOps{.name = "plane",
                         .bounds = planeBounds,
                         .intersect = intersectPlaneRecord,
                         .describe = describePlane,
                         .area = planeArea,
                         .bounded = false,
                         .tessellateRegion = tessellatePlaneRegion,
                         .depthAlong = planeDepthAlong,
                         .parametrise = parametrisePlane};

}  // namespace

ShapeRecord planeRecord(const Plane& plane) {
    ShapeRecord record;
    record.ops = &kPlaneOps;
    std::copy_n(&plane.point.x, 3, record.data.begin());
    std::copy_n(&plane.normal.x, 3, record.data.begin() + 3);
    record.object = plane.object;
    return record;
}

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
