// Radiosity (issue "Radiosity, the lecture's fourth method"): form factors against Hottel's closed
// forms, a closed box against Le / (1 - rho), energy conservation, agreement with the path tracer
// on the Cornell box, and classification (AOVs sum to the beauty, light groups, bounces, skipping).
// A check against a path-traced reference and its control (a case the check must fail) are two
// subcases of one test case: the reference, a static, is rendered once per process for both.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <sstream>
#include <numeric>
#include <optional>

#include "film/aov_presets.h"
#include "film/aov_set.h"
#include "integrators/radiosity.h"
#include "integrators/radiosity_gradients.h"
#include "math/random.h"
#include "lpe/analysis.h"
#include "render/renderer.h"
#include "scene/scene_loader.h"
#include "render_world.h"
#include "scene_builder.h"
#include "../support/film_checks.h"
#include "../support/sanitizer.h"

namespace lightpath {
namespace {

// A scene solved by the radiosity integrator, called directly.
struct Solved {
    test::RenderWorld world;
    RadiosityIntegrator radiosity;

    Solved(Scene s, const RadiosityOptions& options, int maxDepth)
        : world(std::move(s), classesSet(), maxDepth, options, 2) {
        radiosity.preprocess(world.context);
    }

    // Area-weighted form factor from the front of every patch of object `from` to the front of
    // every patch of object `to`.
    double objectFormFactor(std::uint32_t from, std::uint32_t to) const {
        const auto& patches = radiosity.mesh().patches();
        double area = 0.0, sum = 0.0;
        for (std::uint32_t p = 0; p < patches.size(); ++p) {
            if (patches[p].object != from) continue;
            area += patches[p].area;
            const auto row = radiosity.formFactors(p, 0);
            for (std::size_t i = 0; i < row.targets.size(); ++i)
                if (row.targets[i] % 2 == 0 && patches[row.targets[i] / 2].object == to) sum += patches[p].area * row.factors[i];
        }
        return sum / area;
    }
};

double relativeError(double value, double expected) { return std::fabs(value / expected - 1.0); }

PhongMaterial diffuse(const std::string& name, float albedo, float emission = 0.0f) {
    PhongMaterial m;
    m.name = name;
    m.kd = Rgb{albedo};
    m.emission = Rgb{emission};
    return m;
}

void addQuad(Scene& scene, std::uint32_t object, Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
    scene.triangles.push_back({a, b, c, object});
    scene.triangles.push_back({a, c, d, object});
}

// Hottel's view factors (Howell's catalogue, C-11 and C-14), written out from the formulas.
double parallelSquares(double a, double b, double c) {
    const double x = a / c, y = b / c;
    const double x1 = std::sqrt(1 + x * x), y1 = std::sqrt(1 + y * y);
    return 2.0 / (M_PI * x * y) *
           (std::log(std::sqrt((1 + x * x) * (1 + y * y) / (1 + x * x + y * y))) + x * y1 * std::atan(x / y1) +
            y * x1 * std::atan(y / x1) - x * std::atan(x) - y * std::atan(y));
}

double perpendicularSharingEdge(double h, double w) {
    const double hw = std::sqrt(h * h + w * w);
    const double a = (1 + w * w) * (1 + h * h) / (1 + w * w + h * h);
    const double b = std::pow(w * w * (1 + w * w + h * h) / ((1 + w * w) * (w * w + h * h)), w * w);
    const double c = std::pow(h * h * (1 + h * h + w * w) / ((1 + h * h) * (h * h + w * w)), h * h);
    return 1.0 / (M_PI * w) *
           (w * std::atan(1 / w) + h * std::atan(1 / h) - hw * std::atan(1 / hw) + 0.25 * std::log(a * b * c));
}

TEST_CASE("the closed forms themselves: Howell's tabulated values") {
    // Howell's catalogue: 0.1998 and 0.2000 to the four places it gives.
    CHECK(std::fabs(parallelSquares(1, 1, 1) - 0.1998) < 5e-5);
    CHECK(std::fabs(perpendicularSharingEdge(1, 1) - 0.2000) < 5e-5);
}

TEST_CASE("form factors of unit squares match Hottel's closed forms to 1% at the default density" * doctest::test_suite("statistical")) {
    const RadiosityOptions defaults;
    SUBCASE("parallel, directly opposed, one apart") {
        Scene scene;
        const auto m = test::addMaterial(scene, diffuse("grey", 0.5f));
        const auto lower = test::addObject(scene, "lower", m), upper = test::addObject(scene, "upper", m);
        addQuad(scene, lower, {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0});  // facing +z
        addQuad(scene, upper, {0, 0, 1}, {0, 1, 1}, {1, 1, 1}, {1, 0, 1});  // facing -z
        scene.lights.push_back(PointLight{"lamp", {0.5f, 0.5f, 0.5f}, Rgb{1.0f}});  // so there is light to solve
        const Solved solved(scene, defaults, 2);
        const double expected = parallelSquares(1, 1, 1);
        CHECK(relativeError(solved.objectFormFactor(lower, upper), expected) < 0.01);
        CHECK(relativeError(solved.objectFormFactor(upper, lower), expected) < 0.01);
    }
    SUBCASE("perpendicular, sharing an edge") {
        Scene scene;
        const auto m = test::addMaterial(scene, diffuse("grey", 0.5f));
        const auto floor = test::addObject(scene, "floor", m), wall = test::addObject(scene, "wall", m);
        addQuad(scene, floor, {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0});  // facing +z
        addQuad(scene, wall, {0, 0, 0}, {0, 1, 0}, {0, 1, 1}, {0, 0, 1});   // facing +x
        scene.lights.push_back(PointLight{"lamp", {0.5f, 0.5f, 0.5f}, Rgb{1.0f}});
        const Solved solved(scene, defaults, 2);
        const double expected = perpendicularSharingEdge(1, 1);
        CHECK(relativeError(solved.objectFormFactor(floor, wall), expected) < 0.01);
        CHECK(relativeError(solved.objectFormFactor(wall, floor), expected) < 0.01);
    }
}

// The unit cube [0,1]^3 wound inwards, every face of albedo rho emitting Le towards the inside.
Scene emissiveBox(float albedo, float emission) {
    Scene scene;
    const auto m = test::addMaterial(scene, diffuse("wall", albedo, emission));
    const auto box = test::addObject(scene, "box", m);
    const Vec3 p[8] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    addQuad(scene, box, p[0], p[1], p[2], p[3]);  // z = 0, facing +z
    addQuad(scene, box, p[4], p[7], p[6], p[5]);  // z = 1, facing -z
    addQuad(scene, box, p[0], p[4], p[5], p[1]);  // y = 0, facing +y
    addQuad(scene, box, p[3], p[2], p[6], p[7]);  // y = 1, facing -y
    addQuad(scene, box, p[0], p[3], p[7], p[4]);  // x = 0, facing +x
    addQuad(scene, box, p[1], p[5], p[6], p[2]);  // x = 1, facing -x
    scene.camera = test::centredCamera({0.5f, 0.5f, 0.5f}, {1.0f, 0.5f, 0.5f}, {0, 1, 0}, 15);
    scene.camera.verticalFovDegrees = 80.0f;
    return scene;
}

TEST_CASE("a closed box of albedo rho emitting Le everywhere shows Le / (1 - rho)") {
    constexpr float kAlbedo = 0.6f, kEmission = 1.5f;
    const double expected = kEmission / (1.0 - kAlbedo);
    const AovSet aovs(classesSet());
    RenderOptions options;
    options.integrator = "radiosity";
    options.maxDepth = kMaxDepth;
    options.radiosity.patchBudget = 1536;
    struct BoxErrors {
        double mean, worst;
    };
    const auto errors = [&](int finalGather) {
        options.radiosity.finalGather = finalGather;
        options.samplesPerPixel = finalGather > 0 ? 16 : 1;
        const RenderResult result = Renderer(emissiveBox(kAlbedo, kEmission), aovs, options).render();
        double worst = 0.0, sum = 0.0;
        for (int y = 0; y < result.film.height(); ++y)
            for (int x = 0; x < result.film.width(); ++x) {
                worst = std::max(worst, std::fabs(double(result.film.at(0, x, y).g) / expected - 1.0));
                sum += result.film.at(0, x, y).g;
            }
        REQUIRE(result.stats.radiosity);
        CHECK(result.stats.radiosity->residual < options.radiosity.tolerance);
        return BoxErrors{std::fabs(sum / (result.film.width() * result.film.height()) / expected - 1.0), worst};
    };
    CAPTURE(expected);
    // Read at the hit, each pixel shows its element's solution, its noise shrunk away (the smooth display).
    const BoxErrors classic = errors(0);
    CAPTURE(classic.mean);
    CAPTURE(classic.worst);
    CHECK(classic.worst < 0.01);
    // Gathered, a pixel's direct light is sampled there and its later bounces average the elements
    // its rays meet, each with its form factors' noise: exact in the mean, within that noise per
    // pixel (16 samples of 16 rays).
    const BoxErrors gathered = errors(16);
    CAPTURE(gathered.mean);
    CAPTURE(gathered.worst);
    CHECK(gathered.mean < 0.002);
    CHECK(gathered.worst < 0.01);
}

TEST_CASE("energy is conserved: rows of the form factors sum to 1 in a closed box, each bounce keeps rho of the last") {
    constexpr float kAlbedo = 0.5f;
    RadiosityOptions options;
    options.patchBudget = 768;
    options.tolerance = 0.0;
    const Solved solved(emissiveBox(kAlbedo, 1.0f), options, 6);
    const auto& patches = solved.radiosity.mesh().patches();
    double worstInside = 0.0, lostInside = 0.0, worstOutside = 0.0;
    for (std::uint32_t p = 0; p < patches.size(); ++p) {
        const auto insideRow = solved.radiosity.formFactors(p, 0), outsideRow = solved.radiosity.formFactors(p, 1);
        const double inside = std::accumulate(insideRow.factors.begin(), insideRow.factors.end(), 0.0);
        const double outside = std::accumulate(outsideRow.factors.begin(), outsideRow.factors.end(), 0.0);
        worstInside = std::max(worstInside, inside);
        lostInside += 1.0 - inside;
        worstOutside = std::max(worstOutside, outside);
    }
    // Every ray from the inside lands on the inside (but for a rare grazing ray at an edge).
    CHECK(worstInside < 1.0 + 1e-6);
    CHECK(lostInside / double(patches.size()) < 1e-5);
    CHECK(worstOutside == 0.0);  // every ray from the outside escapes

    // Flux leaving the inside after each bounce: each bounce reflects rho of the one before.
    std::vector<double> flux;
    for (int k = 1; k <= 6; ++k) {
        double sum = 0.0;
        for (std::uint32_t p = 0; p < patches.size(); ++p) sum += patches[p].area * solved.radiosity.patchRadiance(0, k, p, 0).g;
        flux.push_back(sum);
    }
    // Bounce 1: the box's own emission Le pi over 6 unit faces, reflected: rho Le (per unit pi, x6).
    CHECK(relativeError(flux[0], 6.0 * kAlbedo) < 0.01);
    for (std::size_t k = 1; k < flux.size(); ++k) CHECK(relativeError(flux[k] / flux[k - 1], kAlbedo) < 0.005);
}

}  // namespace
}  // namespace lightpath

