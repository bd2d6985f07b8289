#include "lights/area_light.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "geometry/intersect.h"
#include "sampling/warp.h"
#include "util/hot_path.h"

namespace lightpath {
namespace {

float shapeArea(const SceneGeometry& geometry, std::uint32_t primitive) {
    if (const ShapeRecord* shape = geometry.shapeOf(primitive)) return static_cast<float>(shape->ops->area(*shape));
    const Triangle& t = geometry.triangleOf(primitive);
    // In float while its squared cross product is a normal float (as every shipped mesh's is, so
    // their areas, and images, stay bit-identical), else in double: a sliver's area is small, not 0.
    const Vec3 cross = glm::cross(t.b - t.a, t.c - t.a);
    const float length2 = glm::dot(cross, cross);
    if (length2 >= std::numeric_limits<float>::min()) return 0.5f * std::sqrt(length2);
    return static_cast<float>(surfaceArea(t));
}

// Emits from both sides of its surface: a kind that encloses a volume (a sphere).
bool emitsTwoSided(const SceneGeometry& geometry, std::uint32_t primitive) {
    const ShapeRecord* shape = geometry.shapeOf(primitive);
    return shape != nullptr && shape->ops->closed;
}

}  // namespace

AreaLightSource::AreaLightSource(const PathEvent& event, ColorParameter emission, const SceneGeometry& geometry,
                                 const std::vector<std::uint32_t>& primitives, bool twoSided)
    : Light(event), emission_(std::move(emission)), geometry_(geometry) {
    std::size_t twoSidedCount = 0;
    for (std::uint32_t primitive : primitives) {
        const float area = shapeArea(geometry, primitive);
        // A zero-area triangle emits nothing and cannot be sampled; an unbounded shape (infinite
        // area) cannot be either.
        if (!(area > 0.0f) || !std::isfinite(area)) continue;
        area_ += area;
        const bool isTriangle = geometry.shapeOf(primitive) == nullptr;
        shapes_.push_back({primitive, area_, isTriangle ? triangleNormal(geometry.triangleOf(primitive)) : Vec3(0.0f)});
        twoSidedCount += emitsTwoSided(geometry, primitive);
    }
    if (!twoSided && twoSidedCount != 0 && twoSidedCount != shapes_.size())
        throw std::invalid_argument("an area light is closed shapes (spheres) or open ones (triangles), not both");
    twoSided_ = twoSided || twoSidedCount != 0;
    if (shapes_.size() == 1) {
        const ShapeRecord* shape = geometry.shapeOf(shapes_[0].primitive);
        if (shape != nullptr && shape->ops->sampleSolidAngle != nullptr && shape->ops->pdfSolidAngle != nullptr)
            solidAngle_ = shape;
    }
    sampleable_ = area_ >= kMinSampledEmitterArea;
    pdfArea_ = 1.0f / area_;
}

LIGHTPATH_HOT_PATH
AreaLightSource::SurfacePoint AreaLightSource::samplePoint(Vec2 u) const {
    // Reuse u.x: pick the shape, then rescale the remainder to [0, 1) for the point on it.
    const float target = u.x * area_;
    auto it = std::upper_bound(shapes_.begin(), shapes_.end(), target,
                               [](float value, const Shape& s) { return value < s.cumulativeArea; });
    if (it == shapes_.end()) --it;
    const float before = it == shapes_.begin() ? 0.0f : std::prev(it)->cumulativeArea;
    const float width = it->cumulativeArea - before;
    u.x = width > 0.0f ? std::clamp((target - before) / width, 0.0f, 0.99999994f) : 0.0f;

    if (const ShapeRecord* shape = geometry_.shapeOf(it->primitive)) {
        const AreaSample p = shape->ops->sampleArea(*shape, u);
        if (!emission_.textured()) return {p.point, p.normal};
        return {p.point, p.normal, geometry_.uvAt(it->primitive, p.point, p.normal)};
    }
    const Triangle& t = geometry_.triangleOf(it->primitive);
    const Vec3 b = sampleUniformTriangle(u);
    const Vec3 point = b.x * t.a + b.y * t.b + b.z * t.c;
    if (!emission_.textured()) return {point, it->triangleNormal};
    // The sampled barycentrics interpolate the corners' uvs: the same uv a ray hitting `point` finds.
    return {point, it->triangleNormal, geometry_.uvAt(it->primitive, point, it->triangleNormal, &b)};
}

Rgb AreaLightSource::emissionAt(Vec2 uv) const {
    SurfaceSide side;
    side.texture.uv = uv;
    return emission_.at(side);
}

LIGHTPATH_HOT_PATH
LightSample AreaLightSource::sample(const Vec3& receiver, Vec2 u) const {
    LightSample s;
    if (!sampleable_) return s;
    SolidAngleSample byAngle;
    Vec2 uv{0.0f};
    const bool byArea = !(solidAngle_ && solidAngle_->ops->sampleSolidAngle(*solidAngle_, receiver, u, byAngle));
    if (!byArea) {
        if (!(byAngle.pdf > 0.0f)) return s;
        s.point = byAngle.point;
        s.normal = byAngle.normal;
        s.pdf = byAngle.pdf;
        if (emission_.textured()) uv = geometry_.uvAt(shapes_[0].primitive, s.point, s.normal);
    } else {
        const SurfacePoint p = samplePoint(u);
        s.point = p.point;
        s.normal = p.normal;
        uv = p.uv;
    }
    // The vector to the light, its length and (by area) the density's conversion share one
    // computation (docs/performance.md, Shading share, eighth pass).
    const Vec3 toLight = s.point - receiver;
    const float distance2 = glm::dot(toLight, toLight);
    s.distance = std::sqrt(distance2);
    if (byArea) s.pdf = areaToSolidAngle(pdfArea_, distance2, s.distance, glm::dot(s.normal, toLight));
    if (!(s.distance > 0.0f)) {
        s.pdf = 0.0f;
        return s;
    }
    s.wi = toLight / s.distance;
    // The receiver behind a one-sided emitter sees nothing of it.
    if (!twoSided_ && -glm::dot(s.normal, s.wi) <= 0.0f) s.pdf = 0.0f;
    if (s.pdf > 0.0f) s.weight = (emission_.textured() ? emissionAt(uv) : emission_.constant()) / s.pdf;
    return s;
}

float AreaLightSource::pdf(const Vec3& receiver, const Vec3& point, const Vec3& normal) const {
    if (!sampleable_) return 0.0f;
    float byAngle = 0.0f;
    if (solidAngle_ && solidAngle_->ops->pdfSolidAngle(*solidAngle_, receiver, byAngle)) return byAngle;
    return areaToSolidAngle(pdfArea_, receiver, point, normal);
}

bool AreaLightSource::samplesByArea(const Vec3& receiver) const {
    float byAngle = 0.0f;
    return !solidAngle_ || !solidAngle_->ops->pdfSolidAngle(*solidAngle_, receiver, byAngle);
}

EmittedRay AreaLightSource::sampleEmission(Vec2 uPoint, Vec2 uDirection) const {
    const SurfacePoint p = samplePoint(uPoint);
    EmittedRay e;
    Vec3 normal = p.normal;
    if (twoSided_ && uDirection.x < 0.5f) {
        // Emitting on both sides: pick one, then reuse the sample for the direction.
        normal = -normal;
        uDirection.x *= 2.0f;
    } else if (twoSided_) {
        uDirection.x = (uDirection.x - 0.5f) * 2.0f;
    }
    const Vec3 local = sampleCosineHemisphere(uDirection);
    e.ray.origin = p.point;
    e.ray.direction = Frame(normal).toWorld(local);
    e.normal = normal;
    e.radiance = emissionAt(p.uv);
    e.pdfPosition = pdfArea_;
    e.pdfDirection = cosineHemispherePdf(local.z) * (twoSided_ ? 0.5f : 1.0f);
    return e;
}

float AreaLightSource::pdfEmissionDirection(const Vec3& normal, const Vec3& direction) const {
    // sampleEmission's cosine lobe about the side's normal; a two-sided light picks either side by half.
    const float cosine = glm::dot(normal, direction);
    if (twoSided_) return 0.5f * cosineHemispherePdf(std::fabs(cosine));
    return cosine > 0.0f ? cosineHemispherePdf(cosine) : 0.0f;
}

EmittedRay AreaLightSource::emitAlong(const EmittedRay& from, const Vec3& direction) const {
    EmittedRay e = from;
    e.ray.direction = direction;
    // A two-sided light emits the same radiance from both sides of its surface: it leaves by the
    // side that faces the direction; a one-sided one only by its normal's side.
    if (twoSided_ && glm::dot(e.normal, direction) < 0.0f) e.normal = -e.normal;
    if (!(glm::dot(e.normal, direction) > 0.0f)) e.radiance = Rgb{0.0f};
    e.pdfDirection = pdfEmissionDirection(e.normal, direction);
    return e;
}

Rgb AreaLightSource::radiance(const SurfaceHit& hit, const Vec3& towardViewer) const {
    if (!twoSided_ && glm::dot(hit.normal, towardViewer) <= 0.0f) return Rgb{0.0f};
    if (!emission_.textured()) return emission_.constant();
    return emissionAt(geometry_.uvAt(hit.primitive, hit.point, hit.normal));
}

Rgb AreaLightSource::power() const {
    // Le pi A for a one-sided Lambertian emitter, twice that for a two-sided one. A
    // texture's mean over its image stands for its mean over the surface: any positive power keeps
    // light choice unbiased; a closer one only lowers the noise.
    return emission_.mean() * (kPi * area_ * (twoSided_ ? 2.0f : 1.0f));
}

LIGHTPATH_HOT_PATH
float areaToSolidAngle(float pdfArea, const Vec3& receiver, const Vec3& point, const Vec3& normal) {
    const Vec3 toPoint = point - receiver;
    const float distance2 = glm::dot(toPoint, toPoint);
    return areaToSolidAngle(pdfArea, distance2, std::sqrt(distance2), glm::dot(normal, toPoint));
}

}  // namespace lightpath
