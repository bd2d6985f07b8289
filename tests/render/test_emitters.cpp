// Emitters of every size the loader accepts give finite, non-negative light in every integrator
// (issue #28), and a sphere light sampled by the cone it subtends gives the closed-form
// irradiance of a uniformly emitting sphere at any radius. Also issue #30's light-set defects.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>

#include "film/aov_presets.h"
#include "film/aov_set.h"
#include "integrators/registry.h"
#include "lights/area_light.h"
#include "render/renderer.h"
#include "render_world.h"
#include "../support/film_checks.h"
#include "scene/scene_loader.h"

namespace lightpath {
namespace {

constexpr const char* kIntegrators[] = {"raycast", "raster", "whitted", "path", "bdpt", "radiosity"};

// `radiosityPatches` > 0: radiosity's budget of patches instead of its default.
RenderResult renderWith(const Scene& scene, const AovSet& aovs, const std::string& integrator, int spp,
                        int radiosityPatches = 0) {
    RenderOptions options;
    options.integrator = integrator;
    options.samplesPerPixel = integrator == "raster" ? 1 : spp;  // the rasteriser samples pixel centres once
    options.threads = 1;
    if (integrator == "radiosity" && radiosityPatches > 0) {
        ParameterValues values(findIntegrator("radiosity")->schema);
        values.set("patches", radiosityPatches);
        options.integratorParameters = values;
    }
    return Renderer(scene, aovs, options).render();
}

using test::finiteNonNegative;

std::string number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", v);
    return text;
}

double layerMean(const Film& film, const std::string& name) {
    std::size_t layer = film.layerCount();
    for (std::size_t l = 0; l < film.layerCount(); ++l)
        if (film.layerNames()[l] == name) layer = l;
    REQUIRE(layer < film.layerCount());
    double sum = 0.0;
    for (int y = 0; y < film.height(); ++y)
        for (int x = 0; x < film.width(); ++x) sum += film.at(layer, x, y).g;
    return sum / (film.width() * film.height());
}

}  // namespace

TEST_CASE("emitters: the tiny sphere light of issue #28 renders finite in every integrator") {
    Scene scene = loadScene(std::string(LIGHTPATH_SOURCE_DIR) + "/tests/fuzz/corpus/scene/regression-tiny-sphere-light.toml");
    scene.camera.width = 64;
    scene.camera.height = 48;
    const AovSet aovs(classesSet());
    for (const std::string integrator : kIntegrators) {
        CAPTURE(integrator);
        const RenderResult result = renderWith(scene, aovs, integrator, 4);
        CHECK(result.stats.rays.nonFinite == 0);
        CHECK(finiteNonNegative(result.film));
    }
}

// A floor point facing a sphere light of radius r whose centre is d straight above it receives
// E = pi L sin^2(theta_max), sin(theta_max) = r/d (the cone of directions the sphere subtends, a
// cap fully above the horizon): the floor (kd = 1) shows kd/pi E = L r^2/d^2 in E(D|G)L.
TEST_CASE("emitters: a sphere light gives the closed-form irradiance from radius 1e-12 to 9e5") {
    struct Case {
        double radius, distance, radiance;
    };
    const Case cases[] = {{1e-12, 1.0, 1e6}, {1e-3, 1.0, 1.0}, {1.0, 10.0, 1.0}, {1e3, 1e4, 1.0}, {9e5, 1e6, 1.0}};
    const AovSet aovs(classesSet());
    for (const Case& c : cases) {
        const std::string text = R"(
[camera]
eye = [0, 0, 0.001]
look_at = [0, 0, 0]
up = [0, 1, 0]
fov = 1
resolution = [4, 4]
[materials.floor]
kd = 1
[[planes]]
point = [0, 0, 0]
normal = [0, 0, 1]
material = "floor"
[[lights]]
type = "sphere"
center = [0, 0, )" + number(c.distance) + R"(]
radius = )" + number(c.radius) + R"(
radiance = )" + number(c.radiance) + "\n";
        const Scene scene = loadSceneFromText(text, "sphere-light.toml");
        const double r = scene.spheres[0].radius, d = scene.spheres[0].center.z;
        const double expected = c.radiance * (r / d) * (r / d);
        for (const std::string integrator : {"raycast", "path"}) {
            CAPTURE(c.radius);
            CAPTURE(integrator);
            const RenderResult result = renderWith(scene, aovs, integrator, 64);
            CHECK(result.stats.rays.nonFinite == 0);
            const double measured = layerMean(result.film, "raycast");
            CAPTURE(measured);
            CAPTURE(expected);
            CHECK(std::fabs(measured - expected) <= 0.02 * expected);  // relative: Approx adds 1 to the scale
        }
    }
}