namespace lightpath {
namespace {

constexpr int kCornellSize = 64;
// Radiosity's ED*L within 5% of the path tracer's (issue: "within 5%").
constexpr double kCornellTolerance = 0.05;

Scene cornellBox(int size) {
    Scene scene = loadScene(LIGHTPATH_SOURCE_DIR "/scenes/cornell-original.toml");
    scene.camera.width = scene.camera.height = size;
    return scene;
}

// The ED*L layer of the Cornell box by `integrator`.
// Radiosity at 16 spp: camera rays only, so that pixels average their footprint as the path
// tracer's do (the lamp and the edges cover some pixels in part).
Film cornellDiffuse(const Scene& scene, const std::string& integrator, int spp, std::size_t patches = 0) {
    const AovSet aovs(std::vector<lpe::NamedExpression>{{"diffuse", "ED*L"}});
    RenderOptions options;
    options.integrator = integrator;
    options.writeBeauty = false;
    options.samplesPerPixel = spp;
    options.sampler = SamplerKind::Sobol;
    options.threads = 2;
    if (patches > 0) options.radiosity.patchBudget = patches;
    return Renderer(scene, aovs, options).render().film;
}

// Relative L1 difference of the images' luminance over blocks of `block` x `block` pixels: the
// path tracer's noise averages out within a block, the mesh's error does not.
double blockError(const Film& test, const Film& reference, int block) {
    const auto luminance = [](const Rgb& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; };
    double difference = 0.0, total = 0.0;
    for (int by = 0; by < reference.height(); by += block) {
        for (int bx = 0; bx < reference.width(); bx += block) {
            double a = 0.0, b = 0.0;
            for (int y = by; y < by + block; ++y)
                for (int x = bx; x < bx + block; ++x) {
                    a += luminance(test.at(0, x, y));
                    b += luminance(reference.at(0, x, y));
                }
            difference += std::fabs(a - b);
            total += b;
        }
    }
    return difference / total;
}

// The path tracer's ED*L of the Cornell box at 256 samples per pixel, rendered once.
const Film& pathTracedCornell() {
    static const Film film = cornellDiffuse(cornellBox(kCornellSize), "path", 256);
    return film;
}

// The L1 error over 8 x 8 blocks falls as the patches shrink (measured: 3.7%, 1.7%, 0.59% at 64,
// 256 and 1024 first elements; 0.36% at 4096) and is within issue 27's 2% at 1024; the same box
// 10% darker (the control) is 14% off.
constexpr double kCornellConverged = 0.02;

TEST_CASE("the Cornell box: radiosity's ED*L converges to the path tracer's as patches shrink; control: radiosity of a Cornell box 10% darker fails the same tolerance" *
          doctest::test_suite("statistical")) {
    SUBCASE("the Cornell box: radiosity's ED*L converges to the path tracer's as patches shrink") {
        const Film& reference = pathTracedCornell();
        std::vector<double> errors;
        for (std::size_t patches : {64, 256, 1024})
            errors.push_back(blockError(cornellDiffuse(cornellBox(kCornellSize), "radiosity", 16, patches), reference, 8));
        CAPTURE(errors[0]);
        CAPTURE(errors[1]);
        CAPTURE(errors[2]);
        CHECK(errors[0] > errors[1]);
        CHECK(errors[1] > errors[2]);
        CHECK(errors[2] < kCornellConverged);
    }
    SUBCASE("control: radiosity of a Cornell box 10% darker fails the same tolerance") {
        Scene darker = cornellBox(kCornellSize);
        for (MaterialSlot& m : darker.materials) phongOf(m).kd = phongOf(m).kd.constant() * 0.9f;
        const double error = blockError(cornellDiffuse(darker, "radiosity", 16, 1024), pathTracedCornell(), 8);
        CAPTURE(error);
        CHECK(error > kCornellConverged);
    }
}

}  // namespace
}  // namespace lightpath

namespace lightpath {
namespace {

struct Rendered {
    Film film;
    RadiosityStats stats;
};

Rendered renderCornell(std::vector<lpe::NamedExpression> expressions, bool beauty, int maxDepth = 5) {
    const AovSet aovs(std::move(expressions));
    RenderOptions options;
    options.integrator = "radiosity";
    options.writeBeauty = beauty;
    options.maxDepth = maxDepth;
    options.threads = 2;
    // The checks count lights, bounces and iterations, or compare renders at one budget with each
    // other: none depends on the mesh's size, so the sanitizer stage solves a fifth of the elements.
    options.radiosity.patchBudget = test::sanitizedCount(1024);
    options.radiosity.tolerance = 0.0;
    // Uniform patches: the refinement passes solve every light and bounce (radiosity.cpp), which
    // the counts checked below (lights, bounces, form-factor rays of the requested solve) leave out.
    options.radiosity.refineRounds = 0;
    RenderResult result = Renderer(cornellBox(32), aovs, options).render();
    REQUIRE(result.stats.radiosity);
    return {std::move(result.film), *result.stats.radiosity};
}

// Layers 1..n-1 (all but the beauty at 0) against the beauty, per pixel and channel.
void checkSumsToBeauty(const Film& film, bool restIsZero) {
    double rest = 0.0;
    for (int y = 0; y < film.height(); ++y)
        for (int x = 0; x < film.width(); ++x)
            rest = std::max(rest, double(maxComponent(film.at(film.layerCount() - 1, x, y))));
    CHECK(test::worstSumError(film) <= 1.0);
    if (restIsZero) CHECK(rest == 0.0);
}

double layerTotal(const Film& film, std::size_t layer) {
    double total = 0.0;
    for (int y = 0; y < film.height(); ++y)
        for (int x = 0; x < film.width(); ++x) total += film.at(layer, x, y).g;
    return total;
}

bool sameLayer(const Film& a, std::size_t la, const Film& b, std::size_t lb) {
    const auto x = a.layer(la), y = b.layer(lb);
    return std::equal(x.begin(), x.end(), y.begin(), y.end());
}

TEST_CASE("radiosity's classes partition its light: raycast EDL, indirect ED{2,}L, emission EL, nothing else") {
    const Rendered r = renderCornell(classesSet(), true);
    checkSumsToBeauty(r.film, true);
    const auto names = r.film.layerNames();
    const auto index = [&](const std::string& name) {
        return static_cast<std::size_t>(std::find(names.begin(), names.end(), name) - names.begin());
    };
    CHECK(layerTotal(r.film, index("raycast")) > 0.0);
    CHECK(layerTotal(r.film, index("indirect")) > 0.0);
    CHECK(layerTotal(r.film, index("emission")) > 0.0);
    // Radiosity has no specular paths.
    CHECK(layerTotal(r.film, index("raytrace")) == 0.0);
    CHECK(layerTotal(r.film, index("mirror")) == 0.0);
}

TEST_CASE("radiosity's light groups and bounces sum to the beauty") {
    SUBCASE("light groups: the point light and the ceiling panel") {
        const Rendered r = renderCornell({{"lamp", "E.*<L.'ceiling-lamp'>"}, {"panel", "E.*<O.'light'>"}}, true);
        checkSumsToBeauty(r.film, true);
        CHECK(layerTotal(r.film, 1) > 0.0);
        CHECK(layerTotal(r.film, 2) > 0.0);
    }
    SUBCASE("bounce by bounce") {
        const Rendered r = renderCornell(
            {{"e", "EL"}, {"b1", "EDL"}, {"b2", "EDDL"}, {"b3", "EDDDL"}, {"b4", "ED{4,}L"}}, true);
        checkSumsToBeauty(r.film, true);
        // Each bounce carries less light than the one before (albedos below 1).
        for (std::size_t l = 2; l < 5; ++l) CHECK(layerTotal(r.film, l) > layerTotal(r.film, l + 1));
        CHECK(layerTotal(r.film, 5) > 0.0);
    }
}

TEST_CASE("radiosity solves no light and no bounce that no requested output accepts") {
    const Rendered full = renderCornell({{"b1", "EDL"}, {"lamp", "E.*<L.'ceiling-lamp'>"}}, true);
    CHECK(full.stats.lightsSolved == 2);
    CHECK(full.stats.iterations == 5);
    CHECK(full.stats.lightBouncesSolved == 10);
    CHECK(full.stats.formFactorRays > 0);

    SUBCASE("direct light only: one iteration, no form factor") {
        const Rendered direct = renderCornell({{"b1", "EDL"}}, false);
        CHECK(direct.stats.iterations == 1);
        CHECK(direct.stats.lightBouncesSolved == 2);
        CHECK(direct.stats.formFactorRays == 0);
        CHECK(sameLayer(direct.film, 0, full.film, 1));
    }
    SUBCASE("one light group: the other light is not solved") {
        const Rendered lamp = renderCornell({{"lamp", "E.*<L.'ceiling-lamp'>"}}, false);
        CHECK(lamp.stats.lightsSolved == 1);
        CHECK(lamp.stats.lightBouncesSolved == 5);
        CHECK(sameLayer(lamp.film, 0, full.film, 2));
    }
    SUBCASE("two bounces of one light") {
        const Rendered two = renderCornell({{"b2", "EDD<O.'light'>"}}, false);
        CHECK(two.stats.lightsSolved == 1);
        CHECK(two.stats.iterations == 2);
        CHECK(two.stats.lightBouncesSolved == 2);
        CHECK(layerTotal(two.film, 0) > 0.0);
    }
}

}  // namespace
}  // namespace lightpath

