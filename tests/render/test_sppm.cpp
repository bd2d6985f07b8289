// Stochastic progressive photon mapping against references that do not come from it: the path tracer on the Cornell box under its lamp (mean and 4x4 block means,
// with a control 5% off that must fail), bdpt on the glass ball's caustic, the caustic seen in a
// mirror that path and bdpt leave black, the AOVs summing to the beauty, one image for any number
// of threads, memory independent of the passes, and explain's terms summing to the pixel.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "film/aov_presets.h"
#include "film/aov_set.h"
#include "integrators/registry.h"
#include "integrators/sppm.h"
#include "render/renderer.h"
#include "scene/scene_loader.h"
#include "../support/film_checks.h"

namespace lightpath {
namespace {

using test::layerOf;
using test::layerSum;
using test::scaled;
using test::worstBlockError;

struct Photons {
    int photons = 20000;  // per pass
    float radius = 0.0f;  // 0: the integrator's default
    int passes = 0;       // 0: --spp
};

RenderOptions renderOptions(const char* integrator, int spp, int threads = 0, Photons sppm = {}) {
    RenderOptions options;
    options.integrator = integrator;
    options.samplesPerPixel = spp;
    options.maxDepth = 5;
    options.seed = 7;
    options.threads = threads;
    if (std::string(integrator) == "sppm") {
        ParameterValues values(findIntegrator("sppm")->schema);
        values.set("photons", sppm.photons);
        if (sppm.radius > 0.0f) values.set("photon-radius", double(sppm.radius));
        if (sppm.passes > 0) values.set("passes", sppm.passes);
        options.integratorParameters = values;
    }
    if (std::string(integrator) == "bdpt") {
        // The reference for caustics: every camera sample walks from the light. Left to its
        // pilot, bdpt lets half of them skip the glass ball's caustic (its beauty's noise is
        // mostly elsewhere), and at 4096 spp the caustic is then 5-7% off, as noise, not bias.
        ParameterValues values(findIntegrator("bdpt")->schema);
        values.set("light-walk-fraction", 1.0);
        options.integratorParameters = values;
    }
    return options;
}

Film render(const Scene& scene, const std::vector<lpe::NamedExpression>& set, const char* integrator, int spp,
            int threads = 0, Photons sppm = {}) {
    const AovSet aovs(set);
    return Renderer(scene, aovs, renderOptions(integrator, spp, threads, sppm)).render().film;
}

TEST_CASE("sppm: memory is the pixels' statistics and one pass's photons, the same after 2 and 8 passes") {
    const Scene scene = loadScene(LIGHTPATH_SOURCE_DIR "/tests/render/data/caustic-in-mirror.toml");
    const AovSet aovs(classesSet());
    const auto stats = [&](int passes) {
        return *Renderer(scene, aovs, renderOptions("sppm", passes, 0, {5000})).render().stats.photon;
    };
    const PhotonStats two = stats(2), eight = stats(8);
    CHECK(two.passes == 2);
    CHECK(eight.passes == 8);
    CHECK(eight.shot == 4 * two.shot);
    // Passes differ only in their photons' seeds: their maps' sizes vary a little, not with passes.
    CHECK(double(eight.bytes) < 1.2 * double(two.bytes));
    // The pixels' radii shrink as photons are found.
    CHECK(eight.lastRadius < two.lastRadius);
    CHECK(two.lastRadius < two.radius);
}

TEST_CASE("sppm: explain's terms are the pixel's value, each photon named with its pass") {
    Scene scene = loadScene(LIGHTPATH_SOURCE_DIR "/tests/render/data/caustic-in-mirror.toml");
    const AovSet aovs(classesSet());
    // 4 samples over 2 passes: two camera rays a pixel in each.
    const Renderer renderer(scene, aovs, renderOptions("sppm", 4, 0, {5000, 0.0f, 2}));
    Film film = renderer.render().film;
    // The brightest pixel of the photons' class (the caustic seen in the mirror).
    int bestX = 0, bestY = 0;
    float best = -1.0f;
    const std::size_t sds = layerOf(film, "indirect");
    for (int y = 0; y < film.height(); ++y)
        for (int x = 0; x < film.width(); ++x)
            if (const float v = film.pixel(x, y)[sds].g; v > best) best = v, bestX = x, bestY = y;
    REQUIRE(best > 0.0f);
    Rgb sum{0.0f};
    bool lastPass = false;
    for (const LoggedContribution& c : renderer.explainPixel(bestX, bestY)) {
        sum += c.value;
        for (std::size_t f = 0; f < c.factorCount; ++f)
            if (std::string(c.factors[f].name) == "pass" && c.factors[f].value.r == 1.0f) lastPass = true;
    }
    const Rgb pixel = film.pixel(bestX, bestY)[0];
    for (int c = 0; c < 3; ++c) CHECK(sum[c] == doctest::Approx(pixel[c]).epsilon(1e-5));
    CHECK(lastPass);
}

TEST_CASE("sppm: a caustic seen in a mirror, E S+ D S+ <L.>, shows, and the classes sum to the beauty with nothing left to rest") {
    const Scene scene = loadScene(LIGHTPATH_SOURCE_DIR "/tests/render/data/caustic-in-mirror.toml");
    auto set = classesSet();
    const Film classes = render(scene, set, "sppm", 4);
    CHECK(test::worstSumError(classes) <= 1.0);
    CHECK(layerSum(classes, classes.layerCount() - 1) == 0.0);
    const Film sds = render(scene, {{"sds", "E S+ D S+ <L.>"}}, "sppm", 4);
    CHECK(layerSum(sds, layerOf(sds, "sds")) > 1.0);
}

// The scene: under its point lights the lecture room's specular-diffuse-specular light (the
// glass ball's caustic in the mirror ball, the mirror's light seen through the glass) is found by
// photon mapping alone; the path tracer's and bdpt's AOV of it is exactly zero.
TEST_CASE("sppm and photon: the lecture room's E S+ (D|G) S+ <L.> shows, and is exactly 0 under path and bdpt") {
    Scene scene = loadScene(LIGHTPATH_SOURCE_DIR "/scenes/lecture-room.toml");
    scene.camera.width = 64;
    scene.camera.height = 48;
    const std::vector<lpe::NamedExpression> set{{"sds", "E S+ (D|G) S+ <L.>"}};
    for (const std::string integrator : {"sppm", "photon", "path", "bdpt"}) {
        CAPTURE(integrator);
        const Film film = render(scene, set, integrator.c_str(), 4);
        const double sds = layerSum(film, layerOf(film, "sds"));
        if (integrator == "sppm" || integrator == "photon") CHECK(sds > 0.0);
        else CHECK(sds == 0.0);
        CHECK(test::worstSumError(film) <= 1.0);
    }
}

TEST_CASE("sppm: the same image, bit for bit, on one thread and on four") {
    Scene scene = loadScene(LIGHTPATH_SOURCE_DIR "/tests/render/data/caustic-in-mirror.toml");
    scene.camera.width = 48;
    scene.camera.height = 36;
    // Several tiles, so four threads share them; each pixel's radius depends on its passes before.
    const Film one = render(scene, classesSet(), "sppm", 3, 1, {5000});
    const Film four = render(scene, classesSet(), "sppm", 3, 4, {5000});
    for (std::size_t l = 0; l < one.layerCount(); ++l) {
        const auto a = one.layer(l), b = four.layer(l);
        CHECK(std::equal(a.begin(), a.end(), b.begin(), b.end()));
    }
}

// The glass ball's caustic from its point light: bdpt's connection of the light to the floor
// through the ball's refractions against sppm's photons, over the image, within 5%. The caustic
// is small, so eye samples dominate the noise: 16 camera rays a pixel in each of 32 passes, and
// bdpt needs 4096 (at 256 it is 20% off its converged value).
TEST_CASE("sppm: the glass ball's caustic E(D|G)S+<L.> agrees with bdpt's within 5%" * doctest::test_suite("statistical")) {
    Scene scene = loadScene(LIGHTPATH_SOURCE_DIR "/scenes/glass-sphere.toml");
    scene.camera.width = 32;
    scene.camera.height = 24;
    scene.background = Rgb{0.0f};
    const std::vector<lpe::NamedExpression> set{{"caustic", "E(D|G)S+<L.>"}};
    const double sppm = layerSum(render(scene, set, "sppm", 512, 0, {100000, 0.0f, 32}), 1);
    const double bdpt = layerSum(render(scene, set, "bdpt", 4096), 1);
    MESSAGE("caustic sppm " << sppm << ", bdpt " << bdpt << ", ratio " << sppm / bdpt);
    REQUIRE(bdpt > 0.0);
    CHECK(std::fabs(sppm / bdpt - 1.0) < 0.05);
    CHECK(std::fabs(1.1 * sppm / bdpt - 1.0) > 0.05);
}

constexpr double kTolerance = 0.02;

TEST_CASE("sppm: converges to the path tracer on the Cornell box under its lamp (mean and 4x4 blocks within 2%)" *
          doctest::test_suite("statistical")) {
    Scene scene = loadScene(LIGHTPATH_SOURCE_DIR "/tests/render/data/cornell-lamp.toml");
    scene.camera.width = scene.camera.height = 16;
    // 4 camera rays a pixel in each of 128 passes of 40000 photons, every pixel's first radius 0.05
    // (1.4 of the default): measured worst block 1.97%, mean 0.11% (seed 8: 1.41%, 0.16%). Each
    // pixel's radius shrinks with the photons it finds, to about a quarter of the first, so the
    // dark indirect-only blocks converge slowly: 32 passes left them 5% off.
    const Film sppm = render(scene, classesSet(), "sppm", 512, 0, {40000, 0.05f, 128});
    const Film path = render(scene, classesSet(), "path", 4096);
    const double error = worstBlockError(sppm, path, 4);
    const double mean = layerSum(sppm, 0) / layerSum(path, 0);
    MESSAGE("worst 4x4 block error " << error << ", mean ratio " << mean);
    CHECK(error < kTolerance);
    CHECK(std::fabs(mean - 1.0) < kTolerance);
    CHECK(worstBlockError(sppm, scaled(path, 1.05f), 4) > kTolerance);
}

}  // namespace
}  // namespace lightpath
