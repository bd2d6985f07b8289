#include "lights/area_light.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "geometry/intersect.h"
#include "sampling/warp.h"

namespace lightpath {
namespace {

constexpr double kTwoPi = 2.0 * 3.14159265358979323846;
// How many float spacings (of the centre's largest coordinate plus the radius) from a sphere's
// surface a receiver still counts as on it: hit points land within a few of the true surface.
constexpr double kOnSphereUlps = 8.0;

float shapeArea(const SceneGeometry& geometry, std::uint32_t primitive) {
    const auto ref = geometry.decodePrimitive(primitive);
    if (ref.shape == ShapeKind::Sphere) return static_cast<float>(surfaceArea(geometry.spheres()[ref.index]));
    if (const ShapeRecord* shape = geometry.registeredShape(primitive))
        return static_cast<float>(shape->ops->area(*shape));
    const Triangle& t = geometry.triangles()[ref.index];
    // In float while its squared cross product is a normal float (as every shipped mesh's is, so
    // their areas, and images, stay bit-identical), else in double: a sliver's area is small, not 0.
    const Vec3 cross = glm::cross(t.b - t.a, t.c - t.a);
    const float length2 = glm::dot(cross, cross);
    if (length2 >= std::numeric_limits<float>::min()) return 0.5f * std::sqrt(length2);
    return static_cast<float>(surfaceArea(t));
}

// Emits from both sides of its surface: a sphere, or a registered kind that encloses a volume.
bool emitsTwoSided(const SceneGeometry& geometry, std::uint32_t primitive) {
    if (geometry.decodePrimitive(primitive).shape == ShapeKind::Sphere) return true;
    const ShapeRecord* shape = geometry.registeredShape(primitive);
    return shape != nullptr && shape->ops->closed;
}

}  // namespace

AreaLightSource::AreaLightSource(const PathEvent& event, Rgb emission, const SceneGeometry& geometry,
                                 const std::vector<std::uint32_t>& primitives)
    : Light(event), emission_(emission), geometry_(geometry) {
    std::size_t twoSidedCount = 0;
    for (std::uint32_t primitive : primitives) {
        const float area = shapeArea(geometry, primitive);
        if (!(area > 0.0f)) continue;  // a zero-area triangle emits nothing and cannot be sampled
        area_ += area;
        shapes_.push_back({primitive, area_});
        twoSidedCount += emitsTwoSided(geometry, primitive);
    }
    if (twoSidedCount != 0 && twoSidedCount != shapes_.size())
        throw std::invalid_argument("an area light is closed shapes (spheres) or open ones (triangles), not both");
    spheres_ = twoSidedCount != 0;
    const bool oneSphere =
        shapes_.size() == 1 && geometry.decodePrimitive(shapes_[0].primitive).shape == ShapeKind::Sphere;
    if (oneSphere) sphere_ = geometry.spheres()[geometry.decodePrimitive(shapes_[0].primitive).index];
    sampleable_ = area_ >= kMinSampledEmitterArea;
}

std::optional<SphereCone> sphereCone(const Sphere& sphere, const Vec3& receiver) {
    const glm::dvec3 toReceiver = glm::dvec3(receiver) - glm::dvec3(sphere.center);
    const double d2 = glm::dot(toReceiver, toReceiver);
    const double r = sphere.radius;
    const double d = std::sqrt(d2);
    // A receiver within the rounding of a hit point of the surface is on it: a hit on the sphere
    // light itself, which sees the light only through its inside (from outside, none of it).
    const Vec3 c = glm::abs(sphere.center);
    const double magnitude = double(std::max({c.x, c.y, c.z})) + r;
    if (!(d - r > kOnSphereUlps * double(std::numeric_limits<float>::epsilon()) * magnitude)) return std::nullopt;
    SphereCone cone;
    cone.axis = Vec3(toReceiver / d);
    cone.sin2ThetaMax = (r / d) * (r / d);
    // cos^2 = (d - r)(d + r) / d^2, without the cancellation of 1 - sin^2 near the surface.
    const double cosThetaMax = std::sqrt(std::max(0.0, (d - r) * (d + r))) / d;
    cone.oneMinusCosThetaMax = cone.sin2ThetaMax / (1.0 + cosThetaMax);
    const double pdf = 1.0 / (kTwoPi * cone.oneMinusCosThetaMax);
    cone.pdf = pdf <= double(std::numeric_limits<float>::max()) ? static_cast<float>(pdf) : 0.0f;
    return cone;
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
        return {sphere.center + sphere.radius * n, n};
    }
    if (const ShapeRecord* shape = geometry_.registeredShape(it->primitive)) {
        const AreaSample p = shape->ops->sampleArea(*shape, u);
        return {p.point, p.normal};
    }
    const Triangle& t = geometry_.triangles()[ref.index];
    const Vec3 b = sampleUniformTriangle(u);
    return {b.x * t.a + b.y * t.b + b.z * t.c, triangleNormal(t)};
}