TEST_CASE("emitters: an emitter too small to sample is warned about once, seen when hit, never sampled") {
    const std::string text = R"(
[materials.lamp]
emission = 1
[materials.grey]
kd = 0.5
[[spheres]]
center = [0, 0, -3]
radius = 1e-20
material = "lamp"
[[spheres]]
center = [0, -101, -3]
radius = 100
material = "grey"
)";
    Scene scene = loadSceneFromText(text, "tiny.toml");
    // The size of issue #28's test above: thousands of pixels see the grey sphere, each one a
    // chance for a sampled emitter to divide by its area (the default 640 x 480 only repeats it).
    scene.camera.width = 64;
    scene.camera.height = 48;
    REQUIRE(scene.warnings.size() == 1);
    CHECK(scene.warnings[0].find("tiny.toml:") == 0);
    CHECK(scene.warnings[0].find("never sampled") != std::string::npos);
    const test::RenderWorld world(scene);
    const Light* tiny = world.lights.lightOfObject(0);
    REQUIRE(tiny != nullptr);
    CHECK_FALSE(tiny->sampleable());
    CHECK_FALSE(world.lights.hasAreaLights());
    CHECK(world.lights.nextEventProbability(*tiny) == 0.0f);
    CHECK(world.lights.emitterProbability(*tiny) == 0.0f);
    const AovSet aovs(classesSet());
    for (const std::string integrator : kIntegrators) {
        CAPTURE(integrator);
        // Radiosity with 64 patches: its default 4096 on the grey sphere made nearly all of this
        // test's time (their form factors, 12 s under the sanitizers), and the light set that
        // leaves the tiny emitter unsampled is the same at any budget.
        const RenderResult result = renderWith(scene, aovs, integrator, 2, 64);
        CHECK(result.stats.rays.nonFinite == 0);
        CHECK(finiteNonNegative(result.film));
    }
}

TEST_CASE("emitters: a sliver triangle light keeps its area and lights by it") {
    // Edges 1 and 1e-25: the float cross product squared underflows (1e-50), the area is 5e-26.
    Scene scene;
    const std::string text = R"(
[materials.lamp]
emission = 1
[[triangles]]
vertices = [[0, 0, 0], [1, 0, 0], [0.5, 1e-25, 0]]
material = "lamp"
)";
    scene = loadSceneFromText(text, "sliver.toml");
    const test::RenderWorld world(scene);
    const auto* light = dynamic_cast<const AreaLightSource*>(world.lights.lightOfObject(0));
    REQUIRE(light != nullptr);
    CHECK(light->area() == doctest::Approx(5e-26).epsilon(1e-5));
    // Seen from (0.5, 0, 1), one unit above its plane: a sample at distance d = 1 / |wi.z| gives
    // E = L A cos cos' / d^2 = A wi.z^4 (the sliver is 1 long, so d is not 1).
    const Vec3 receiver{0.5f, 0.0f, 1.0f};
    const LightSample s = light->sample(receiver, Vec2{0.3f, 0.6f});
    REQUIRE(s.pdf > 0.0f);
    const float irradiance = s.weight.g * -s.wi.z;
    CHECK(std::isfinite(irradiance));
    const double z = s.wi.z;
    CHECK(irradiance == doctest::Approx(5e-26 * z * z * z * z).epsilon(1e-4).scale(0));
}