namespace lightpath {
namespace {

TEST_CASE("radiosity on the shipped scenes with planes and spheres: the classes sum to the beauty") {
    const AovSet aovs(classesSet());
    for (const char* name : {"taxonomy.toml", "glass-sphere.toml", "mirror-sphere.toml", "szymczak-three-lights.toml"}) {
        CAPTURE(name);
        Scene scene = loadScene(std::string(LIGHTPATH_SOURCE_DIR "/scenes/") + name);
        scene.camera.height = std::max(1, scene.camera.height * 32 / scene.camera.width);
        scene.camera.width = 32;
        RenderOptions options;
        options.integrator = "radiosity";
        options.threads = 2;
        options.radiosity.patchBudget = 512;
        // Sums hold for any number of rays; these are the fewest that still refine (2x2 strata).
        options.radiosity.formFactorRays = 16;
        options.radiosity.lightSamples = 4;
        const RenderResult result = Renderer(scene, aovs, options).render();
        checkSumsToBeauty(result.film, true);
        REQUIRE(result.stats.radiosity);
        // The first mesh within the budget; refinement grows it by at most 4x (radiosity.cpp's kRefineGrowth).
        CHECK(result.stats.radiosity->clusters <= 4 * 512);
        CHECK(layerTotal(result.film, 0) > 0.0);
    }
}

}  // namespace
}  // namespace lightpath

namespace lightpath {
namespace {

// tests/render/data/cornell-lamp.reference: the path tracer's converged CornellBox-Original under
// its own lamp (32768 spp, max depth 64), frozen before radiosity existed. One R G B line per pixel.
Film frozenCornellReference(int width, int height) {
    std::ifstream in(LIGHTPATH_SOURCE_DIR "/tests/render/data/cornell-lamp.reference");
    REQUIRE(in);
    Film film(width, height, {"beauty"});
    std::string line;
    int pixel = 0;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        if (pixel == width * height) FAIL("more pixels than ", width, "x", height);
        std::istringstream values(line);
        Rgb& v = film.pixel(pixel % width, pixel / width)[0];
        values >> v.r >> v.g >> v.b;
        ++pixel;
    }
    CHECK(pixel == width * height);
    return film;
}

TEST_CASE("the Cornell box under its lamp alone: radiosity with every bounce matches the frozen path-traced reference" * doctest::test_suite("statistical")) {
    const Scene lamp = loadScene(LIGHTPATH_SOURCE_DIR "/tests/render/data/cornell-lamp.toml");
    const Film reference = frozenCornellReference(lamp.camera.width, lamp.camera.height);
    const auto render = [](const Scene& scene) {
        RenderOptions options;
        options.integrator = "radiosity";
        options.maxDepth = kMaxDepth;
        options.threads = 2;
        // Pixels average their footprint, as the reference's do: the lamp covers some in part.
        options.samplesPerPixel = 64;
        options.sampler = SamplerKind::Sobol;
        return Renderer(scene, AovSet(std::vector<lpe::NamedExpression>{}), options).render().film;
    };
    const double error = blockError(render(lamp), reference, 4);
    Scene darker = lamp;
    for (MaterialSlot& m : darker.materials) phongOf(m).kd = phongOf(m).kd.constant() * 0.9f;
    const double control = blockError(render(darker), reference, 4);
    CAPTURE(error);
    CAPTURE(control);
    CHECK(error < kCornellTolerance);
    CHECK(control > kCornellTolerance);
}

}  // namespace
}  // namespace lightpath

