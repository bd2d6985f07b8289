// `[[spheres]]`: a sphere, declared, read and registered here like every shape kind
// (docs/extending.md): its geometry as a ShapeOps table (geometry/shape.h) with the robust/naive
// intersection variants (geometry/intersect.h) and sampling by visible cone for area lights.
#include "shapes/sphere.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "geometry/intersect.h"
#include "sampling/warp.h"
#include "scene/shape_type.h"

namespace lightpath {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
// How many float spacings (of the centre's largest coordinate plus the radius) from a sphere's
// surface a receiver still counts as on it: hit points land within a few of the true surface.
constexpr double kOnSphereUlps = 8.0;

Sphere sphereOf(const ShapeRecord& r) {
    Sphere sphere;
    sphere.center = {r.data[0], r.data[1], r.data[2]};
    sphere.radius = r.data[3];
    sphere.object = r.object;
    return sphere;
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

namespace {

Bounds sphereBounds(const ShapeRecord& record) {
    const Sphere s = sphereOf(record);
    return {s.center - Vec3(s.radius), s.center + Vec3(s.radius)};
}

float intersectSphereRecord(const Ray& ray, const ShapeRecord& record, float tMin, const NumericsOptions& numerics) {
    const Sphere s = sphereOf(record);
    return numerics.sphere == SphereTest::Stable ? intersectSphere(ray, s, tMin) : intersectSphereNaive(ray, s, tMin);
}

void describeSphere(const ShapeRecord& record, SurfaceHit& hit) {
    const Sphere s = sphereOf(record);
    hit.normal = sphereNormal(s, hit.point);
    // Snap the point back onto the sphere: ray.at(t) carries the rounding of t.
    hit.point = s.center + hit.normal * s.radius;
    hit.shadingNormal = hit.normal;
}

// Longitude and latitude about the y axis (pbrt-v4 6.2 with y up): u = phi / 2 pi, phi from +x
// towards +z, v = theta / pi from the +y pole.
SurfaceParameters parametriseSphere(const ShapeRecord& record, const Vec3& point) {
    const Sphere s = sphereOf(record);
    const Vec3 d = (point - s.center) / s.radius;
    float phi = std::atan2(d.z, d.x);
    if (phi < 0.0f) phi += 2.0f * kPi;
    const float theta = std::acos(std::clamp(d.y, -1.0f, 1.0f));
    const float sinTheta = std::sin(theta), cosTheta = std::cos(theta);
    const float sinPhi = std::sin(phi), cosPhi = std::cos(phi);
    SurfaceParameters p;
    p.uv = {phi / (2.0f * kPi), theta / kPi};
    p.dpdu = 2.0f * kPi * s.radius * Vec3(-sinTheta * sinPhi, 0.0f, sinTheta * cosPhi);
    p.dpdv = kPi * s.radius * Vec3(cosTheta * cosPhi, -sinTheta, cosTheta * sinPhi);
    return p;
}

double sphereArea(const ShapeRecord& record) { return surfaceArea(sphereOf(record)); }

AreaSample sampleSphere(const ShapeRecord& record, Vec2 u) {
    const Sphere s = sphereOf(record);
    const Vec3 n = sampleUniformSphere(u);
    return {s.center + s.radius * n, n};
}

void tessellateSphere(const ShapeRecord& record, float edgeLength, std::vector<Triangle>& out) {
    // Latitude-longitude quads (two triangles each, wound outward), edges about edgeLength long.
    constexpr float kMinSectors = 8.0f, kMaxSectors = 4096.0f;
    const Sphere s = sphereOf(record);
    const float wanted = std::ceil(2.0f * kPi * s.radius / edgeLength);
    const auto sectors = static_cast<std::uint32_t>(
        std::clamp(std::isfinite(wanted) ? wanted : kMaxSectors, kMinSectors, kMaxSectors));
    const std::uint32_t bands = std::max<std::uint32_t>(2, sectors / 2);
    const auto at = [&](std::uint32_t band, std::uint32_t sector) {
        const double theta = std::numbers::pi * double(band) / double(bands);
        const double phi = kTwoPi * double(sector % sectors) / double(sectors);
        const Vec3 n(float(std::sin(theta) * std::cos(phi)), float(std::sin(theta) * std::sin(phi)),
                     float(std::cos(theta)));
        return s.center + s.radius * n;
    };
    for (std::uint32_t band = 0; band < bands; ++band) {
        for (std::uint32_t sector = 0; sector < sectors; ++sector) {
            const Vec3 p00 = at(band, sector), p01 = at(band, sector + 1);
            const Vec3 p10 = at(band + 1, sector), p11 = at(band + 1, sector + 1);
            if (band != 0) out.push_back({p00, p10, p01, s.object});
            if (band + 1 != bands) out.push_back({p01, p10, p11, s.object});
        }
    }
}

// Radiosity's cells (Cohen and Wallace 1993, ch. 8): `rows` bands of equal height, so of equal
// area (Archimedes), each of `columns` sectors, about one patch size wide at the equator. Cell
// (ring, sector) spans z = cos(theta) from 1 - 2 ring/rows down to 1 - 2 (ring+1)/rows and phi
// from 2 pi sector/columns to 2 pi (sector+1)/columns, in the frame of the world's axes.
constexpr double kMaxCellsAcross = 1 << 15;  // bounds the counts at a tiny patch size
// At least this many bands and sectors, whatever the patch size (issue 27): a sphere about as wide
// as the patch size got 2 bands, so its lit and unlit halves shared cells (the lecture room's matte
// ball, 2 x 6 cells at the default budget: 0.63 of the path tracer's direct light on its visible
// side, 1.3 times its fourth bounce). Above the floor the count is still ceil(2 r / size) bands by
// ceil(2 pi r / size) sectors, so it falls with the size as before.
constexpr double kMinBands = 12.0, kMinSectors = 24.0;

PatchGrid sphereCells(const ShapeRecord& record, float patchSize) {
    const float radius = sphereOf(record).radius;
    const double bands = std::clamp(std::ceil(2.0 * radius / patchSize), kMinBands, kMaxCellsAcross);
    const double sectors = std::clamp(std::ceil(2.0 * kPi * radius / patchSize), kMinSectors, kMaxCellsAcross);
    const auto rows = static_cast<std::uint32_t>(bands), columns = static_cast<std::uint32_t>(sectors);
    return {rows, columns, 2 + (rows - 1) * columns};
}

// Corners: the two poles, then rings 1 .. rows-1 of `columns` each (phi wraps around).
std::uint32_t sphereCorner(const PatchGrid& grid, std::uint32_t ring, std::uint32_t sector) {
    if (ring == 0) return 0;
    if (ring == grid.rows) return 1;
    return 2 + (ring - 1) * grid.columns + sector % grid.columns;
}

float sphereCellArea(const ShapeRecord& record, const PatchGrid& grid, std::uint32_t, std::uint32_t) {
    const float radius = sphereOf(record).radius;
    return 4.0f * kPi * radius * radius / float(grid.rows * grid.columns);
}

AreaSample sampleSphereCell(const ShapeRecord& record, const PatchGrid& grid, std::uint32_t ring,
                            std::uint32_t sector, Vec2 u) {
    // Uniform in z and phi is uniform by area on the sphere.
    const Sphere sphere = sphereOf(record);
    const float z0 = 1.0f - 2.0f * float(ring) / float(grid.rows);
    const float z1 = 1.0f - 2.0f * float(ring + 1) / float(grid.rows);
    const float phi0 = 2.0f * kPi * float(sector) / float(grid.columns);
    const float phi1 = 2.0f * kPi * float(sector + 1) / float(grid.columns);
    const float z = z0 + (z1 - z0) * u.x;
    const float phi = phi0 + (phi1 - phi0) * u.y;
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    const Vec3 n{r * std::cos(phi), r * std::sin(phi), z};
    return {sphere.center + sphere.radius * n, n};
}

GridPoint locateOnSphere(const ShapeRecord& record, const PatchGrid& grid, const Vec3& point) {
    const Sphere sphere = sphereOf(record);
    const Vec3 n = (point - sphere.center) / sphere.radius;
    const float z = std::clamp(n.z, -1.0f, 1.0f);
    float phi = std::atan2(n.y, n.x);
    if (phi < 0.0f) phi += 2.0f * kPi;
    const float gz = (1.0f - z) * 0.5f * float(grid.rows);
    const float gp = phi / (2.0f * kPi) * float(grid.columns);
    const auto ring = std::min(static_cast<std::uint32_t>(std::max(gz, 0.0f)), grid.rows - 1);
    const auto sector = std::min(static_cast<std::uint32_t>(std::max(gp, 0.0f)), grid.columns - 1);
    return {ring, sector, {std::clamp(gz - float(ring), 0.0f, 1.0f), std::clamp(gp - float(sector), 0.0f, 1.0f)}};
}

constexpr PatchGridOps kSphereCells{sphereCells, sphereCorner, sphereCellArea, sampleSphereCell, locateOnSphere};

bool sampleSphereSolidAngle(const ShapeRecord& record, const Vec3& receiver, Vec2 u, SolidAngleSample& out) {
    const Sphere sphere = sphereOf(record);
    const std::optional<SphereCone> cone = sphereCone(sphere, receiver);
    if (!cone) return false;
    out = {};
    if (!(cone->pdf > 0.0f)) return true;
    // Uniform in the cone (pbrt-v4 6.2.4), then the point on the sphere the direction meets
    // first: alpha, its angle at the centre from the axis, by the law of sines.
    const double oneMinusCos = double(u.x) * cone->oneMinusCosThetaMax;
    const double cosTheta = 1.0 - oneMinusCos;
    const double sin2Theta = oneMinusCos * (2.0 - oneMinusCos);
    const double ratio = std::min(1.0, sin2Theta / cone->sin2ThetaMax);
    const double cosAlpha =
        std::clamp(sin2Theta / std::sqrt(cone->sin2ThetaMax) + cosTheta * std::sqrt(1.0 - ratio), -1.0, 1.0);
    const double sinAlpha = std::sqrt(std::max(0.0, 1.0 - cosAlpha * cosAlpha));
    const double phi = kTwoPi * double(u.y);
    const Frame frame(cone->axis);
    out.normal = glm::normalize(
        frame.toWorld(Vec3(float(sinAlpha * std::cos(phi)), float(sinAlpha * std::sin(phi)), float(cosAlpha))));
    out.point = sphere.center + sphere.radius * out.normal;
    out.pdf = cone->pdf;
    return true;
}

bool pdfSphereSolidAngle(const ShapeRecord& record, const Vec3& receiver, float& pdf) {
    const std::optional<SphereCone> cone = sphereCone(sphereOf(record), receiver);
    if (!cone) return false;
    pdf = cone->pdf;
    return true;
}

void addSphere(const ParameterValues& values, SceneBuilder& scene) {
    Sphere sphere;
    sphere.center = values.vec3("center");
    sphere.radius = values.number("radius");
    sphere.object = scene.addShapeObject(values);
    if (auto warning = tooSmallToSampleWarning("sphere", surfaceArea(sphere), scene.emissionOf(sphere.object)))
        scene.warn(values.located("radius", *warning));
    scene.addSphere(sphere);
}

}  // namespace

const ShapeOps kSphereOps{.name = "sphere",
                          .closed = true,
                          .bounds = sphereBounds,
                          .intersect = intersectSphereRecord,
                          .describe = describeSphere,
                          .area = sphereArea,
                          .sampleArea = sampleSphere,
                          .tessellate = tessellateSphere,
                          .sampleSolidAngle = sampleSphereSolidAngle,
                          .pdfSolidAngle = pdfSphereSolidAngle,
                          .patchGrid = &kSphereCells,
                          .parametrise = parametriseSphere};

ShapeRecord sphereRecord(const Sphere& sphere) {
    ShapeRecord record;
    record.ops = &kSphereOps;
    std::copy_n(&sphere.center.x, 3, record.data.begin());
    record.data[3] = sphere.radius;
    record.object = sphere.object;
    return record;
}

}  // namespace lightpath

// Rank 0: spheres are numbered first among the scene's objects.
LIGHTPATH_REGISTER_SHAPE(lightpath::ShapeType{
    {"shape", "sphere", "a sphere, seen from outside and inside, emitting from its whole surface",
     {lightpath::kShapeNameParameter,
      {"center", lightpath::ParameterType::Point, "m", "", {}, "its centre", true},
      {"radius", lightpath::ParameterType::Number, "m", "", lightpath::kPositive, "its radius", true},
      lightpath::kShapeMaterialParameter, lightpath::kShapeInteriorParameter},
     ""},
    0, "spheres", lightpath::addSphere})
