#include "shape_checks.h"

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "geometry/intersect.h"

namespace lightpath::conformance {
namespace {

constexpr double kPiD = 3.14159265358979323846;
constexpr int kLines = 200000;
constexpr double kSigmas = 5.0;

// The ball the lines are drawn through: the bounds' circumscribed sphere.
struct Ball {
    glm::dvec3 center;
    double radius;
};

// An unbounded kind's (a plane's) lines go through a ball at the origin much larger than the range
// the cases draw its points from, so most cross it.
constexpr double kUnboundedBall = 100.0;

Ball ballOf(const ShapeRecord& shape) {
    if (!shape.ops->bounded) return {glm::dvec3(0.0), kUnboundedBall};
    const Bounds b = shape.ops->bounds(shape);
    const glm::dvec3 lo(b.lo), hi(b.hi);
    return {0.5 * (lo + hi), 0.5 * glm::length(hi - lo) * 1.01 + 1e-6};
}

glm::dvec3 uniformDirection(std::mt19937& rng) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const double z = 1.0 - 2.0 * u(rng), phi = 2.0 * kPiD * u(rng);
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    return {r * std::cos(phi), r * std::sin(phi), z};
}

// An isotropic uniform line through the ball, as a ray starting outside it.
Ray randomLine(const Ball& ball, std::mt19937& rng) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const glm::dvec3 d = uniformDirection(rng);
    const glm::dvec3 a = glm::normalize(glm::cross(d, std::fabs(d.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0)));
    const glm::dvec3 b = glm::cross(d, a);
    const double r = ball.radius * std::sqrt(u(rng)), phi = 2.0 * kPiD * u(rng);
    Ray ray;
    ray.origin = Vec3(ball.center + r * (std::cos(phi) * a + std::sin(phi) * b) - 2.0 * ball.radius * d);
    ray.direction = Vec3(d);
    ray.tMax = float(4.0 * ball.radius);
    return ray;
}

// Every crossing of the line with the shape, in order (intersect again past each hit).
template <typename Visit>
int crossings(const ShapeRecord& shape, const Ray& ray, Visit visit) {
    int count = 0;
    float tMin = 0.0f;
    for (int guard = 0; guard < 64; ++guard) {
        const float t = shape.ops->intersect(ray, shape, tMin, NumericsOptions{});
        if (t == kNoHit) break;
        ++count;
        visit(t);
        tMin = std::nextafter(t, std::numeric_limits<float>::infinity()) + 1e-6f * float(std::fabs(t));
    }
    return count;
}

// Within `sigmas` standard errors of the mean: |mean - expected| <= sigmas sqrt(var / n).
bool agrees(double sum, double sumSquares, int n, double expected, double& mean, double& error) {
    mean = sum / n;
    const double variance = std::max(0.0, sumSquares / n - mean * mean);
    error = std::sqrt(variance / n);
    return std::fabs(mean - expected) <= kSigmas * error + 1e-12;
}

}  // namespace

// An unbounded kind has infinite area and a box holding all space: Cauchy-Crofton, area sampling
// and tessellation have nothing finite to check, so the checks below ask exactly that of it.
bool checkedAsUnbounded(const ShapeRecord& shape, CheckResult& result) {
    if (shape.ops->bounded) return false;
    const double area = shape.ops->area(shape);
    if (!(std::isinf(area) && area > 0.0)) result.fail(shape.ops->name, ": unbounded, but area() = ", area, ", not infinite");
    const Bounds b = shape.ops->bounds(shape);
    if (!glm::all(glm::isinf(b.lo)) || !glm::all(glm::isinf(b.hi)) || b.lo.x > 0.0f || b.hi.x < 0.0f)
        result.fail(shape.ops->name, ": unbounded, but bounds() is not all of space");
    return true;
}

CheckResult checkShapeCrossings(const ShapeRecord& shape) {
    CheckResult result;
    if (checkedAsUnbounded(shape, result)) return result;
    const Ball ball = ballOf(shape);
    const double area = shape.ops->area(shape);
    const double expected = area / (2.0 * kPiD * ball.radius * ball.radius);
    Bounds box = shape.ops->bounds(shape);
    const Vec3 slack = 1e-4f * (box.hi - box.lo) + 1e-5f;
    std::mt19937 rng(7);
    double sum = 0.0, sumSquares = 0.0;
    for (int i = 0; i < kLines; ++i) {
        const Ray ray = randomLine(ball, rng);
        const int n = crossings(shape, ray, [&](float t) {
            const Vec3 p = ray.at(t);
            if (glm::any(glm::lessThan(p, box.lo - slack)) || glm::any(glm::greaterThan(p, box.hi + slack)))
                result.fail(shape.ops->name, ": a hit at ", p.x, " ", p.y, " ", p.z, " lies outside bounds()");
        });
        sum += n;
        sumSquares += double(n) * n;
    }
    double mean = 0.0, error = 0.0;
    if (!agrees(sum, sumSquares, kLines, expected, mean, error)) {
        result.fail(shape.ops->name, ": lines cross it ", mean, " times on average (+- ", error, "); area() = ", area,
                    " says ", expected, " (Cauchy-Crofton: A / (2 pi R^2), R = ", ball.radius, ")");
    }
    return result;
}

