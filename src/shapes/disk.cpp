// `[[disks]]`: a flat disk, the worked example of adding a shape (docs/extending.md). Everything
// the renderer asks of it is here: its geometry as a ShapeOps table (geometry/shape.h) and its
// scene-file type, registered with LIGHTPATH_REGISTER_SHAPE.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "geometry/intersect.h"
#include "sampling/warp.h"
#include "scene/shape_type.h"

namespace lightpath {
namespace {

// The record's floats: center, unit normal, radius.
struct Disk {
    Vec3 center;
    Vec3 normal;
    float radius;
};

Disk unpack(const ShapeRecord& r) {
    return {{r.data[0], r.data[1], r.data[2]}, {r.data[3], r.data[4], r.data[5]}, r.data[6]};
}

Bounds diskBounds(const ShapeRecord& record) {
    // Along axis i the rim reaches r sqrt(1 - n_i^2) from the centre.
    const Disk d = unpack(record);
    const Vec3 extent = d.radius * glm::sqrt(glm::max(Vec3(0.0f), Vec3(1.0f) - d.normal * d.normal));
    return {d.center - extent, d.center + extent};
}

float intersectDisk(const Ray& ray, const ShapeRecord& record, float tMin, const NumericsOptions&) {
    // The plane's hit (in double, as intersectPlane), then inside the rim: |p - c|^2 <= r^2.
    const Disk d = unpack(record);
    const glm::dvec3 normal(d.normal);
    const double denominator = glm::dot(normal, glm::dvec3(ray.direction));
    if (!(denominator != 0.0)) return kNoHit;
    const glm::dvec3 toCenter = glm::dvec3(d.center) - glm::dvec3(ray.origin);
    const double t = glm::dot(toCenter, normal) / denominator;
    if (!(t > 0.0)) return kNoHit;
    const auto tf = static_cast<float>(t);
    if (!(tf > tMin && tf < ray.tMax)) return kNoHit;
    const glm::dvec3 offset = t * glm::dvec3(ray.direction) - toCenter;
    const double r = d.radius;
    return glm::dot(offset, offset) <= r * r ? tf : kNoHit;
}

void describeDisk(const ShapeRecord& record, SurfaceHit& hit) {
    const Disk d = unpack(record);
    // Back onto the disk's plane: ray.at(t) carries the rounding of t.
    hit.point -= d.normal * glm::dot(hit.point - d.center, d.normal);
    hit.normal = d.normal;
    hit.shadingNormal = d.normal;
}

double diskArea(const ShapeRecord& record) {
    const double r = unpack(record).radius;
    return std::numbers::pi * r * r;
}

AreaSample sampleDisk(const ShapeRecord& record, Vec2 u) {
    // Shirley and Chiu's concentric map is uniform by area on the unit disk.
    const Disk d = unpack(record);
    const Vec2 p = d.radius * sampleConcentricDisk(u);
    const Frame frame(d.normal);
    return {d.center + p.x * frame.s + p.y * frame.t, d.normal};
}

void tessellateDisk(const ShapeRecord& record, float edgeLength, std::vector<Triangle>& out) {
    // A fan of `sectors` triangles from the centre, rim edges about edgeLength long; each
    // (centre, rim i, rim i+1) turns counter-clockwise about the normal (Frame's s x t = n).
    constexpr float kMinSectors = 8.0f, kMaxSectors = 4096.0f;
    const Disk d = unpack(record);
    const float wanted = std::ceil(2.0f * kPi * d.radius / edgeLength);
    const auto sectors = static_cast<std::uint32_t>(std::clamp(std::isfinite(wanted) ? wanted : kMaxSectors,
                                                               kMinSectors, kMaxSectors));
    const Frame frame(d.normal);
    const auto rim = [&](std::uint32_t i) {
        const double phi = 2.0 * std::numbers::pi * double(i % sectors) / double(sectors);
        return d.center + d.radius * (float(std::cos(phi)) * frame.s + float(std::sin(phi)) * frame.t);
    };
    for (std::uint32_t i = 0; i < sectors; ++i) out.push_back({d.center, rim(i), rim(i + 1), record.object});
}

constexpr ShapeOps kDiskOps{"disk", false, diskBounds, intersectDisk, describeDisk,
                            diskArea, sampleDisk,      tessellateDisk};

void addDisk(const ParameterValues& values, SceneBuilder& scene) {
    ShapeRecord record;
    record.ops = &kDiskOps;
    const Vec3 center = values.vec3("center");
    // In double: the squared length of a tiny float vector underflows to 0 in float.
    const Vec3 normal(glm::normalize(glm::dvec3(values.vec3("normal"))));
    std::copy_n(&center.x, 3, record.data.begin());
    std::copy_n(&normal.x, 3, record.data.begin() + 3);
    record.data[6] = values.number("radius");
    record.object = scene.addShapeObject(values);
    if (auto warning = tooSmallToSampleWarning("disk", diskArea(record), scene.emissionOf(record.object)))
        scene.warn(values.located("radius", *warning));
    scene.addShape(record);
}

}  // namespace
}  // namespace lightpath

LIGHTPATH_REGISTER_SHAPE(lightpath::ShapeType{
    {"shape", "disk", "a flat disk, seen from both sides, emitting on the side of its normal",
     {lightpath::kShapeNameParameter,
      {"center", lightpath::ParameterType::Point, "m", "", {}, "its centre", true},
      {"normal", lightpath::ParameterType::Vector, "", "", {}, "the side it faces (normalised)", true},
      {"radius", lightpath::ParameterType::Number, "m", "", lightpath::kPositive, "its radius", true},
      lightpath::kShapeMaterialParameter},
     ""},
    10, "disks", lightpath::addDisk})