TEST_CASE("light set: a shapeless light that is not a delta is indexed as a light, not as an object (#30)") {
    // Its event's index counts scene lights; the light set once wrote its choice probability at
    // that index into a table of objects (here: none).
    class GlowSource final : public Light {
    public:
        explicit GlowSource(std::uint32_t index) : Light({lpe::EventType::Emitter, lpe::Scatter::None, Subject::SceneLight, index}) {}
        LightSample sample(const Vec3&, Vec2) const override { return {}; }
        float pdf(const Vec3&, const Vec3&, const Vec3&) const override { return 0.0f; }
        EmittedRay sampleEmission(Vec2, Vec2) const override { return {}; }
        EmittedRay emitAlong(const EmittedRay&, const Vec3&) const override { return {}; }
        float pdfEmissionDirection(const Vec3&, const Vec3&) const override { return 0.0f; }
        Rgb radiance(const SurfaceHit&, const Vec3&) const override { return Rgb{0.0f}; }
        Rgb power() const override { return Rgb{1.0f}; }
        bool isDelta() const override { return false; }
    };
    class Glow final : public SceneLight {
    public:
        Glow() : SceneLight("glow") {}
        std::unique_ptr<SceneLight> clone() const override { return std::make_unique<Glow>(*this); }
        Vec3 position() const override { return Vec3{0.0f}; }
        std::unique_ptr<Light> makeSource(std::uint32_t index) const override { return std::make_unique<GlowSource>(index); }
    };
    Scene scene;
    scene.lights.push_back(Glow());
    const test::RenderWorld world(scene);
    REQUIRE(world.lights.all().size() == 1);
    CHECK(world.lights.nextEventProbability(*world.lights.all()[0]) == 1.0f);
}

TEST_CASE("area light: a textured emission is read at the uv of the point hit or sampled, its power from the mean") {
    // emissive-texture.toml: a unit quad light x in [-0.5, 0.5], y in [0.3, 1.3] at z = 0 facing
    // +z, radiance 4 times a linear texture of quadrants 64 | 128 (below), 191 | 255 (above) / 255.
    const Scene scene = loadScene(std::filesystem::path(LIGHTPATH_SOURCE_DIR) / "tests/render/data/gltf/emissive-texture.toml");
    const test::RenderWorld world(scene);
    const Light* light = nullptr;
    for (std::uint32_t object = 0; object < scene.objects.size(); ++object)
        if (world.lights.lightOfObject(object) != nullptr) light = world.lights.lightOfObject(object);
    REQUIRE(light != nullptr);
    const auto quadrant = [](const Vec3& p) {
        const int level = p.y < 0.8f ? (p.x < 0.0f ? 64 : 128) : (p.x < 0.0f ? 191 : 255);
        return 4.0f * float(level) / 255.0f;
    };
    // Light sampling: Le = weight pdf at each sampled point, the texel of its quadrant (points near
    // the seams, which the bilinear filter blends, are left out).
    const Vec3 receiver{0.1f, 0.8f, 1.0f};
    int checked = 0;
    for (int i = 0; i < 16; ++i)
        for (int j = 0; j < 16; ++j) {
            const LightSample s = light->sample(receiver, Vec2{(float(i) + 0.5f) / 16.0f, (float(j) + 0.5f) / 16.0f});
            REQUIRE(s.pdf > 0.0f);
            if (std::fabs(s.point.x) < 0.02f || std::fabs(s.point.y - 0.8f) < 0.02f) continue;
            CAPTURE(s.point);
            CHECK(s.weight.r * s.pdf == doctest::Approx(quadrant(s.point)).epsilon(1e-4));
            ++checked;
        }
    CHECK(checked > 200);
    // A ray hitting it: the same texel.
    for (const Vec3 target : {Vec3{-0.25f, 0.55f, 0.0f}, Vec3{0.25f, 0.55f, 0.0f}, Vec3{-0.25f, 1.05f, 0.0f}, Vec3{0.25f, 1.05f, 0.0f}}) {
        const Ray ray{receiver, glm::normalize(target - receiver)};
        const std::optional<SurfaceHit> hit = world.geometry.intersect(ray);
        REQUIRE(hit.has_value());
        CHECK(world.lights.radiance(*hit, -ray.direction).g == doctest::Approx(quadrant(target)).epsilon(1e-4));
    }
    // Its power: pi A times the texture's mean, 4 (64 + 128 + 191 + 255) / (4 255), not the tint 4
    // (OpenImageIO's mean of an 8-bit image is itself 8-bit: 160 / 255, 0.3% off).
    CHECK(light->power().b == doctest::Approx(kPi * 4.0 * 638.0 / 1020.0).epsilon(0.01));
}