namespace lightpath {
namespace {

// Issue 27: radiosity per bounce (EDL, EDDL, EDDDL, ED{4,}L) against the path tracer, on a scene
// with more triangles than the element budget. The worst relative error of the image's mean and of
// each of its 4 x 4 regions, over the four bounces.
struct BounceErrors {
    double mean = 0.0, region = 0.0;
};

constexpr int kBounceDepth = 6;

// The AOVs `expressions` alone (no beauty) of `scene` under `integrator`, Sobol samples on 2 threads.
Film renderAovs(const Scene& scene, std::vector<lpe::NamedExpression> expressions, const std::string& integrator,
                int spp, int maxDepth, const RadiosityOptions& radiosity) {
    const AovSet aovs(std::move(expressions));
    RenderOptions options;
    options.integrator = integrator;
    options.writeBeauty = false;
    options.samplesPerPixel = spp;
    options.sampler = SamplerKind::Sobol;
    options.maxDepth = maxDepth;
    options.threads = 2;
    options.radiosity = radiosity;
    return Renderer(scene, aovs, options).render().film;
}

// `lights`: the emitters a bounce ends at (Heckbert's L: all of them, the ambient term and the sky included).
Film renderBounces(const Scene& scene, const std::string& integrator, int spp, const RadiosityOptions& radiosity,
                   const std::string& lights = "L") {
    return renderAovs(scene,
                      {{"b1", "ED" + lights}, {"b2", "EDD" + lights}, {"b3", "EDDD" + lights}, {"b4", "ED{4,}" + lights}},
                      integrator, spp, kBounceDepth, radiosity);
}

// The worst over the first `bounces` layers (EDL, EDDL, EDDDL, ED{4,}L).
BounceErrors bounceErrors(const Film& test, const Film& reference, std::size_t bounces = 4) {
    const auto luminance = [](const Rgb& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; };
    BounceErrors worst;
    const int w = reference.width(), h = reference.height();
    for (std::size_t layer = 0; layer < bounces; ++layer) {
        double regionsA[4][4] = {}, regionsB[4][4] = {}, a = 0.0, b = 0.0;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const double ta = luminance(test.at(layer, x, y)), tb = luminance(reference.at(layer, x, y));
                regionsA[4 * y / h][4 * x / w] += ta;
                regionsB[4 * y / h][4 * x / w] += tb;
                a += ta;
                b += tb;
            }
        if (!(b > 0.0)) continue;
        worst.mean = std::max(worst.mean, std::fabs(a / b - 1.0));
        // Regions holding less than a twentieth of an average region's light (the sky, a black
        // corner) are left out: there the path tracer's noise is the whole difference.
        for (int ry = 0; ry < 4; ++ry)
            for (int rx = 0; rx < 4; ++rx)
                if (regionsB[ry][rx] > b / 16.0 / 20.0)
                    worst.region = std::max(worst.region, std::fabs(regionsA[ry][rx] / regionsB[ry][rx] - 1.0));
    }
    return worst;
}

// A 69,451-triangle bunny in a Lambertian Cornell box (tests/render/data/cornell-bunny.toml). With
// more triangles than the budget, the old patch budget made every triangle one patch (patch size
// 1e6), so each wall was two patches (issue 27's CornellBox-Water failure); now the bunny's
// triangles are clustered and the walls subdivided.
Scene heavyMesh() { return loadScene(LIGHTPATH_SOURCE_DIR "/tests/render/data/cornell-bunny.toml"); }

const Film& pathTracedHeavyMesh() {
    static const Film film = renderBounces(heavyMesh(), "path", 4096, {});
    return film;
}

// Issue 27's bar, 2% in the mean and 5% per 4x4 region, at the default settings (8192 first
// elements, refined where the error estimate asks, the final gather). Measured: mean 0.15%, worst
// region 1.6%; the old budget's mesh (the control) is off by 15% in a region.
constexpr double kHeavyMeshMean = 0.02, kHeavyMeshRegion = 0.05;

TEST_CASE("a mesh with more triangles than the element budget: radiosity per bounce within 2% (mean) and 5% (4x4 regions) of path; control: the old budget's mesh of that scene (patch size 1e6, walls of two patches) fails the same check" *
          doctest::test_suite("statistical")) {
    SUBCASE("a mesh with more triangles than the element budget: radiosity per bounce within 2% (mean) and 5% (4x4 regions) of path") {
        const BounceErrors errors = bounceErrors(renderBounces(heavyMesh(), "radiosity", 16, {}), pathTracedHeavyMesh());
        CAPTURE(errors.mean);
        CAPTURE(errors.region);
        CHECK(errors.mean < kHeavyMeshMean);
        CHECK(errors.region < kHeavyMeshRegion);
    }
    SUBCASE("control: the old budget's mesh of that scene (patch size 1e6, walls of two patches) fails the same check") {
        RadiosityOptions options;
        options.patchSize = 1e6f;
        const BounceErrors errors = bounceErrors(renderBounces(heavyMesh(), "radiosity", 16, options), pathTracedHeavyMesh());
        CAPTURE(errors.mean);
        CAPTURE(errors.region);
        CHECK((errors.mean > kHeavyMeshMean || errors.region > kHeavyMeshRegion));
    }
}

// Issue 27's open scene: a floor and a wall as infinite planes (tests/render/data/open-planes.toml).
Scene openPlanes() { return loadScene(LIGHTPATH_SOURCE_DIR "/tests/render/data/open-planes.toml"); }

const Film& pathTracedOpenPlanes() {
    static const Film film = renderBounces(openPlanes(), "path", 8192, {});
    return film;
}

// Issue 27's bar, 2% in the mean and 5% per 4x4 region, at the default settings: the planes are
// cut into rings beyond the scene, and refinement resolves the line where the floor and the wall
// meet. Measured: mean 0.14%, worst region 1.9%. Clipped to the scene (the control), the
// light from beyond it is lost: 39% low in the mean.
constexpr double kOpenPlanesMean = 0.02, kOpenPlanesRegion = 0.05;

TEST_CASE("infinite planes: radiosity per bounce within 2% (mean) and 5% (4x4 regions) of path (rings, not clipped); control: the same planes clipped to the scene (no rings) fail the same check" *
          doctest::test_suite("statistical")) {
    SUBCASE("infinite planes: radiosity per bounce within 2% (mean) and 5% (4x4 regions) of path (rings, not clipped)") {
        const BounceErrors errors = bounceErrors(renderBounces(openPlanes(), "radiosity", 16, {}), pathTracedOpenPlanes());
        CAPTURE(errors.mean);
        CAPTURE(errors.region);
        CHECK(errors.mean < kOpenPlanesMean);
        CHECK(errors.region < kOpenPlanesRegion);
    }
    SUBCASE("control: the same planes clipped to the scene (no rings) fail the same check") {
        RadiosityOptions clipped;
        clipped.planeRings = 0;
        const BounceErrors errors = bounceErrors(renderBounces(openPlanes(), "radiosity", 16, clipped), pathTracedOpenPlanes());
        CAPTURE(errors.mean);
        CAPTURE(errors.region);
        CHECK((errors.mean > kOpenPlanesMean || errors.region > kOpenPlanesRegion));
    }
}

// Refinement (issue 27): the error estimate cuts patches where the light changes faster than they
// resolve. scenes/cornell-original.toml at 64 x 64: the lights radiosity solves (its ambient term
// and black background are no light of radiosity's), against the path tracer at 1024 spp. On 4096
// first elements refined in three rounds and read at the camera's hit (classicCoarseMesh) the
// worst 4 x 4 region over the four bounces is 1.9% (mean 0.4%); the uniform mesh at the same first
// budget, unrefined, is 6.3% off in a region (the floor in front of the short block, bounces 2-4).
constexpr const char* kRadiosityLights = "(<L.[^'ambient']>|O)";

Scene cornellOriginal64() {
    Scene scene = loadScene(LIGHTPATH_SOURCE_DIR "/scenes/cornell-original.toml");
    scene.camera.width = scene.camera.height = 64;
    return scene;
}

// The mesh the refinement and reconstruction tests below measure on: 4096 first elements refined in
// three rounds (the defaults before the final gather's finer first mesh, RadiosityOptions). On the
// default mesh their controls' errors fall within the bars too, so the controls would not fail.
RadiosityOptions coarseMesh() {
    RadiosityOptions options;
    options.patchBudget = 4096;
    options.refineRounds = 3;
    return options;
}

// The mesh itself, read at the camera's hit (no final gather, which would average its error away).
RadiosityOptions classicCoarseMesh() {
    RadiosityOptions options = coarseMesh();
    options.finalGather = 0;
    return options;
}

const Film& pathTracedCornellBounces() {
    static const Film film = renderBounces(cornellOriginal64(), "path", 1024, {}, kRadiosityLights);
    return film;
}

TEST_CASE("refined radiosity: every bounce of the Cornell box within 2% (mean) and 5% (4x4 regions) of path; control: the same box without refinement (the first mesh alone) fails the 5% region bound" *
          doctest::test_suite("statistical")) {
    SUBCASE("refined radiosity: every bounce of the Cornell box within 2% (mean) and 5% (4x4 regions) of path") {
        const BounceErrors errors =
            bounceErrors(renderBounces(cornellOriginal64(), "radiosity", 16, classicCoarseMesh(), kRadiosityLights), pathTracedCornellBounces());
        CAPTURE(errors.mean);
        CAPTURE(errors.region);
        CHECK(errors.mean < 0.02);
        CHECK(errors.region < 0.05);
    }
    SUBCASE("control: the same box without refinement (the first mesh alone) fails the 5% region bound") {
        RadiosityOptions uniform = classicCoarseMesh();
        uniform.refineRounds = 0;
        const BounceErrors errors =
            bounceErrors(renderBounces(cornellOriginal64(), "radiosity", 16, uniform, kRadiosityLights), pathTracedCornellBounces());
        CAPTURE(errors.mean);
        CAPTURE(errors.region);
        CHECK(errors.region > 0.05);
    }
}

// The noise-aware refinement criterion (issue 27): a patch is cut where its vertex radiosities
// differ from its own by over the tolerance AND by more than RadiosityOptions::refineNoiseSigmas
// standard deviations of its sampling noise. A 2 x 2 floor under a point light 6 above it, a
// 0.6 x 0.6 blocker half-way up casting a sharp shadow [0.4, 1.6]^2 on the floor, patch size 0.25
// (edges of the shadow inside patches). The light changes fast only at the shadow's edge (the
// lamp's cos^3 / d^2 falloff moves a vertex value by at most 2% of a patch's): refinement must cut
// there (beside every point of the outline) and nowhere else on the floor. A hard edge is never resolved by linear patches, and a
// long edge across a small floor asks for more than the 4x element cap, so the warning must say so
// (a real discontinuity remains). The floor's later bounces (from the blocker's underside,
// reached by a fifth of the form-factor rays under it) are noisy by about 12% a patch; the
// noise-blind criterion cuts them too.
constexpr float kShadowLow = 0.4f, kShadowHigh = 1.6f, kShadowPatch = 0.25f;

Scene sharpShadowScene() {
    Scene scene;
    const auto grey = test::addMaterial(scene, diffuse("grey", 0.5f));
    const auto floor = test::addObject(scene, "floor", grey);
    addQuad(scene, floor, {0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0});
    const auto blocker = test::addObject(scene, "blocker", grey);
    addQuad(scene, blocker, {0.7f, 0.7f, 3.0f}, {0.7f, 1.3f, 3.0f}, {1.3f, 1.3f, 3.0f}, {1.3f, 0.7f, 3.0f});
    scene.lights.push_back(PointLight{"lamp", {1.0f, 1.0f, 6.0f}, Rgb{36.0f}});
    scene.camera = test::centredCamera({1.0f, -3.0f, 4.0f}, {1.0f, 1.0f, 0.0f}, {0, 0, 1}, 16);
    return scene;
}

// Distance from a floor point to the shadow's outline.
float distanceToShadowEdge(Vec3 p) {
    const float dx = std::max({kShadowLow - p.x, 0.0f, p.x - kShadowHigh});
    const float dy = std::max({kShadowLow - p.y, 0.0f, p.y - kShadowHigh});
    if (dx > 0.0f || dy > 0.0f) return std::sqrt(dx * dx + dy * dy);
    return std::min({p.x - kShadowLow, kShadowHigh - p.x, p.y - kShadowLow, kShadowHigh - p.y});
}

struct FloorRefinement {
    int cutFarFromEdge = 0;  // floor patches below a cut farther than a first patch's diagonal from the edge
    int edgePointsRefined = 0, edgePoints = 0;  // points of the outline with a cut patch beside them
    bool warned = false;     // the cap stopped refinement, and the warning said so
};

FloorRefinement floorRefinement(const RadiosityOptions& options) {
    const Solved solved(sharpShadowScene(), options, 4);
    const auto& patches = solved.radiosity.mesh().patches();
    FloorRefinement result;
    result.warned = solved.radiosity.stats().unresolved.find("refinement stopped") != std::string::npos;
    for (const RadiosityPatch& p : patches)
        if (p.object == 0 && p.level > 0 && distanceToShadowEdge((p.a + p.b + p.c) / 3.0f) > kShadowPatch * std::sqrt(2.0f))
            ++result.cutFarFromEdge;
    // Points along two sides of the outline: a cut patch (its centroid within a first patch's
    // edge of the point) must lie beside each.
    for (int i = 0; i < 16; ++i) {
        const float t = kShadowLow + (kShadowHigh - kShadowLow) * (float(i) + 0.5f) / 16.0f;
        for (const Vec3 point : {Vec3{kShadowLow, t, 0.0f}, Vec3{t, kShadowHigh, 0.0f}}) {
            ++result.edgePoints;
            for (const RadiosityPatch& p : patches)
                if (p.object == 0 && p.level > 0 && glm::length((p.a + p.b + p.c) / 3.0f - point) < kShadowPatch) {
                    ++result.edgePointsRefined;
                    break;
                }
        }
    }
    return result;
}

RadiosityOptions sharpShadowOptions() {
    RadiosityOptions options;
    options.patchSize = kShadowPatch;
    options.refineRounds = 3;  // the default two rounds stop short of the cap on this floor
    return options;
}

TEST_CASE("noise-aware refinement: a sharp shadow's edge is cut, nothing away from it, and the cap's warning says so") {
    const FloorRefinement refined = floorRefinement(sharpShadowOptions());
    CAPTURE(refined.edgePointsRefined);
    CHECK(refined.cutFarFromEdge == 0);
    CHECK(refined.edgePointsRefined == refined.edgePoints);
    CHECK(refined.warned);
}

TEST_CASE("control: the noise-blind criterion cuts the floor away from the shadow's edge too") {
    RadiosityOptions blind = sharpShadowOptions();
    blind.refineNoiseSigmas = 0.0;
    const FloorRefinement refined = floorRefinement(blind);
    CAPTURE(refined.cutFarFromEdge);
    CHECK(refined.edgePointsRefined == refined.edgePoints);
    CHECK(refined.cutFarFromEdge > 0);
}

// Jacobi's tolerance (issue 27), on scenes/lecture-room.toml (1024 uniform elements): a bounce
// that adds less than 1e-4 of the light so far of the outputs that receive it ends the solve. In an open scene most light leaves for the sky, so
// against all the light (ED*L alone, as every request was measured before) the solve stops early;
// an output of its own for ED{4,}L must get every bounce up to --max-depth, as the path tracer's
// does (the lecture room's ED{4,}L was 29% low: bounces 5 and 6 dropped).
// Under the sanitizers the room is solved without its bunny: the bunny's 70k triangles made 90% of
// the preprocess (eight burial rays each, RadiosityMesh::buriedTriangles; the budget-warning CLI
// tests still run that there), and the open room's walls and sky decide both checks (4 and 6
// iterations, with the bunny and without, in Release too).
Scene toleranceRoom() {
    constexpr const char* path = LIGHTPATH_SOURCE_DIR "/scenes/lecture-room.toml";
    if (!test::kSanitized) return loadScene(path);
    std::ifstream file(path);
    std::stringstream text;
    text << file.rdbuf();
    std::string toml = text.str();
    const std::size_t bunny = toml.find("[[meshes]]"), next = toml.find("[[", bunny + 2);
    REQUIRE(bunny != std::string::npos);
    REQUIRE(next != std::string::npos);
    toml.erase(bunny, next - bunny);
    return loadSceneFromText(toml, path);
}

int iterationsSolved(std::vector<lpe::NamedExpression> outputs) {
    RadiosityOptions options;
    options.patchBudget = 1024;
    options.refineRounds = 0;
    test::RenderWorld world(toleranceRoom(), std::move(outputs), kBounceDepth, options, 2);
    RadiosityIntegrator radiosity;
    radiosity.preprocess(world.context);
    return radiosity.stats().iterations;
}

TEST_CASE("an open scene's ED{4,}L output gets every bounce up to the depth") {
    CHECK(iterationsSolved({{"b1", "EDL"}, {"b2", "EDDL"}, {"b3", "EDDDL"}, {"b4", "ED{4,}L"}}) == kBounceDepth);
}

TEST_CASE("control: against all the light (ED*L alone) the same scene's solve stops before the depth") {
    CHECK(iterationsSolved({{"all", "ED*L"}}) < kBounceDepth);
}

// split()'s quadtree: every point of a cut triangle is found in the leaf that holds it, with
// weights that rebuild it from the leaf's corners; areas add up; the leaves are their own clusters.
TEST_CASE("radiosity mesh refinement: a cut patch's leaves tile it and lookup finds the leaf under a point") {
    Scene scene;
    const auto m = test::addMaterial(scene, diffuse("grey", 0.5f));
    const auto floor = test::addObject(scene, "floor", m);
    addQuad(scene, floor, {0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0});
    scene.lights.push_back(PointLight{"lamp", {1.0f, 1.0f, 1.0f}, Rgb{1.0f}});
    const test::RenderWorld world(scene);
    // Patch size 1.5: each triangle (legs 2) is cut 2 x 2, four patches of its own (not clustered).
    RadiosityMesh mesh(world.scene, world.geometry, 1.5f, 0);
    REQUIRE(mesh.patches().size() == 8);
    float total = 0.0f;
    for (const RadiosityPatch& p : mesh.patches()) total += p.area;
    // Cut the first patch (its children 8, 9, 10 appended, 10 the middle one), then the middle
    // child, then a corner child of that: three levels.
    const std::uint32_t first[] = {0};
    mesh.split(first);
    REQUIRE(mesh.patches().size() == 11);
    const std::uint32_t middle[] = {10};
    mesh.split(middle);
    const std::uint32_t corner[] = {11};
    mesh.split(corner);
    CHECK(mesh.patches().size() == 17);
    CHECK(mesh.clusters().size() == 17);
    float area = 0.0f;
    for (const RadiosityPatch& p : mesh.patches()) {
        area += p.area;
        CHECK(mesh.clusters()[p.cluster].memberCount == 1);
    }
    CHECK(area == doctest::Approx(total).epsilon(1e-5));
    CHECK(mesh.patches()[11].level == 3);
    CHECK(mesh.patches()[1].level == 0);
    Pcg32 rng(7, 1);
    for (int i = 0; i < 2000; ++i) {
        SurfaceHit hit;
        hit.point = Vec3{2.0f * rng.nextFloat(), 2.0f * rng.nextFloat(), 0.0f};
        hit.normal = Vec3{0, 0, 1};
        hit.primitive = world.geometry.triangleId(hit.point.x >= hit.point.y ? 0u : 1u);
        const auto found = mesh.lookup(hit);
        REQUIRE(found);
        const RadiosityPatch& p = mesh.patches()[found->patch];
        const Vec3 rebuilt = found->weights[0] * p.a + found->weights[1] * p.b + found->weights[2] * p.c;
        CAPTURE(i);
        CHECK(glm::length(rebuilt - hit.point) < 1e-4f);
        for (int k = 0; k < 3; ++k) CHECK(found->weights[k] >= -1e-5f);
    }
}

// Buried triangles (issue 27): a box of small triangles half sunk into an infinite floor, lit from
// above. At patch size 0.75 the sides' clusters by the floor line (the plane y = 0.5, a line of the
// box's grid) span it, in cluster cells of half the patch size ([0.375, 0.75)) as of the whole
// ([0, 0.75)), so clustered together the buried triangles, which no light reaches, darken the
// visible ones beside them; RadiosityMesh::buriedTriangles keeps them apart. Measured on the box's
// own pixels (E<.D'box'>D{k-1}L), bounces 1 and 2, against the path tracer at 1024 spp: the worst
// of the two 2.0% off apart, 18.5% together.
constexpr float kSunkFloor = 0.5f;

// A cells x cells grid of quads of two triangles from `corner` along `u` and `v` (normal u x v).
void addGridQuad(Scene& scene, std::uint32_t object, Vec3 corner, Vec3 u, Vec3 v, int cells) {
    for (int j = 0; j < cells; ++j)
        for (int i = 0; i < cells; ++i) {
            const Vec3 a = corner + u * (float(i) / float(cells)) + v * (float(j) / float(cells));
            addQuad(scene, object, a, a + u / float(cells), a + (u + v) / float(cells), a + v / float(cells));
        }
}

Scene sunkBoxScene() {
    Scene scene;
    const auto grey = test::addMaterial(scene, diffuse("grey", 0.5f));
    const auto clay = test::addMaterial(scene, diffuse("clay", 0.7f));
    test::addPlane(scene, "floor", grey, {0, kSunkFloor, 0}, {0, 1, 0});
    const auto box = test::addObject(scene, "box", clay);
    // The unit box [-0.5, 0.5] x [0, 1] x [-0.5, 0.5], outward normals, 8 x 8 quads a side.
    const Vec3 x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
    const Vec3 low{-0.5f, 0.0f, -0.5f}, high{0.5f, 1.0f, 0.5f};
    addGridQuad(scene, box, low, z, x, 8);                      // bottom, -y
    addGridQuad(scene, box, {low.x, high.y, low.z}, x, z, 8);   // top, +y
    addGridQuad(scene, box, low, x, y, 8);                      // back, -z
    addGridQuad(scene, box, {low.x, low.y, high.z}, y, x, 8);   // front, +z
    addGridQuad(scene, box, low, y, z, 8);                      // left, -x
    addGridQuad(scene, box, {high.x, low.y, low.z}, z, y, 8);   // right, +x
    scene.lights.push_back(PointLight{"lamp", {0.8f, 3.0f, 1.6f}, Rgb{12.0f}});
    scene.camera = test::centredCamera({0.9f, 1.8f, 3.2f}, {0.0f, 0.75f, 0.0f}, {0, 1, 0}, 25);
    return scene;
}

Film renderSunkBox(const std::string& integrator, int spp, const RadiosityOptions& radiosity) {
    return renderAovs(sunkBoxScene(), {{"b1", "E<.D'box'>L"}, {"b2", "E<.D'box'>DL"}}, integrator, spp, 2, radiosity);
}

// The worst relative error of the box's light over its pixels, of bounces 1 and 2.
double sunkBoxError(const RadiosityOptions& options) {
    static const Film path = renderSunkBox("path", 1024, {});
    const Film radiosity = renderSunkBox("radiosity", 4, options);
    double worst = 0.0;
    for (std::size_t layer = 0; layer < 2; ++layer) {
        const double expected = layerTotal(path, layer);
        REQUIRE(expected > 0.0);
        worst = std::max(worst, relativeError(layerTotal(radiosity, layer), expected));
    }
    return worst;
}

// Read at the camera's hit (no final gather, whose direct light per pixel and gather would hide
// what the clustering does to the solution).
RadiosityOptions sunkBoxOptions() {
    RadiosityOptions options;
    options.patchSize = 0.75f;
    options.finalGather = 0;
    return options;
}

constexpr double kSunkBoxTolerance = 0.05;

TEST_CASE("radiosity of buried triangles: a box half sunk into the floor shows the path tracer's light, bounces 1 and 2 within 5%; control: radiosity of the same box with buried and exposed triangles clustered together fails the same check" *
          doctest::test_suite("statistical")) {
    SUBCASE("radiosity of buried triangles: a box half sunk into the floor shows the path tracer's light, bounces 1 and 2 within 5%") {
        const RadiosityOptions options = sunkBoxOptions();
        const Solved solved(sunkBoxScene(), options, 2);
        std::size_t clustered = 0;
        for (const RadiosityCluster& c : solved.radiosity.mesh().clusters()) clustered += c.memberCount > 1 ? 1 : 0;
        CHECK(clustered > 0);  // the box's triangles are clustered: the case the fix is about
        const double error = sunkBoxError(options);
        CAPTURE(error);
        CHECK(error < kSunkBoxTolerance);
    }
    SUBCASE("control: radiosity of the same box with buried and exposed triangles clustered together fails the same check") {
        RadiosityOptions together = sunkBoxOptions();
        together.separateBuried = false;
        // Cutting clusters (RadiosityOptions::refineClusters) separates the mixed ones too, where the
        // error estimate sees their parts differ (the control's error 3.0% with it): off, so this
        // control measures the clustering rule alone, as it was measured (18.5%).
        together.refineClusters = false;
        const double error = sunkBoxError(together);
        CAPTURE(error);
        CHECK(error > kSunkBoxTolerance);
    }
}

// Planes cut at contact lines (issue 27): a floor plane and a wall standing on it along x = 0.9
// (two triangles, y from 0 to 2, z from -1.3 to 1.7: neither line is a patch boundary at size
// 0.7). With the cut, no floor patch of the rectangle over the scene straddles the wall's line or
// the line where the floor meets the back-wall plane z = -1.3; without it (the control) patches do.
int floorPatchesStraddling(bool cutPlanes) {
    Scene scene;
    const auto m = test::addMaterial(scene, diffuse("grey", 0.5f));
    test::addPlane(scene, "floor", m, {0, 0, 0}, {0, 1, 0});
    test::addPlane(scene, "back", m, {0, 0, -1.3f}, {0, 0, 1});
    const auto wall = test::addObject(scene, "wall", m);
    addQuad(scene, wall, {0.9f, 0, -1.3f}, {0.9f, 0, 1.7f}, {0.9f, 2, 1.7f}, {0.9f, 2, -1.3f});
    scene.lights.push_back(PointLight{"lamp", {0.0f, 1.5f, 0.0f}, Rgb{1.0f}});
    scene.camera = test::centredCamera({0.0f, 1.0f, 3.0f}, {0.0f, 0.5f, 0.0f}, {0, 1, 0}, 9);
    const test::RenderWorld world(scene);
    const RadiosityMesh mesh(world.scene, world.geometry, 0.7f, 3, {}, cutPlanes);
    int straddling = 0;
    for (const RadiosityPatch& p : mesh.patches()) {
        // The rectangle over the scene spans about x in [-2.4, 3.3], z in [-3.7, 5.4] (the bounds of
        // the wall, lamp and eye grown by half their diagonal); the rings beyond are not cut.
        const Vec3 centroid = (p.a + p.b + p.c) / 3.0f;
        if (p.object != 0 || centroid.x < -2.0f || centroid.x > 3.0f || centroid.z < -3.5f || centroid.z > 5.0f) continue;
        for (const auto& [axis, at] : {std::pair{0, 0.9f}, std::pair{2, -1.3f}}) {
            const float da = p.a[axis] - at, db = p.b[axis] - at, dc = p.c[axis] - at;
            constexpr float kOn = 1e-4f;
            const bool below = da < -kOn || db < -kOn || dc < -kOn, above = da > kOn || db > kOn || dc > kOn;
            if (below && above) ++straddling;
        }
    }
    return straddling;
}

// The least-squares gradient of the later bounces' gather (radiosity_gradients.h) on a flat quad
// of 128 patches, against a linear light written out here: the centroid's value of a linear field
// is its mean over the triangle, so a patch's value and its neighbours' say the field exactly, and
// every corner of every fitted patch must show the field there. A field steep enough to fall
// below 0 inside some patches is limited: no corner negative, the corners' mean (the triangle's
// mean) still the patch's own value.
TEST_CASE("radiosity's gradient gather: a linear light is reconstructed exactly at every corner; a steep one is kept non-negative with its mean") {
    Scene scene;
    const auto grey = test::addMaterial(scene, diffuse("grey", 0.5f));
    const auto floor = test::addObject(scene, "floor", grey);
    addQuad(scene, floor, {0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0});
    const test::RenderWorld world(scene);
    const RadiosityMesh mesh(world.scene, world.geometry, 0.36f, 0);  // 8 x 8 sub-triangles each
    const PatchGradients gradients(mesh);
    const auto& patches = mesh.patches();
    REQUIRE(patches.size() == 128);
    CHECK(gradients.fittable() == patches.size());
    const auto field = [](const Vec3& p, float slope) { return Rgb{1.0f + slope * p.x, 2.0f - 0.5f * p.y, 0.5f}; };
    const auto valuesOf = [&](float slope) {
        std::vector<Rgb> values(2 * mesh.clusters().size(), Rgb{0.0f});  // the back sides unlit
        for (const RadiosityPatch& p : patches) values[2 * p.cluster] = field((p.a + p.b + p.c) / 3.0f, slope);
        return values;
    };
    std::vector<std::array<Rgb, 3>> corners;
    std::vector<std::uint8_t> fitted;
    SUBCASE("linear") {
        gradients.fit(valuesOf(0.3f), corners, fitted);
        float worst = 0.0f;
        for (std::uint32_t p = 0; p < patches.size(); ++p) {
            REQUIRE(fitted[2 * p] == 1);
            REQUIRE(fitted[2 * p + 1] == 1);
            const Vec3 at[3] = {patches[p].a, patches[p].b, patches[p].c};
            for (int v = 0; v < 3; ++v) {
                worst = std::max(worst, maxComponent(glm::abs(corners[2 * p][v] - field(at[v], 0.3f))));
                CHECK(isBlack(corners[2 * p + 1][v]));
            }
        }
        CAPTURE(worst);
        CHECK(worst < 1e-4f);
    }
    SUBCASE("steep: limited") {
        // Red 1 - x / 1.96: positive at every centroid (the last at x = 2 - 0.25 / 3), negative at x = 2.
        const float slope = -1.0f / 1.96f;
        const std::vector<Rgb> values = valuesOf(slope);
        gradients.fit(values, corners, fitted);
        float lowest = 1.0f, worstMean = 0.0f;
        int limited = 0;
        for (std::uint32_t p = 0; p < patches.size(); ++p) {
            const Rgb mean = (corners[2 * p][0] + corners[2 * p][1] + corners[2 * p][2]) / 3.0f;
            worstMean = std::max(worstMean, maxComponent(glm::abs(mean - values[2 * patches[p].cluster])));
            const Vec3 at[3] = {patches[p].a, patches[p].b, patches[p].c};
            for (int v = 0; v < 3; ++v) {
                lowest = std::min(lowest, corners[2 * p][v].r);
                if (field(at[v], slope).r < 0.0f) ++limited;
            }
        }
        CAPTURE(lowest);
        CAPTURE(worstMean);
        CHECK(limited > 0);
        CHECK(lowest >= 0.0f);
        CHECK(worstMean < 1e-5f);
    }
}

TEST_CASE("radiosity mesh: a plane is cut where a wall and another plane meet it, so no patch straddles the line") {
    CHECK(floorPatchesStraddling(true) == 0);
}

TEST_CASE("control: radiosity mesh of the same plane uncut has patches straddling those lines") {
    CHECK(floorPatchesStraddling(false) > 0);
}


// Clusters cut by refinement (issue 27): a dense slab (12,288 small triangles, a 32 x 32 grid of
// quads a face) in a closed room (black but its ceiling), a black square hung between it and a point light casting a sharp
// shadow across its top. At patch size 0.5 the top's triangles are clustered in cells of 0.25,
// which the shadow's edges cross: solved as one element, a cluster shows the mean of its lit and
// shadowed triangles, so the 4 x 4 regions along the edges are off. Refinement cuts the clusters
// the error estimate flags (RadiosityMesh::splitClusters, radiosity.cpp, clustersToRefine) towards
// their triangles. Measured on the slab's own pixels per bounce (E<.D'slab'>D{k-1}L, k = 1..4)
// against the path tracer at 1024 spp: worst 4 x 4 region 0.19 (0.28 under unscaled Gouraud; the
// shadow's edge at bounce 1, across the triangles that straddle it), mean 2.2%; clusters never cut
// (the control) 0.51. Issue 27's 5% per region is NOT met by a hard shadow's edge on triangles of
// this size; the test holds what cutting clusters buys.
constexpr float kSlabLow = 0.05f, kSlabHigh = 0.25f;

Scene shadowedSlabScene() {
    Scene scene;
    const auto grey = test::addMaterial(scene, diffuse("grey", 0.7f));
    const auto clay = test::addMaterial(scene, diffuse("clay", 0.7f));
    const auto black = test::addMaterial(scene, diffuse("black", 0.0f));
    // Only the ceiling reflects besides the slab, so the refinement's element cap goes to the slab.
    const auto room = test::addObject(scene, "room", black);
    const auto ceiling = test::addObject(scene, "ceiling", grey);
    const Vec3 lo{-1.5f, 0.0f, -1.5f}, hi{1.5f, 3.0f, 2.5f};
    addQuad(scene, room, {lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, lo.y, hi.z}, {lo.x, lo.y, hi.z});  // floor
    addQuad(scene, ceiling, {lo.x, hi.y, lo.z}, {lo.x, hi.y, hi.z}, {hi.x, hi.y, hi.z}, {hi.x, hi.y, lo.z});
    addQuad(scene, room, {lo.x, lo.y, lo.z}, {lo.x, hi.y, lo.z}, {hi.x, hi.y, lo.z}, {hi.x, lo.y, lo.z});  // back
    addQuad(scene, room, {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z});  // front
    addQuad(scene, room, {lo.x, lo.y, lo.z}, {lo.x, lo.y, hi.z}, {lo.x, hi.y, hi.z}, {lo.x, hi.y, lo.z});  // left
    addQuad(scene, room, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {hi.x, hi.y, hi.z}, {hi.x, lo.y, hi.z});  // right
    const auto slab = test::addObject(scene, "slab", clay);
    const Vec3 x{2, 0, 0}, y{0, kSlabHigh - kSlabLow, 0}, z{0, 0, 2};
    const Vec3 a{-1.0f, kSlabLow, -1.0f}, b{1.0f, kSlabHigh, 1.0f};
    addGridQuad(scene, slab, a, x, z, 32);                      // bottom
    addGridQuad(scene, slab, {a.x, b.y, a.z}, z, x, 32);        // top
    addGridQuad(scene, slab, a, y, x, 32);                      // back
    addGridQuad(scene, slab, {a.x, a.y, b.z}, x, y, 32);        // front
    addGridQuad(scene, slab, a, z, y, 32);                      // left
    addGridQuad(scene, slab, {b.x, a.y, a.z}, y, z, 32);        // right
    const auto blocker = test::addObject(scene, "blocker", black);
    addQuad(scene, blocker, {-0.3f, 0.8f, -0.3f}, {0.3f, 0.8f, -0.3f}, {0.3f, 0.8f, 0.3f}, {-0.3f, 0.8f, 0.3f});
    scene.lights.push_back(PointLight{"lamp", {0.05f, 2.0f, -0.8f}, Rgb{8.0f}});
    scene.camera = test::centredCamera({0.0f, 2.6f, 1.9f}, {0.0f, kSlabHigh, 0.1f}, {0, 1, 0}, 33);
    return scene;
}

Film renderShadowedSlab(const std::string& integrator, int spp, const RadiosityOptions& radiosity) {
    return renderAovs(shadowedSlabScene(),
                      {{"b1", "E<.D'slab'>L"}, {"b2", "E<.D'slab'>DL"}, {"b3", "E<.D'slab'>DDL"}, {"b4", "E<.D'slab'>DDDL"}},
                      integrator, spp, 4, radiosity);
}

BounceErrors shadowedSlabErrors(const RadiosityOptions& options) {
    static const Film path = renderShadowedSlab("path", 1024, {});
    return bounceErrors(renderShadowedSlab("radiosity", 4, options), path);
}

// The solution read at the camera's hit (no final gather): what the mesh resolves is what this
// measures, and a gather would average it over the hemisphere.
RadiosityOptions shadowedSlabOptions() {
    RadiosityOptions options;
    options.patchSize = 0.5f;
    options.finalGather = 0;
    return options;
}

constexpr double kSlabMean = 0.03, kSlabRegion = 0.35;

TEST_CASE("radiosity cluster refinement: a dense slab's shadow edges, every bounce within 3% (mean) and 35% (4x4 regions) of path; control: radiosity of the same slab with clusters never cut fails the same check" *
          doctest::test_suite("statistical")) {
    SUBCASE("radiosity cluster refinement: a dense slab's shadow edges, every bounce within 3% (mean) and 35% (4x4 regions) of path") {
        const RadiosityOptions options = shadowedSlabOptions();
        const Solved solved(shadowedSlabScene(), options, 4);
        CHECK(solved.radiosity.stats().clustersCut > 0);  // the slab's clusters were cut: the case this is about
        const BounceErrors errors = shadowedSlabErrors(options);
        CAPTURE(errors.mean);
        CAPTURE(errors.region);
        CHECK(errors.mean < kSlabMean);
        CHECK(errors.region < kSlabRegion);
    }
    SUBCASE("control: radiosity of the same slab with clusters never cut fails the same check") {
        RadiosityOptions uncut = shadowedSlabOptions();
        uncut.refineClusters = false;
        const BounceErrors errors = shadowedSlabErrors(uncut);
        CAPTURE(errors.mean);
        CAPTURE(errors.region);
        CHECK((errors.mean > kSlabMean || errors.region > kSlabRegion));
    }
}


// The display (issue 27): Gouraud shows over a patch the mean of its vertex values, each the mean of
// the patches around the vertex, so a patch beside a steep change shows its neighbours' light.
// The smooth display scales each element's interpolation towards its own mean where the two differ
// by more than the element's noise (RadiosityIntegrator::computeDisplayScale). scenes/taxonomy.toml
// at 64 x 64 (radiosity's lights, path at 1024 spp), the direct light EDL, whose shadows' edges
// and the balls' contacts Gouraud blurs. Later bounces' elements are too noisy (16 form-factor rays
// each) for the correction to pass the noise test, and stay Gouraud's (docs/integrators.md).
// Measured: worst region 3.5% (mean 1.2%); unscaled Gouraud 9.3%, the control.
constexpr double kContactMean = 0.02, kContactRegion = 0.05;

Scene taxonomy64() {
    Scene scene = loadScene(LIGHTPATH_SOURCE_DIR "/scenes/taxonomy.toml");
    scene.camera.width = scene.camera.height = 64;
    return scene;
}

// EDL alone is rendered: with no later bounce requested, the path tracer stops at the first and
// radiosity solves the direct light only.
Film directLight(const std::string& integrator, int spp, const RadiosityOptions& options) {
    return renderAovs(taxonomy64(), {{"b1", std::string("ED") + kRadiosityLights}}, integrator, spp, kBounceDepth, options);
}

BounceErrors contactErrors(RadiosityDisplay display) {
    static const Film path = directLight("path", 1024, {});
    RadiosityOptions options;
    options.display = display;
    options.finalGather = 0;  // the display is what this measures: the final gather computes EDL per pixel
    return bounceErrors(directLight("radiosity", 16, options), path, 1);
}

TEST_CASE("radiosity's smooth display: the direct light's shadows and contacts within 2% (mean) and 5% (4x4 regions) of path; control: the same solve shown by unscaled Gouraud fails the same check" *
          doctest::test_suite("statistical")) {
    SUBCASE("radiosity's smooth display: the direct light's shadows and contacts within 2% (mean) and 5% (4x4 regions) of path") {
        const BounceErrors errors = contactErrors(RadiosityDisplay::Smooth);
        CAPTURE(errors.mean);
        CAPTURE(errors.region);
        CHECK(errors.mean < kContactMean);
        CHECK(errors.region < kContactRegion);
    }
    SUBCASE("control: the same solve shown by unscaled Gouraud fails the same check") {
        const BounceErrors errors = contactErrors(RadiosityDisplay::Gouraud);
        CAPTURE(errors.mean);
        CAPTURE(errors.region);
        CHECK((errors.mean > kContactMean || errors.region > kContactRegion));
    }
}

// Issue 27's bar on the lecture's scenes: every bounce within 2% (mean) and 5% (4x4 regions) of the
// path tracer. Read from the solution at the camera's hit, bounce 2 was off by a quarter in places
// (a ball's underside, the floor beside a contact: a patch's value averages a light that changes
// across it); the final gather (RadiosityOptions::finalGather) averages the solution over the hit's
// hemisphere instead, so the mesh's error reaches the image only through that average.
// The references are frozen: per bounce, the image's luminance sum and its 4x4 regions' sums
// (row by row), the mean of eight path renders `lightpath render SCENE --integrator path --resolution
// 64x64 --max-depth 6 --spp 2048 --seed 0..7 --sampler sobol` with the four bounces' AOVs, as
// bench/radiosity_bounces.py makes them. 0: a region not judged (under a twentieth of an average
// region's light, or the eight renders' standard error over 1.25% of it).
struct FrozenBounces {
    const char* scene;
    std::array<double, 4> total;
    std::array<std::array<double, 16>, 4> regions;
};

constexpr std::array<FrozenBounces, 2> kFrozenBounces{{
    {"szymczak-one-light",
     {784.252, 56.7007, 7.69778, 1.75455},
     {{{0, 0, 0, 0, 32.6806, 44.3618, 33.4845, 25.6409, 56.3629, 64.1667, 78.0736, 27.2077, 117.274, 110.475, 108.394, 86.0639},
       {0, 0, 0, 0, 2.4397, 2.77752, 2.73991, 1.49963, 8.39496, 6.92097, 12.977, 7.13301, 1.0608, 1.83128, 6.52412, 2.40185},
       {0, 0, 0, 0, 0.0490414, 0.187261, 0.202293, 0.0465377, 1.33391, 1.98355, 1.35899, 0.643995, 0.283231, 0.368143,
        0.784057, 0.456772},
       {0, 0, 0, 0, 0, 0, 0.0619231, 0, 0.383734, 0.479668, 0.412166, 0.171481, 0, 0, 0, 0}}}},
    {"taxonomy",
     {336.865, 37.4376, 5.55527, 1.88177},
     {{{5.18202, 12.8772, 12.877, 5.18198, 10.8552, 22.3754, 26.0198, 13.0106, 15.9778, 32.4143, 17.2363, 12.6635, 36.7517,
        42.8859, 40.2497, 30.3071},
       {2.70209, 3.47957, 3.96934, 3.44001, 2.99159, 3.72116, 5.10409, 4.79967, 1.41812, 1.78785, 1.16243, 1.62175, 0.326278,
        0.429999, 0.300994, 0.182695},
       {0.207516, 0.256005, 0.265423, 0.224081, 0.363933, 0.489806, 0.603495, 0.468913, 0.429989, 0.531728, 0.231968,
        0.507087, 0.276383, 0.271775, 0.21305, 0.214119},
       {0.108501, 0.12631, 0.130586, 0.121328, 0.161643, 0.201198, 0.259009, 0.232729, 0.110307, 0.132403, 0.0668785,
        0.124986, 0, 0, 0, 0}}}},
}};

constexpr double kGatherMean = 0.02, kGatherRegion = 0.05;

BounceErrors frozenBounceErrors(const FrozenBounces& frozen, const RadiosityOptions& options) {
    Scene scene = loadScene(std::string(LIGHTPATH_SOURCE_DIR "/scenes/") + frozen.scene + ".toml");
    scene.camera.width = scene.camera.height = 64;
    const Film film = renderBounces(scene, "radiosity", 64, options, kRadiosityLights);
    BounceErrors worst;
    for (std::size_t layer = 0; layer < 4; ++layer) {
        std::array<double, 16> regions{};
        double total = 0.0;
        for (int y = 0; y < 64; ++y)
            for (int x = 0; x < 64; ++x) {
                const Rgb c = film.at(layer, x, y);
                const double l = 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
                regions[std::size_t(4 * (y / 16) + x / 16)] += l;
                total += l;
            }
        worst.mean = std::max(worst.mean, std::fabs(total / frozen.total[layer] - 1.0));
        for (std::size_t r = 0; r < 16; ++r)
            if (frozen.regions[layer][r] > 0.0)
                worst.region = std::max(worst.region, std::fabs(regions[r] / frozen.regions[layer][r] - 1.0));
    }
    return worst;
}

TEST_CASE("radiosity's final gather: the lecture's scenes, every bounce within 2% (mean) and 5% (4x4 regions) of path; control: the solution read at the camera's hit fails the same check" *
          doctest::test_suite("statistical")) {
    SUBCASE("radiosity's final gather: every bounce within 2% (mean) and 5% (4x4 regions) of path") {
        for (const FrozenBounces& frozen : kFrozenBounces) {
            const std::string scene = frozen.scene;
            const BounceErrors errors = frozenBounceErrors(frozen, {});
            CAPTURE(scene);
            CAPTURE(errors.mean);
            CAPTURE(errors.region);
            CHECK(errors.mean < kGatherMean);
            CHECK(errors.region < kGatherRegion);
        }
    }
    SUBCASE("control: the solution read at the camera's hit fails the same check") {
        RadiosityOptions classic;
        classic.finalGather = 0;
        for (const FrozenBounces& frozen : kFrozenBounces) {
            const std::string scene = frozen.scene;
            const BounceErrors errors = frozenBounceErrors(frozen, classic);
            CAPTURE(scene);
            CAPTURE(errors.mean);
            CAPTURE(errors.region);
            CHECK((errors.mean > kGatherMean || errors.region > kGatherRegion));
        }
    }
}

// Later bounces gather from the light reconstructed at each form-factor ray's hit (RadiosityOptions::
// reconstructGather: the hit patch's Gouraud plane, scaled to its element's own mean), not from the
// element's constant value. With constants, a receiver that sees mostly the bright part of an
// element (a ball's underside and the floor beside its contact, a pyramid's face and the floor at
// its foot) got the element's mean, and the light between them leaked away bounce by bounce in an
// open scene. The scaled plane alone cannot rise to the peak at a contact (the plane through vertex
// means at the pyramid's foot); each triangle patch read through its least-squares gradient
// (RadiosityOptions::gatherGradients) can. On szymczak-one-light's 4096 first elements
// (coarseMesh), against the final gather's frozen eight-seed references, worst mean over the four
// bounces (worst 4x4 region): gradients 0.4% (3.9%), the plane alone 1.1% (6.8%), constant elements
// 2.6% (7.7%). The means alone no longer tell the plane from the gradients; the regions do (the
// test read ED{4,}L's mean against one 16384-spp render, whose 0.4% excess over seven more kept
// the plane's 1.2% shortfall beyond the 2% bar).
TEST_CASE("radiosity's later bounces: szymczak-one-light on 4096 first elements, every bounce within 2% (mean) and 5% (4x4 regions) of path; constant elements and the scaled Gouraud plane (the controls) fail the same check" *
          doctest::test_suite("statistical")) {
    const FrozenBounces& frozen = kFrozenBounces[0];
    REQUIRE(std::string(frozen.scene) == "szymczak-one-light");
    SUBCASE("each triangle patch read through its fitted gradient") {
        const BounceErrors errors = frozenBounceErrors(frozen, coarseMesh());
        CAPTURE(errors.mean);
        CAPTURE(errors.region);
        CHECK(errors.mean < kGatherMean);
        CHECK(errors.region < kGatherRegion);
    }
    SUBCASE("controls: constant elements, and the scaled Gouraud plane alone") {
        RadiosityOptions constant = coarseMesh(), plane = coarseMesh();
        constant.reconstructGather = false;
        plane.gatherGradients = false;
        for (const RadiosityOptions& options : {constant, plane}) {
            const BounceErrors errors = frozenBounceErrors(frozen, options);
            CAPTURE(options.reconstructGather);
            CAPTURE(errors.mean);
            CAPTURE(errors.region);
            CHECK((errors.mean > kGatherMean || errors.region > kGatherRegion));
        }
    }
}


}  // namespace
}  // namespace lightpath