LightSample AreaLightSource::sample(const Vec3& receiver, Vec2 u) const {
    LightSample s;
    if (!sampleable_) return s;
    const std::optional<SphereCone> cone = sphere_ ? sphereCone(*sphere_, receiver) : std::nullopt;
    if (cone) {
        // Uniform in the cone (pbrt-v4 6.2.4), then the point on the sphere the direction meets
        // first: alpha, its angle at the centre from the axis, by the law of sines.
        if (!(cone->pdf > 0.0f)) return s;
        const double oneMinusCos = double(u.x) * cone->oneMinusCosThetaMax;
        const double cosTheta = 1.0 - oneMinusCos;
        const double sin2Theta = oneMinusCos * (2.0 - oneMinusCos);
        const double ratio = std::min(1.0, sin2Theta / cone->sin2ThetaMax);
        const double cosAlpha =
            std::clamp(sin2Theta / std::sqrt(cone->sin2ThetaMax) + cosTheta * std::sqrt(1.0 - ratio), -1.0, 1.0);
        const double sinAlpha = std::sqrt(std::max(0.0, 1.0 - cosAlpha * cosAlpha));
        const double phi = kTwoPi * double(u.y);
        const Frame frame(cone->axis);
        s.normal = glm::normalize(frame.toWorld(Vec3(float(sinAlpha * std::cos(phi)), float(sinAlpha * std::sin(phi)),
                                                     float(cosAlpha))));
        s.point = sphere_->center + sphere_->radius * s.normal;
        s.pdf = cone->pdf;
    } else {
        const SurfacePoint p = samplePoint(u);
        s.point = p.point;
        s.normal = p.normal;
        s.pdf = areaToSolidAngle(1.0f / area_, receiver, p.point, p.normal);
    }
    const Vec3 toLight = s.point - receiver;
    s.distance = std::sqrt(glm::dot(toLight, toLight));
    if (!(s.distance > 0.0f)) {
        s.pdf = 0.0f;
        return s;
    }
    s.wi = toLight / s.distance;
    // The receiver behind a one-sided emitter sees nothing of it (spheres emit on both sides).
    if (!spheres_ && -glm::dot(s.normal, s.wi) <= 0.0f) s.pdf = 0.0f;
    if (s.pdf > 0.0f) s.weight = emission_ / s.pdf;
    return s;
}

float AreaLightSource::pdf(const Vec3& receiver, const Vec3& point, const Vec3& normal) const {
    if (!sampleable_) return 0.0f;
    if (sphere_) {
        if (const auto cone = sphereCone(*sphere_, receiver)) return cone->pdf;
    }
    return areaToSolidAngle(1.0f / area_, receiver, point, normal);
}

bool AreaLightSource::samplesByArea(const Vec3& receiver) const {
    return !sphere_ || !sphereCone(*sphere_, receiver);
}

EmittedRay AreaLightSource::sampleEmission(Vec2 uPoint, Vec2 uDirection) const {
    const SurfacePoint p = samplePoint(uPoint);
    EmittedRay e;
    Vec3 normal = p.normal;
    if (spheres_ && uDirection.x < 0.5f) {
        // A sphere emits on both sides: pick one, then reuse the sample for the direction.
        normal = -normal;
        uDirection.x *= 2.0f;
    } else if (spheres_) {
        uDirection.x = (uDirection.x - 0.5f) * 2.0f;
    }
    const Vec3 local = sampleCosineHemisphere(uDirection);
    e.ray.origin = p.point;
    e.ray.direction = Frame(normal).toWorld(local);
    e.normal = normal;
    e.radiance = emission_;
    e.pdfPosition = 1.0f / area_;
    e.pdfDirection = cosineHemispherePdf(local.z) * (spheres_ ? 0.5f : 1.0f);
    return e;
}

float AreaLightSource::pdfEmissionDirection(const Vec3& normal, const Vec3& direction) const {
    // sampleEmission's cosine lobe about the side's normal; a sphere picks either side by half.
    const float cosine = glm::dot(normal, direction);
    if (spheres_) return 0.5f * cosineHemispherePdf(std::fabs(cosine));
    return cosine > 0.0f ? cosineHemispherePdf(cosine) : 0.0f;
}

Rgb AreaLightSource::radiance(const SurfaceHit& hit, const Vec3& towardViewer) const {
    if (!spheres_ && glm::dot(hit.normal, towardViewer) <= 0.0f) return Rgb{0.0f};
    return emission_;
}

Rgb AreaLightSource::power() const {
    // Le pi A for a one-sided Lambertian emitter; a sphere emits from both sides of its surface.
    return emission_ * (kPi * area_ * (spheres_ ? 2.0f : 1.0f));
}

float areaToSolidAngle(float pdfArea, const Vec3& receiver, const Vec3& point, const Vec3& normal) {
    const Vec3 toPoint = point - receiver;
    const float distance2 = glm::dot(toPoint, toPoint);
    const float cosEmitter = std::fabs(glm::dot(normal, toPoint)) / std::sqrt(distance2);
    const float pdf = cosEmitter > 0.0f ? pdfArea * distance2 / cosEmitter : 0.0f;
    return std::isfinite(pdf) ? pdf : 0.0f;
}

}  // namespace lightpath