TEST_CASE("area light: one light is spheres or triangles, never both (#30)") {
    // Spheres emit on both sides and triangles on one; the light once took the kind of its last
    // primitive for all of them, so a mix was sampled on one side and weighed as two.
    const SceneGeometry geometry({Sphere{{0, 0, 0}, 1.0f, 0}}, {}, {Triangle{{2, 0, 0}, {3, 0, 0}, {2, 1, 0}, 0}});
    const PathEvent event{lpe::EventType::ObjectEmission, lpe::Scatter::None, Subject::Object, 0};
    CHECK_THROWS_AS(AreaLightSource(event, Rgb{1.0f}, geometry, {geometry.shapeId(0), geometry.triangleId(0)}),
                    std::invalid_argument);
    CHECK_THROWS_AS(AreaLightSource(event, Rgb{1.0f}, geometry, {geometry.triangleId(0), geometry.shapeId(0)}),
                    std::invalid_argument);
    CHECK_NOTHROW(AreaLightSource(event, Rgb{1.0f}, geometry, {geometry.shapeId(0)}));
}

}  // namespace lightpath

namespace lightpath {

// Inside a closed sphere that emits Le and reflects kd, every wall point sees emission over its
// whole hemisphere: E(D|G)L is kd Le. Sampled by area, by the cone or by the cosine, each sample
// is exactly that (cos cos / d^2 is 1/4r^2 everywhere on a sphere), so any shadow ray the light's
// own surface wrongly blocks shows as a pixel kd Le / spp low: no noise hides it. Rounding (the
// path tracer's MIS weights along short chords) moves a pixel by far less, under a quarter of that.
TEST_CASE("emitters: inside a closed emissive sphere every pixel's direct light is kd Le, no sample lost to the light's own surface") {
    const Scene scene = loadSceneFromText(R"(
[camera]
eye = [0.1, -0.2, 0.05]
look_at = [0, 0, -1]
up = [0, 1, 0]
fov = 90
resolution = [24, 24]
[materials.wall]
kd = 0.5
emission = 1
[[spheres]]
name = "furnace"
material = "wall"
center = [0, 0, 0]
radius = 1
)", "furnace.toml");
    const AovSet aovs(classesSet());
    constexpr int kSpp = 128;
    constexpr float kOneSampleLost = 0.5f / kSpp;
    for (const std::string integrator : {"raycast", "path"}) {
        CAPTURE(integrator);
        const Film film = renderWith(scene, aovs, integrator, kSpp).film;
        const std::size_t layer = static_cast<std::size_t>(
            std::find(film.layerNames().begin(), film.layerNames().end(), "raycast") - film.layerNames().begin());
        REQUIRE(layer < film.layerCount());
        int off = 0;
        for (int y = 0; y < film.height(); ++y)
            for (int x = 0; x < film.width(); ++x) off += !(std::fabs(film.at(layer, x, y).g - 0.5f) < 0.25f * kOneSampleLost);
        CHECK(off == 0);
    }
}

TEST_CASE("next-event estimation's numbers: drawn where a light reads them, skipped without moving the rest") {
    // The premise: with one area light the choice ignores its number. The check: drawLightChoice
    // returns the numbers a full draw (choice, then point) gives where a light reads them, and
    // leaves the sampler where the full draw does, for 0, 1 and 2 area lights and every kind.
    const std::string room = R"(
[camera]
eye = [0, 0, 5]
look_at = [0, 0, 0]
[materials.grey]
kd = 0.5
[[lights]]
position = [0, 3, 0]
[[spheres]]
center = [0, -101, 0]
radius = 100
material = "grey"
)";
    const std::string lamp = R"(
[[lights]]
type = "sphere"
center = [1, 2, 0]
radius = 0.2
radiance = 3
)";
    const std::string bulb = R"(