namespace lightpath {
namespace {

// A lacquered floor (a GGX layer of F0 0.2 over a white base, under a polished coat) under a sun
// from the side, seen from near grazing: its base reflects c (1 - E(wo)) (1 - E(wi)) times the
// coat's (1 - E_c(wo)) (1 - E_c(wi)), darker toward the horizon and for the sun's slant.
constexpr const char* kLacquerFloor = R"(
[camera]
eye = [0, 0.8, 4]
look_at = [0, 0, -1]
fov = 50
resolution = [48, 32]
[materials.lacquer]
type = "microfacet"
base_color = 0.8
metallic = 0
roughness = 0.5
dielectric_f0 = 0.2
clearcoat = 1
clearcoat_roughness = 0
[[planes]]
name = "floor"
point = [0, 0, 0]
normal = [0, 1, 0]
material = "lacquer"
[[lights]]
type = "directional"
direction = [0.8, -0.5, 0.2]
irradiance = 3
)";

// Mean of channel means per 4 x 4 region of one layer.
std::vector<double> regionMeans(const Film& film, std::size_t layer) {
    std::vector<double> regions;
    for (int y0 = 0; y0 + 4 <= film.height(); y0 += 4)
        for (int x0 = 0; x0 + 4 <= film.width(); x0 += 4) {
            double sum = 0.0;
            for (int y = y0; y < y0 + 4; ++y)
                for (int x = x0; x < x0 + 4; ++x) {
                    const Rgb v = film.at(layer, x, y);
                    sum += (v.r + v.g + v.b) / 3.0;
                }
            regions.push_back(sum / 16.0);
        }
    return regions;
}

double worstRegionRatio(const Film& a, const Film& b) {
    const std::vector<double> ra = regionMeans(a, 0), rb = regionMeans(b, 0);
    double worst = 0.0;
    for (std::size_t i = 0; i < ra.size(); ++i)
        if (rb[i] > 0.0) worst = std::max(worst, std::abs(ra[i] / rb[i] - 1.0));
    return worst;
}

}  // namespace

