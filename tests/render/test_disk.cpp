// `[[disks]]` (src/shapes/disk.cpp), the worked example of a shape kind, against closed forms:
// ray hits at the t of the plane's equation, area pi r^2, area samples uniform (chi-square over
// equal-area rings and sectors; E[r^2] = R^2 / 2), a fan's area N/2 r^2 sin(2 pi / N) converging
// to pi r^2, and ray casting and the rasteriser seeing the same disk.
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

#include "film/aov_presets.h"
#include "film/aov_set.h"
#include "geometry/intersect.h"
#include "render/renderer.h"
#include "scene/scene_loader.h"
#include "scene/shape_type.h"

namespace lightpath {
namespace {

constexpr double kPiD = 3.14159265358979323846;

// A SceneBuilder that keeps the one shape a declaration adds.
class KeepShape final : public SceneBuilder {
public:
    ShapeRecord shape;
    void addLight(LightSlot) override {}
    std::uint32_t addEmitterObject(std::string, const ColorParameter&) override { return 0; }
    void addSphere(const Sphere&) override {}
    void addPlane(const Plane&) override {}
    void addTriangle(const Triangle&) override {}
    void addTriangle(const Triangle&, const TriangleNormals&) override {}
    std::uint32_t addShapeObject(const ParameterValues&) override { return 0; }
    std::uint32_t addObject(std::string, std::uint32_t) override { return 0; }
    std::uint32_t sceneMaterial(MaterialSlot) override { return 0; }
    std::filesystem::path folder() const override { return {}; }
    Rgb emissionOf(std::uint32_t) const override { return Rgb{0.0f}; }
    void addShape(const ShapeRecord& s) override { shape = s; }
    void warn(std::string) override {}
};

ShapeRecord disk(Vec3 center, Vec3 normal, double radius) {
    const ShapeType* type = ShapeRegistry::instance().find("disk");
    REQUIRE(type != nullptr);
    ParameterValues values(type->schema);
    values.set("center", center);
    values.set("normal", normal);
    values.set("radius", radius);
    values.set("material", std::string("m"));
    KeepShape keep;
    type->addTo(values, keep);
    REQUIRE(keep.shape.ops != nullptr);
    return keep.shape;
}

float hitT(const ShapeRecord& d, Vec3 origin, Vec3 direction) {
    Ray ray;
    ray.origin = origin;
    ray.direction = glm::normalize(direction);
    return d.ops->intersect(ray, d, 0.0f, NumericsOptions{});
}

TEST_CASE("disk: a ray meets it at the plane's t inside the rim, and misses outside") {
    const ShapeRecord d = disk({1, 2, 3}, {0, 0, 2}, 2.0);
    CHECK(hitT(d, {1.5f, 2, 10}, {0, 0, -1}) == doctest::Approx(7.0).epsilon(1e-6));
    // From the origin towards (2, 3, 3), 1.414 from the centre: t = |(2, 3, 3)| = sqrt(22).
    CHECK(hitT(d, {0, 0, 0}, {2, 3, 3}) == doctest::Approx(std::sqrt(22.0)).epsilon(1e-6));
    CHECK(hitT(d, {0, 0, 0}, {1 + 2.05f, 2, 3}) == kNoHit);     // 2.05 from the centre
    CHECK(hitT(d, {1.5f, 2, 10}, {0, 0, 1}) == kNoHit);          // pointing away
    CHECK(hitT(d, {1.5f, 2, 10}, {1, 0, 0}) == kNoHit);          // parallel to its plane
    // From below it is seen too, its normal still the declared one.
    Ray ray;
    ray.origin = {1, 2.5f, -4};
    ray.direction = {0, 0, 1};
    const float t = d.ops->intersect(ray, d, 0.0f, NumericsOptions{});
    CHECK(t == doctest::Approx(7.0).epsilon(1e-6));
    SurfaceHit hit;
    hit.point = ray.at(t);
    d.ops->describe(d, hit);
    CHECK(hit.normal == Vec3(0, 0, 1));
    CHECK(hit.point.z == 3.0f);
}

TEST_CASE("disk: its area is pi r^2") {
    CHECK(disk({0, 0, 0}, {0, 1, 0}, 2.0).ops->area(disk({0, 0, 0}, {0, 1, 0}, 2.0)) ==
          doctest::Approx(4.0 * kPiD).epsilon(1e-7));
    const ShapeRecord small = disk({0, 0, 0}, {1, 1, 1}, 1e-3);
    CHECK(small.ops->area(small) == doctest::Approx(kPiD * 1e-6).epsilon(1e-6));
}

TEST_CASE("disk: area samples are uniform (chi-square over equal-area cells, E[r^2] = R^2 / 2)") {
    const double radius = 1.5;
    const Vec3 center{0.5f, -1, 2}, normal = glm::normalize(Vec3{1, 2, -0.5f});
    const ShapeRecord d = disk(center, normal, radius);
    // 4 rings of equal area (edges at R sqrt(k / 4)) times 8 sectors: every cell holds 1/32.
    constexpr int kRings = 4, kSectors = 8, kSamples = 64000;
    std::vector<int> counts(kRings * kSectors, 0);
    const Vec3 s = glm::normalize(glm::cross(normal, std::fabs(normal.x) < 0.9f ? Vec3{1, 0, 0} : Vec3{0, 1, 0}));
    const Vec3 t = glm::cross(normal, s);
    double meanR2 = 0.0;
    std::uint32_t state = 12345u;
    const auto next = [&] {
        state = state * 1664525u + 1013904223u;  // Numerical Recipes' LCG, independent of the code
        return float(state >> 8) * 0x1p-24f;
    };
    for (int i = 0; i < kSamples; ++i) {
        const AreaSample p = d.ops->sampleArea(d, Vec2{next(), next()});
        const Vec3 v = p.point - center;
        CHECK_MESSAGE(std::fabs(glm::dot(v, normal)) < 1e-5f, "off the disk's plane");
        const double r2 = double(glm::dot(v, v));
        meanR2 += r2 / kSamples;
        const int ring = std::min(kRings - 1, int(r2 / (radius * radius) * kRings));
        double phi = std::atan2(double(glm::dot(v, t)), double(glm::dot(v, s)));
        if (phi < 0.0) phi += 2.0 * kPiD;
        const int sector = std::min(kSectors - 1, int(phi / (2.0 * kPiD) * kSectors));
        ++counts[ring * kSectors + sector];
    }
    const double expected = double(kSamples) / counts.size();
    double chi2 = 0.0;
    for (int c : counts) chi2 += (c - expected) * (c - expected) / expected;
    // 31 degrees of freedom: P(chi2 > 66.6) = 1e-4.
    CHECK(chi2 < 66.6);
    // r^2 is uniform on [0, R^2]: mean R^2/2, standard error R^2 / sqrt(12 N).
    CHECK(std::fabs(meanR2 - radius * radius / 2.0) < 4.0 * radius * radius / std::sqrt(12.0 * kSamples));
}

TEST_CASE("disk: its tessellation is a fan whose area N/2 r^2 sin(2 pi/N) converges to pi r^2") {
    const double radius = 2.0;
    const ShapeRecord d = disk({0, 1, 0}, {0, 1, 0}, radius);
    double previousError = std::numeric_limits<double>::infinity();
    for (float edge : {1.0f, 0.3f, 0.1f, 0.03f, 0.01f}) {
        std::vector<Triangle> fan;
        d.ops->tessellate(d, edge, fan);
        double area = 0.0;
        for (const Triangle& tri : fan) {
            area += surfaceArea(tri);
            CHECK(glm::dot(glm::cross(tri.b - tri.a, tri.c - tri.a), Vec3{0, 1, 0}) > 0.0f);  // wound as the normal
        }
        const double n = double(fan.size());
        CHECK(area == doctest::Approx(n / 2.0 * radius * radius * std::sin(2.0 * kPiD / n)).epsilon(1e-5));
        const double error = kPiD * radius * radius - area;
        CHECK(error >= -1e-5);
        CHECK(error < previousError);
        previousError = error;
    }
    CHECK(previousError / (kPiD * radius * radius) < 1e-4);
}

constexpr const char* kDiskScene = R"(
[camera]
eye = [0, 2, 6]
look_at = [0, 0.5, 0]
fov = 40
resolution = [48, 36]

[materials.floor]
kd = [0.6, 0.5, 0.4]
[materials.blue]
kd = [0.2, 0.3, 0.8]
ks = 0.3
n = 20
[materials.lamp]
emission = 3

[[lights]]
type = "point"
position = [2, 4, 3]
intensity = 20

[[planes]]
point = [0, 0, 0]
normal = [0, 1, 0]
material = "floor"

[[disks]]
name = "coin"
center = [-0.6, 0.8, 0]
normal = [0.3, 1, 0.6]
radius = 0.7
material = "blue"

[[disks]]
center = [0.9, 1.2, -0.5]
normal = [0, 0, 1]
radius = 0.4
material = "lamp"
)";

TEST_CASE("disk: ray casting and the rasteriser see the same disks, pixel for pixel") {
    const Scene scene = loadSceneFromText(kDiskScene, "disks.toml");
    REQUIRE(scene.shapes.size() == 2);
    const AovSet aovs(classesSet());
    RenderOptions options;
    options.shadows = false;
    options.integrator = "raycast";
    const Film raycast = Renderer(scene, aovs, options).render().film;
    options.integrator = "raster";
    const Film raster = Renderer(scene, aovs, options).render().film;
    int differing = 0, onDisk = 0;
    const SceneGeometry geometry(scene.spheres, scene.planes, scene.triangles, {}, Accelerator::Bvh, {}, 0,
                                 scene.shapes);
    const Camera camera(scene.camera);
    for (int y = 0; y < raycast.height(); ++y) {
        for (int x = 0; x < raycast.width(); ++x) {
            const auto hit = geometry.intersect(camera.generateRay(float(x) + 0.5f, float(y) + 0.5f));
            onDisk += hit && hit->shape != nullptr && hit->shape->name == "disk";
            for (std::size_t l = 0; l < raycast.layerCount(); ++l) {
                const Rgb p = raycast.at(l, x, y), q = raster.at(l, x, y);
                const float scale = std::max({1.0f, p.r, p.g, p.b});
                differing += std::max({std::fabs(p.r - q.r), std::fabs(p.g - q.g), std::fabs(p.b - q.b)}) > 1e-4f * scale;
            }
        }
    }
    CHECK(onDisk > 100);
    CHECK(differing == 0);
}

}  // namespace
}  // namespace lightpath