CheckResult checkShapeSampling(const ShapeRecord& shape) {
    CheckResult result;
    if (checkedAsUnbounded(shape, result)) return result;
    const Ball ball = ballOf(shape);
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    constexpr int kSamples = 100000, kHalfSpaces = 4;
    std::vector<AreaSample> samples;
    for (int i = 0; i < kSamples; ++i) samples.push_back(shape.ops->sampleArea(shape, Vec2{float(u(rng)), float(u(rng))}));
    for (int h = 0; h < kHalfSpaces; ++h) {
        // A plane through a random point of the inner half of the ball, facing a random way.
        const glm::dvec3 normal = uniformDirection(rng);
        const double offset = glm::dot(ball.center, normal) + (u(rng) - 0.5) * ball.radius;
        const auto inside = [&](const Vec3& p) { return glm::dot(glm::dvec3(p), normal) < offset; };
        double inSamples = 0.0;
        for (const AreaSample& s : samples) inSamples += inside(s.point);
        double sum = 0.0, all = 0.0;
        for (int i = 0; i < kLines / 2; ++i) {
            const Ray ray = randomLine(ball, rng);
            int in = 0;
            all += crossings(shape, ray, [&](float t) { in += inside(ray.at(t)); });
            sum += in;
        }
        if (all == 0.0) return result.fail(shape.ops->name, ": no line crosses it"), result;
        // The share of crossings in the half-space estimates its share of the area; compare.
        const double share = sum / all, sampleShare = inSamples / kSamples;
        const double error = std::sqrt(share * (1.0 - share) / all) * 2.0 + std::sqrt(sampleShare * (1.0 - sampleShare) / kSamples);
        if (std::fabs(share - sampleShare) > kSigmas * error + 1e-3)
            result.fail(shape.ops->name, ": ", sampleShare, " of area samples lie in a half-space holding ", share,
                        " of its surface (+- ", error, "): sampleArea() is not uniform by area");
    }
    // Each sample lies on the surface: a ray from outside the ball aimed at it meets the surface there.
    for (int i = 0; i < 1000; ++i) {
        const AreaSample& s = samples[i];
        if (std::fabs(glm::length(s.normal) - 1.0f) > 1e-5f) result.fail(shape.ops->name, ": a sample's normal is not unit");
        // From outside the ball, at least 0.1 off the tangent plane (a grazing ray's t carries the
        // sample's rounding divided by the cosine).
        glm::dvec3 away = uniformDirection(rng);
        while (std::fabs(glm::dot(away, glm::dvec3(s.normal))) < 0.1) away = uniformDirection(rng);
        const glm::dvec3 from = glm::dvec3(s.point) + 3.0 * ball.radius * away;
        const double distance = glm::length(glm::dvec3(s.point) - from);
        Ray ray;
        ray.origin = Vec3(from);
        ray.direction = Vec3((glm::dvec3(s.point) - from) / distance);
        ray.tMax = float(distance * (1.0 + 1e-4));
        bool there = false;
        crossings(shape, ray, [&](float t) { there = there || t >= float(distance * (1.0 - 1e-4)); });
        if (!there) result.fail(shape.ops->name, ": a ray aimed at the sample ", s.point.x, " ", s.point.y, " ", s.point.z,
                                " finds no surface there");
    }
    return result;
}

CheckResult checkShapeHits(const ShapeRecord& shape) {
    CheckResult result;
    const Ball ball = ballOf(shape);
    const float step = float(1e-3 * ball.radius);
    std::mt19937 rng(13);
    int hits = 0;
    for (int i = 0; i < 20000 && hits < 2000; ++i) {
        const Ray ray = randomLine(ball, rng);
        const float t = shape.ops->intersect(ray, shape, 0.0f, NumericsOptions{});
        if (t == kNoHit) continue;
        ++hits;
        SurfaceHit hit;
        hit.t = t;
        hit.point = ray.at(t);
        shape.ops->describe(shape, hit);
        if (std::fabs(glm::length(hit.normal) - 1.0f) > 1e-5f || std::fabs(glm::length(hit.shadingNormal) - 1.0f) > 1e-5f)
            result.fail(shape.ops->name, ": a hit's normal is not unit");
        // Back along the normal from a step above the point: the surface is a step away.
        Ray probe;
        probe.origin = hit.point + step * hit.normal;
        probe.direction = -hit.normal;
        probe.tMax = 2.0f * step;
        const float back = shape.ops->intersect(probe, shape, 0.0f, NumericsOptions{});
        if (back == kNoHit || std::fabs(back - step) > 0.01f * step)
            result.fail(shape.ops->name, ": the hit ", hit.point.x, " ", hit.point.y, " ", hit.point.z,
                        " is not on the surface along its normal");
    }
    if (hits == 0) result.fail(shape.ops->name, ": no line hits it");
    return result;
}

CheckResult checkShapeTessellation(const ShapeRecord& shape) {
    CheckResult result;
    if (checkedAsUnbounded(shape, result)) return result;
    const double area = shape.ops->area(shape);
    const double size = 2.0 * ballOf(shape).radius;
    const auto tessellatedArea = [&](double edge) {
        std::vector<Triangle> triangles;
        shape.ops->tessellate(shape, float(edge), triangles);
        double sum = 0.0;
        for (const Triangle& t : triangles) sum += surfaceArea(t);
        return sum;
    };
    const double coarse = std::fabs(tessellatedArea(size / 4.0) - area), fine = std::fabs(tessellatedArea(size / 400.0) - area);
    if (!(fine <= 0.01 * area))
        result.fail(shape.ops->name, ": tessellated at edges of ", size / 400.0, " its area is off by ", fine, " of ", area);
    if (!(fine <= coarse))
        result.fail(shape.ops->name, ": a finer tessellation is further from the area (", fine, " against ", coarse, ")");
    return result;
}

}  // namespace lightpath::conformance