// Radiosity's patches are Lambertian, but at the point the camera sees, its final gather weighs
// each direction light arrives from by the material's own diffuse part toward the eye
// (Material::diffuseReflectanceBetween), so a microfacet base under a layer and a coat shows what
// the path tracer shows. The control: the same floor as a Lambertian of the material's average
// albedo (diffuseReflectance, what radiosity showed before) is far off toward the horizon.
TEST_CASE("radiosity shows a base under a GGX layer and a coat as the path tracer does: toward the eye, from the sun; "
          "control: its average albedo as a Lambertian kd fails") {
    const Scene scene = loadSceneFromText(kLacquerFloor, LIGHTPATH_SOURCE_DIR "/tests/render/data/lacquer-floor.toml");
    const std::vector<lpe::NamedExpression> direct{{"direct", "ED<L>"}};
    RadiosityOptions radiosity;
    const Film path = renderAovs(scene, direct, "path", 16, 2, radiosity);
    const Film solved = renderAovs(scene, direct, "radiosity", 16, 2, radiosity);
    const double worst = worstRegionRatio(solved, path);
    CAPTURE(worst);
    CHECK(worst < 0.01);
    // The control: kd = the material's mean albedo, what a Lambertian patch shows from every side.
    const Rgb average = scene.materials[0]->diffuseReflectance();
    std::string lambertian = kLacquerFloor;
    const std::string from = lambertian.substr(lambertian.find("[materials.lacquer]"),
                                               lambertian.find("[[planes]]") - lambertian.find("[materials.lacquer]"));
    lambertian.replace(lambertian.find(from), from.size(),
                       "[materials.lacquer]\nkd = [" + std::to_string(average.r) + ", " + std::to_string(average.g) +
                           ", " + std::to_string(average.b) + "]\n");
    const Scene plain = loadSceneFromText(lambertian, LIGHTPATH_SOURCE_DIR "/tests/render/data/lacquer-floor.toml");
    const double control = worstRegionRatio(renderAovs(plain, direct, "radiosity", 16, 2, radiosity), path);
    CAPTURE(control);
    CHECK(control > 0.1);
}

}  // namespace lightpath
