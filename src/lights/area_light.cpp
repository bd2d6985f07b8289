#include "lights/area_light.h"

#include <algorithm>
#include <cmath>

#include "sampling/warp.h"

namespace lightpath {
namespace {

float shapeArea(const SceneGeometry& geometry, std::uint32_t primitive) {
    const auto ref = geometry.decodePrimitive(primitive);
    if (ref.shape == ShapeKind::Sphere) {
        const float r = geometry.spheres()[ref.index].radius;
        return 4.0f * kPi * r * r;
    }
    const Triangle& t = geometry.triangles()[ref.index];
    return 0.5f * glm::length(glm::cross(t.b - t.a, t.c - t.a));
}

}  // namespace

AreaLightSource::AreaLightSource(const PathEvent& event, Rgb emission, const SceneGeometry& geometry,
                                 const std::vector<std::uint32_t>& primitives)
    : Light(event), emission_(emission), geometry_(geometry) {
    for (std::uint32_t primitive : primitives) {
        const float area = shapeArea(geometry, primitive);
        if (!(area > 0.0f)) continue;  // a zero-area triangle emits nothing and cannot be sampled
        area_ += area;
        shapes_.push_back({primitive, area_});
        spheres_ = geometry.decodePrimitive(primitive).shape == ShapeKind::Sphere;
    }
}

AreaLightSource::SurfacePoint AreaLightSource::samplePoint(Vec2 u) const {
    // Reuse u.x: pick the shape, then rescale the remainder to [0, 1) for the point on it.
    const float target = u.x * area_;
    auto it = std::upper_bound(shapes_.begin(), shapes_.end(), target,
                               [](float value, const Shape& s) { return value < s.cumulativeArea; });
    if (it == shapes_.end()) --it;
    const float before = it == shapes_.begin() ? 0.0f : std::prev(it)->cumulativeArea;
    const float width = it->cumulativeArea - before;
    u.x = width > 0.0f ? std::clamp((target - before) / width, 0.0f, 0.99999994f) : 0.0f;

    const auto ref = geometry_.decodePrimitive(it->primitive);
    if (ref.shape == ShapeKind::Sphere) {
        const Sphere& sphere = geometry_.spheres()[ref.index];
        const Vec3 n = sampleUniformSphere(u);
        return {sphere.center + sphere.radius * n, n, true};
    }
    const Triangle& t = geometry_.triangles()[ref.index];
    const Vec3 b = sampleUniformTriangle(u);
    return {b.x * t.a + b.y * t.b + b.z * t.c, glm::normalize(glm::cross(t.b - t.a, t.c - t.a)), false};
}

LightSample AreaLightSource::sample(const Vec3& receiver, Vec2 u) const {
    const SurfacePoint p = samplePoint(u);
    LightSample s;
    s.point = p.point;
    s.normal = p.normal;
    const Vec3 toLight = p.point - receiver;
    const float distance2 = glm::dot(toLight, toLight);
    s.distance = std::sqrt(distance2);
    if (!(s.distance > 0.0f)) return s;
    s.wi = toLight / s.distance;
    const float cosLight = -glm::dot(p.normal, s.wi);
    if (cosLight <= 0.0f && !p.twoSided) return s;  // the receiver is behind a one-sided emitter
    s.pdf = areaToSolidAngle(1.0f / area_, receiver, p.point, p.normal);
    if (s.pdf > 0.0f) s.weight = emission_ / s.pdf;
    return s;
}

float AreaLightSource::pdf(const Vec3& receiver, const Vec3& point, const Vec3& normal) const {
    return areaToSolidAngle(1.0f / area_, receiver, point, normal);
}

EmittedRay AreaLightSource::sampleEmission(Vec2 uPoint, Vec2 uDirection) const {
    const SurfacePoint p = samplePoint(uPoint);
    EmittedRay e;
    Vec3 normal = p.normal;
    if (p.twoSided && uDirection.x < 0.5f) {
        // A sphere emits on both sides: pick one, then reuse the sample for the direction.
        normal = -normal;
        uDirection.x *= 2.0f;
    } else if (p.twoSided) {
        uDirection.x = (uDirection.x - 0.5f) * 2.0f;
    }
    const Vec3 local = sampleCosineHemisphere(uDirection);
    e.ray.origin = p.point;
    e.ray.direction = Frame(normal).toWorld(local);
    e.normal = normal;
    e.radiance = emission_;
    e.pdfPosition = 1.0f / area_;
    e.pdfDirection = cosineHemispherePdf(local.z) * (p.twoSided ? 0.5f : 1.0f);
    return e;
}

float AreaLightSource::pdfEmissionDirection(const Vec3& normal, const Vec3& direction) const {
    // sampleEmission's cosine lobe about the side's normal; a sphere picks either side by half.
    const float cosine = glm::dot(normal, direction);
    if (spheres_) return 0.5f * cosineHemispherePdf(std::fabs(cosine));
    return cosine > 0.0f ? cosineHemispherePdf(cosine) : 0.0f;
}

Rgb AreaLightSource::radiance(const SurfaceHit& hit, const Vec3& towardViewer) const {
    if (hit.shape != ShapeKind::Sphere && glm::dot(hit.normal, towardViewer) <= 0.0f) return Rgb{0.0f};
    return emission_;
}

Rgb AreaLightSource::power() const {
    // Le pi A for a one-sided Lambertian emitter; a sphere emits from both sides of its surface.
    float twoSidedArea = 0.0f;
    float before = 0.0f;
    for (const Shape& s : shapes_) {
        if (geometry_.decodePrimitive(s.primitive).shape == ShapeKind::Sphere) twoSidedArea += s.cumulativeArea - before;
        before = s.cumulativeArea;
    }
    return emission_ * (kPi * (area_ + twoSidedArea));
}

float areaToSolidAngle(float pdfArea, const Vec3& receiver, const Vec3& point, const Vec3& normal) {
    const Vec3 toPoint = point - receiver;
    const float distance2 = glm::dot(toPoint, toPoint);
    const float cosEmitter = std::fabs(glm::dot(normal, toPoint)) / std::sqrt(distance2);
    return cosEmitter > 0.0f ? pdfArea * distance2 / cosEmitter : 0.0f;
}

}  // namespace lightpath