[[lights]]
type = "sphere"
center = [-1, 2, 0]
radius = 0.1
radiance = 5
)";
    for (int areaLights = 0; areaLights <= 2; ++areaLights) {
        const std::string text = room + (areaLights >= 1 ? lamp : "") + (areaLights >= 2 ? bulb : "");
        const test::RenderWorld world(loadSceneFromText(text, "lights.toml"));
        CAPTURE(areaLights);
        REQUIRE(world.lights.hasAreaLights() == (areaLights > 0));
        REQUIRE(world.lights.choosesAmongAreaLights() == (areaLights > 1));
        if (areaLights == 1) {
            const ChosenLight first = world.lights.chooseAreaLight(0.0f), last = world.lights.chooseAreaLight(kBelowOne);
            CHECK(first.light == last.light);
            CHECK(first.probability == 1.0f);
        }
        for (SamplerKind kind : {SamplerKind::Independent, SamplerKind::Stratified, SamplerKind::Sobol}) {
            for (int index : {0, 3}) {
                CAPTURE(samplerName(kind));
                CAPTURE(index);
                Sampler drawn(kind, 0xabcdefull, index, 4), full(kind, 0xabcdefull, index, 4);
                const LightChoiceSample u = drawLightChoice(drawn, world.lights);
                const float uChoice = full.next1D();
                const Vec2 uPoint = full.next2D();
                if (areaLights > 1) CHECK(u.uChoice == uChoice);
                if (areaLights > 0) CHECK(u.uPoint == uPoint);
                CHECK(drawn.next2D() == full.next2D());
                CHECK(drawn.next1D() == full.next1D());
            }
        }
    }
}

}  // namespace lightpath

namespace lightpath {
namespace {

// A square lamp halfway between a floor and a ceiling of the same matte material, seen edge-on by
// a camera at its height: the scene is symmetric about the lamp's plane, so every integrator's
// image is too when the lamp emits from both sides (two_sided_emission: glTF's doubleSided, as
// Cycles' mesh lights). Emitting from its normal's side only (up), the floor gets no direct light.
Scene lampBetweenFloorAndCeiling(bool twoSided) {
    return loadSceneFromText(std::string(R"(
[camera]
eye = [0, 1, 4]
look_at = [0, 1, 0]
fov = 60
resolution = [32, 32]
[materials.matte]
kd = 0.5
[materials.lamp]
kd = 0
emission = 4
two_sided_emission = )") + (twoSided ? "true" : "false") + R"(
[[triangles]]
material = "matte"
vertices = [[-4, 0, -6], [-4, 0, 3], [4, 0, 3]]
[[triangles]]
material = "matte"
vertices = [[-4, 0, -6], [4, 0, 3], [4, 0, -6]]
[[triangles]]
material = "matte"
vertices = [[-4, 2, -6], [4, 2, 3], [-4, 2, 3]]
[[triangles]]
material = "matte"
vertices = [[-4, 2, -6], [4, 2, -6], [4, 2, 3]]
[[triangles]]
name = "lamp"
material = "lamp"
vertices = [[-0.5, 1, -1.5], [-0.5, 1, -0.5], [0.5, 1, -0.5]]
[[triangles]]
name = "lamp"
material = "lamp"
vertices = [[-0.5, 1, -1.5], [0.5, 1, -0.5], [0.5, 1, -1.5]]
)", "two-sided-lamp.toml");
}

// (top - bottom) / (top + bottom) of the beauty's image halves: the ceiling's and the floor's.
double asymmetry(const Film& film) {
    double top = 0.0, bottom = 0.0;
    for (int y = 0; y < film.height(); ++y)
        for (int x = 0; x < film.width(); ++x) (y < film.height() / 2 ? top : bottom) += film.at(0, x, y).g;
    return (top - bottom) / (top + bottom);
}

}  // namespace

TEST_CASE("emitters: a two-sided emissive quad lights both its sides alike in every integrator" * doctest::test_suite("statistical")) {
    const AovSet aovs(classesSet());
    const Scene twoSided = lampBetweenFloorAndCeiling(true), oneSided = lampBetweenFloorAndCeiling(false);
    for (const std::string integrator : {"raycast", "raster", "whitted", "path", "bdpt", "radiosity", "photon", "sppm"}) {
        CAPTURE(integrator);
        const double both = asymmetry(renderWith(twoSided, aovs, integrator, 16, 256).film);
        const double one = asymmetry(renderWith(oneSided, aovs, integrator, 16, 256).film);
        CAPTURE(both);
        CAPTURE(one);
        CHECK(std::fabs(both) < 0.03);
        CHECK(std::fabs(one) > 0.3);  // the control: one side sees only the other's light
    }
}

}  // namespace lightpath
