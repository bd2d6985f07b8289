// Example plugin (docs/extending.md): `[[cylinders]]`, an open cylinder (no caps), the worked
// example of adding a shape outside the library. One file: its geometry as a ShapeOps table
// (geometry/shape.h) and its scene-file type, registered with LIGHTPATH_REGISTER_SHAPE.
// It is open (closed = false): seen from both sides, emitting on its outer side only.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <utility>

#include "geometry/intersect.h"
#include "sampling/warp.h"
#include "scene/shape_type.h"

namespace lightpath::examples {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// The record's floats: the base's centre, the unit axis from base to top, the height, the radius.
struct Cylinder {
    Vec3 base;
    Vec3 axis;
    float height;
    float radius;
};

Cylinder unpack(const ShapeRecord& r) {
    return {{r.data[0], r.data[1], r.data[2]}, {r.data[3], r.data[4], r.data[5]}, r.data[6], r.data[7]};
}

// The point at angle phi about the axis (from Frame(axis).s towards .t) and height s above the base.
Vec3 surfacePoint(const Cylinder& c, const Frame& frame, double phi, float s) {
    const Vec3 radial = float(std::cos(phi)) * frame.s + float(std::sin(phi)) * frame.t;
    return c.base + s * c.axis + c.radius * radial;
}

Bounds cylinderBounds(const ShapeRecord& record) {
    // The rim circles at both ends: along axis i each reaches r sqrt(1 - a_i^2) from its centre.
    const Cylinder c = unpack(record);
    const Vec3 top = c.base + c.height * c.axis;
    const Vec3 extent = c.radius * glm::sqrt(glm::max(Vec3(0.0f), Vec3(1.0f) - c.axis * c.axis));
    return {glm::min(c.base, top) - extent, glm::max(c.base, top) + extent};
}

float intersectCylinder(const Ray& ray, const ShapeRecord& record, float tMin, const NumericsOptions&) {
    // Across the axis the cylinder is a circle: |f + t d|^2 = r^2 for the parts f, d of the origin
    // (from the base) and the direction perpendicular to the axis. Solved in double as the sphere
    // (geometry/intersect.h: Haines et al. 2019, the discriminant from the line's distance to the
    // axis and the root pair q/a, c/q), each root kept if it lies between base and top.
    const Cylinder c = unpack(record);
    const glm::dvec3 axis(c.axis);
    const glm::dvec3 origin = glm::dvec3(ray.origin) - glm::dvec3(c.base);
    const glm::dvec3 direction(ray.direction);
    const double originAlong = glm::dot(origin, axis), directionAlong = glm::dot(direction, axis);
    const glm::dvec3 f = origin - originAlong * axis;
    const glm::dvec3 d = direction - directionAlong * axis;
    const double a = glm::dot(d, d);
    if (!(a > 0.0)) return kNoHit;  // along the axis (or NaN): no single crossing of the wall
    const double b = glm::dot(f, d);
    const double r = c.radius;
    const glm::dvec3 perpendicular = f - (b / a) * d;
    const double discriminant = a * (r * r - glm::dot(perpendicular, perpendicular));
    if (!(discriminant >= 0.0)) return kNoHit;
    const double q = -(b + std::copysign(std::sqrt(discriminant), b));
    double t0 = q / a;
    double t1 = q != 0.0 ? (glm::dot(f, f) - r * r) / q : t0;
    if (t0 > t1) std::swap(t0, t1);
    for (const double t : {t0, t1}) {
        if (!(t > 0.0)) continue;  // behind, even if it rounds to a float t of 0 (as the disk)
        const auto tf = static_cast<float>(t);
        if (!(tf > tMin && tf < ray.tMax)) continue;
        const double along = originAlong + t * directionAlong;
        if (along >= 0.0 && along <= double(c.height)) return tf;
    }
    return kNoHit;
}

void describeCylinder(const ShapeRecord& record, SurfaceHit& hit) {
    // The outward normal is the hit's offset from the axis; the point goes back onto the wall
    // (ray.at(t) carries the rounding of t).
    const Cylinder c = unpack(record);
    const glm::dvec3 axis(c.axis);
    const glm::dvec3 offset = glm::dvec3(hit.point) - glm::dvec3(c.base);
    const double along = glm::dot(offset, axis);
    const glm::dvec3 radial = offset - along * axis;
    const double distance = glm::length(radial);
    const Vec3 normal = distance > 0.0 ? Vec3(radial / distance) : Frame(c.axis).s;
    hit.point = c.base + float(along) * c.axis + c.radius * normal;
    hit.normal = normal;
    hit.shadingNormal = normal;
}

double cylinderArea(const ShapeRecord& record) {
    const Cylinder c = unpack(record);
    return kTwoPi * double(c.radius) * double(c.height);
}

AreaSample sampleCylinder(const ShapeRecord& record, Vec2 u) {
    // Unrolled, the wall is a 2 pi r x h rectangle: uniform in angle and height is uniform by area.
    const Cylinder c = unpack(record);
    const Frame frame(c.axis);
    const double phi = kTwoPi * double(u.x);
    const Vec3 normal = float(std::cos(phi)) * frame.s + float(std::sin(phi)) * frame.t;
    return {c.base + (u.y * c.height) * c.axis + c.radius * normal, normal};
}

void tessellateCylinder(const ShapeRecord& record, float edgeLength, std::vector<Triangle>& out) {
    // `rings` x `sectors` quads of two triangles; each side at most edgeLength / sqrt 2, so the
    // diagonal too is at most edgeLength. (p(i, j), p(i, j+1), p(i+1, j)) turns from the angle's
    // direction to the axis': (d/dphi) x axis is the outward normal (Frame's s x t = axis).
    constexpr float kMinSectors = 8.0f, kMaxSectors = 4096.0f, kMaxRings = 4096.0f;
    const Cylinder c = unpack(record);
    const float side = edgeLength / std::sqrt(2.0f);
    const auto count = [](float wanted, float low, float high) {
        return static_cast<std::uint32_t>(std::clamp(std::isfinite(wanted) ? wanted : high, low, high));
    };
    const std::uint32_t sectors = count(std::ceil(2.0f * kPi * c.radius / side), kMinSectors, kMaxSectors);
    const std::uint32_t rings = count(std::ceil(c.height / side), 1.0f, kMaxRings);
    const Frame frame(c.axis);
    const auto at = [&](std::uint32_t ring, std::uint32_t sector) {
        const double phi = kTwoPi * double(sector % sectors) / double(sectors);
        return surfacePoint(c, frame, phi, c.height * float(ring) / float(rings));
    };
    for (std::uint32_t ring = 0; ring < rings; ++ring) {
        for (std::uint32_t sector = 0; sector < sectors; ++sector) {
            const Vec3 p00 = at(ring, sector), p01 = at(ring, sector + 1);
            const Vec3 p10 = at(ring + 1, sector), p11 = at(ring + 1, sector + 1);
            out.push_back({p00, p01, p10, record.object});
            out.push_back({p01, p11, p10, record.object});
        }
    }
}

constexpr ShapeOps kCylinderOps{"cylinder",   false,          cylinderBounds, intersectCylinder, describeCylinder,
                                cylinderArea, sampleCylinder, tessellateCylinder};

void addCylinder(const ParameterValues& values, SceneBuilder& scene) {
    const Vec3 base = values.vec3("base"), top = values.vec3("top");
    // In double: the squared length of a tiny float vector underflows to 0 in float.
    const glm::dvec3 span = glm::dvec3(top) - glm::dvec3(base);
    const double height = glm::length(span);
    if (!(float(height) > 0.0f)) values.fail("top", "expected a point other than base (the cylinder has no height)");
    const Vec3 axis(span / height);
    ShapeRecord record;
    record.ops = &kCylinderOps;
    std::copy_n(&base.x, 3, record.data.begin());
    std::copy_n(&axis.x, 3, record.data.begin() + 3);
    record.data[6] = float(height);
    record.data[7] = values.number("radius");
    record.object = scene.addShapeObject(values);
    if (auto warning = tooSmallToSampleWarning("cylinder", cylinderArea(record), scene.emissionOf(record.object)))
        scene.warn(values.located("radius", *warning));
    scene.addShape(record);
}

}  // namespace
}  // namespace lightpath::examples

LIGHTPATH_REGISTER_SHAPE(lightpath::ShapeType{
    {"shape", "cylinder", "example plugin: an open cylinder (no caps), seen from both sides, emitting outwards",
     {lightpath::kShapeNameParameter,
      {"base", lightpath::ParameterType::Point, "m", "", {}, "the centre of one end", true},
      {"top", lightpath::ParameterType::Point, "m", "", {}, "the centre of the other end, not base", true},
      {"radius", lightpath::ParameterType::Number, "m", "", lightpath::kPositive, "its radius", true},
      lightpath::kShapeMaterialParameter},
     ""},
    100, "cylinders", lightpath::examples::addCylinder})
