#include "shape_checks.h"

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "geometry/intersect.h"
#include "uniform_real.h"

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
    test::UniformReal<double> u(0.0, 1.0);
    const double z = 1.0 - 2.0 * u(rng), phi = 2.0 * kPiD * u(rng);
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    return {r * std::cos(phi), r * std::sin(phi), z};
}

// An isotropic uniform line through the ball, as a ray starting outside it.
Ray randomLine(const Ball& ball, std::mt19937& rng) {
    test::UniformReal<double> u(0.0, 1.0);
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

// Whether `point` lies on the surface: from a step above it along `normal`, a ray back finds the
// surface a step away.
bool onSurface(const ShapeRecord& shape, const Vec3& point, const Vec3& normal, float step) {
    Ray probe;
    probe.origin = point + step * normal;
    probe.direction = -normal;
    probe.tMax = 2.0f * step;
    const float back = shape.ops->intersect(probe, shape, 0.0f, NumericsOptions{});
    return back != kNoHit && std::fabs(back - step) <= 0.01f * step;
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
    test::UniformReal<double> u(0.0, 1.0);
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
        if (!onSurface(shape, hit.point, hit.normal, step))
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

CheckResult checkShapePatchGrid(const ShapeRecord& shape) {
    CheckResult result;
    const PatchGridOps* cells = shape.ops->patchGrid;
    if (!cells) return result;
    const std::string_view name = shape.ops->name;
    if (!shape.ops->bounded || !shape.ops->sampleArea)
        return result.fail(name, ": a patch grid needs a finite surface sampled by area"), result;
    const Ball ball = ballOf(shape);
    // Coarse cells, so that each receives many of the samples below.
    const PatchGrid grid = cells->cells(shape, float(ball.radius / 2.0));
    if (grid.rows == 0 || grid.columns == 0 || grid.rows * grid.columns > 400)
        return result.fail(name, ": ", grid.rows, " x ", grid.columns, " cells of about a quarter of its size"), result;
    const double area = shape.ops->area(shape);
    double cellSum = 0.0;
    std::vector<double> cellAreas;
    for (std::uint32_t row = 0; row < grid.rows; ++row)
        for (std::uint32_t column = 0; column < grid.columns; ++column)
            cellSum += cellAreas.emplace_back(cells->cellArea(shape, grid, row, column));
    if (std::fabs(cellSum - area) > 1e-4 * area)
        result.fail(name, ": the cells' areas sum to ", cellSum, ", area() is ", area);

    // Corners: numbered within [0, corners), each one used.
    std::vector<bool> used(grid.corners, false);
    for (std::uint32_t row = 0; row <= grid.rows; ++row) {
        for (std::uint32_t column = 0; column <= grid.columns; ++column) {
            const std::uint32_t corner = cells->corner(grid, row, column);
            if (corner >= grid.corners)
                result.fail(name, ": corner (", row, ", ", column, ") is numbered ", corner, " of ", grid.corners);
            else
                used[corner] = true;
        }
    }
    for (std::uint32_t c = 0; c < grid.corners; ++c)
        if (!used[c]) result.fail(name, ": corner number ", c, " of ", grid.corners, " belongs to no cell");

    // Each cell's centre and samples locate to that cell and lie on the surface.
    std::mt19937 rng(17);
    test::UniformReal<double> u(0.0, 1.0);
    const float step = float(1e-3 * ball.radius);
    for (std::uint32_t row = 0; row < grid.rows; ++row) {
        for (std::uint32_t column = 0; column < grid.columns; ++column) {
            for (int k = 0; k < 8; ++k) {
                const Vec2 uv = k == 0 ? Vec2{0.5f} : Vec2{float(0.05 + 0.9 * u(rng)), float(0.05 + 0.9 * u(rng))};
                const AreaSample s = cells->sampleCell(shape, grid, row, column, uv);
                const GridPoint at = cells->locate(shape, grid, s.point);
                if (at.row != row || at.column != column)
                    result.fail(name, ": a point of cell (", row, ", ", column, ") at u = ", uv.x, " ", uv.y,
                                " locates to cell (", at.row, ", ", at.column, ")");
                if (std::fabs(glm::length(s.normal) - 1.0f) > 1e-5f) result.fail(name, ": a cell sample's normal is not unit");
                else if (!onSurface(shape, s.point, s.normal, step))
                    result.fail(name, ": a sample of cell (", row, ", ", column, ") is not on the surface");
            }
        }
    }

    // Uniform samples of the whole surface fall into each cell in proportion to its area: the
    // cells cover the surface, and locate() and cellArea() agree with each other.
    constexpr int kSamples = 100000;
    std::vector<int> counts(cellAreas.size(), 0);
    for (int i = 0; i < kSamples; ++i) {
        const AreaSample s = shape.ops->sampleArea(shape, Vec2{float(u(rng)), float(u(rng))});
        const GridPoint at = cells->locate(shape, grid, s.point);
        if (at.row >= grid.rows || at.column >= grid.columns || !(at.fraction.x >= 0.0f && at.fraction.x <= 1.0f) ||
            !(at.fraction.y >= 0.0f && at.fraction.y <= 1.0f)) {
            result.fail(name, ": a point of the surface locates outside the grid (", at.row, ", ", at.column, ")");
            continue;
        }
        ++counts[at.row * grid.columns + at.column];
    }
    for (std::size_t c = 0; c < counts.size(); ++c) {
        const double p = cellAreas[c] / area, expected = p * kSamples;
        const double sigma = std::sqrt(kSamples * p * (1.0 - p));
        if (std::fabs(counts[c] - expected) > kSigmas * sigma + 1.0)
            result.fail(name, ": cell (", c / grid.columns, ", ", c % grid.columns, ") holds ", counts[c],
                        " of ", kSamples, " uniform samples; its area says ", expected, " +- ", sigma);
    }
    return result;
}

CheckResult checkShapeRegionTessellation(const ShapeRecord& shape) {
    CheckResult result;
    if (!shape.ops->tessellateRegion) return result;
    const std::string_view name = shape.ops->name;
    // A region around the origin, where the cases draw their points.
    constexpr float kHalf = 10.0f;
    Bounds region;
    region.grow(Vec3{-kHalf, -0.5f * kHalf, -0.25f * kHalf});
    region.grow(Vec3{kHalf, 0.5f * kHalf, 0.25f * kHalf});
    std::vector<Triangle> triangles;
    shape.ops->tessellateRegion(shape, region, triangles);
    if (triangles.empty()) return result.fail(name, ": no triangles over the region"), result;
    const float step = 1e-3f * kHalf;
    for (const Triangle& t : triangles) {
        const Vec3 normal = glm::normalize(glm::cross(t.b - t.a, t.c - t.a));
        const Vec3 centroid = (t.a + t.b + t.c) / 3.0f;
        if (!onSurface(shape, centroid, normal, step) && !onSurface(shape, centroid, -normal, step)) {
            result.fail(name, ": a triangle of its region's tessellation is not on the surface");
            continue;
        }
        SurfaceHit hit;
        hit.point = centroid;
        shape.ops->describe(shape, hit);
        if (!(glm::dot(hit.normal, normal) > 0.99f)) result.fail(name, ": a triangle of its region is wound against its normal");
    }
    // Lines through the region: every hit inside it lies on a triangle.
    const Ball ball{glm::dvec3(0.0), double(glm::length(region.hi))};
    std::mt19937 rng(19);
    int inside = 0;
    for (int i = 0; i < 20000; ++i) {
        const Ray ray = randomLine(ball, rng);
        const float t = shape.ops->intersect(ray, shape, 0.0f, NumericsOptions{});
        if (t == kNoHit) continue;
        const Vec3 p = ray.at(t);
        if (glm::any(glm::lessThan(p, region.lo)) || glm::any(glm::greaterThan(p, region.hi))) continue;
        ++inside;
        bool covered = false;
        for (const Triangle& tri : triangles) {
            // Barycentric coordinates by least squares; on it within a little slack.
            const glm::dvec3 e1(tri.b - tri.a), e2(tri.c - tri.a), d(p - tri.a);
            const double d00 = glm::dot(e1, e1), d01 = glm::dot(e1, e2), d11 = glm::dot(e2, e2);
            const double det = d00 * d11 - d01 * d01;
            if (!(det > 0.0)) continue;
            const double s = (d11 * glm::dot(d, e1) - d01 * glm::dot(d, e2)) / det;
            const double r = (d00 * glm::dot(d, e2) - d01 * glm::dot(d, e1)) / det;
            if (s >= -1e-6 && r >= -1e-6 && s + r <= 1.0 + 1e-6) {
                covered = true;
                break;
            }
        }
        if (!covered) result.fail(name, ": the hit ", p.x, " ", p.y, " ", p.z, " inside the region lies on no triangle");
    }
    if (inside == 0) result.fail(name, ": no line hits it inside the region");
    return result;
}

CheckResult checkShapeDepthAlong(const ShapeRecord& shape) {
    CheckResult result;
    if (!shape.ops->depthAlong) return result;
    const std::string_view name = shape.ops->name;
    const Ball ball = ballOf(shape);
    std::mt19937 rng(23);
    test::UniformReal<double> u(0.0, 1.0);
    int hits = 0;
    for (int i = 0; i < 20000; ++i) {
        const Ray ray = randomLine(ball, rng);
        // An eye anywhere along the line, looking along it by a direction of any length.
        Ray eyeRay = ray;
        eyeRay.origin = ray.at(float(u(rng) * 4.0 * ball.radius));
        eyeRay.tMax = std::numeric_limits<float>::infinity();
        const Vec3 direction = ray.direction * float(0.1 + 10.0 * u(rng));
        const float s = shape.ops->depthAlong(shape, eyeRay.origin, direction);
        const bool depth = s > 0.0f && std::isfinite(s);
        const float t = shape.ops->intersect(eyeRay, shape, 0.0f, NumericsOptions{});
        if (t == kNoHit) {
            if (depth) result.fail(name, ": depthAlong gives ", s, " where intersect finds no hit");
            continue;
        }
        SurfaceHit hit;
        hit.point = eyeRay.at(t);
        shape.ops->describe(shape, hit);
        const float cosine = std::fabs(glm::dot(hit.normal, eyeRay.direction));
        if (cosine < 0.05f) continue;  // grazing: t's rounding / cos
        ++hits;
        // A closed form in float may round the eye's and the point's coordinates (a plane's
        // n.(p - eye)): a few float spacings of them, over the cosine, besides 1e-4 relative.
        const float rounding = 8.0f * std::numeric_limits<float>::epsilon() *
                               (glm::length(eyeRay.origin) + glm::length(hit.point)) / cosine;
        const float along = s * glm::length(direction);
        if (!depth || std::fabs(along - t) > 1e-4f * t + rounding)
            result.fail(name, ": depthAlong says ", along, " along the unit ray where intersect finds ", t);
    }
    if (hits == 0) result.fail(name, ": no line hits it");
    return result;
}

}  // namespace lightpath::conformance
