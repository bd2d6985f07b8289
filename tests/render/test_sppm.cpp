// Stochastic progressive photon mapping against references that do not come from it: its radius
// schedule by hand, the path tracer on the Cornell box under its lamp (mean and 4x4 block means,
// with a control 5% off that must fail), bdpt on the glass ball's caustic, the caustic seen in a
// mirror that path and bdpt leave black, the AOVs summing to the beauty, and one image for any
// number of threads.
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

struct SppmSettings {
    int photons = 20000;
    float radius = 0.0f;  // 0: the integrator's default
    int passes = 0;       // 0: one per pixel sample
};

Film render(const Scene& scene, const std::vector<lpe::NamedExpression>& set, const char* integrator, int spp,
            int threads = 0, SppmSettings sppm = {}) {
    const AovSet aovs(set);
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
    return Renderer(scene, aovs, options).render().film;
}

TEST_CASE("sppm: the radius shrinks as r_{i+1}^2 = r_i^2 (i + alpha) / (i + 1), evaluated by hand") {
    CHECK(sppmRadius(2.0f, 2.0 / 3.0, 0) == doctest::Approx(2.0));
    CHECK(sppmRadius(2.0f, 2.0 / 3.0, 1) == doctest::Approx(std::sqrt(4.0 * 5.0 / 6.0)));
    CHECK(sppmRadius(2.0f, 2.0 / 3.0, 2) == doctest::Approx(std::sqrt(4.0 * 5.0 / 6.0 * 8.0 / 9.0)));
    // alpha = 1 keeps every photon: the radius stays.
    CHECK(sppmRadius(2.0f, 1.0, 50) == doctest::Approx(2.0));
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

TEST_CASE("sppm: the same image, bit for bit, on one thread and on four") {
    Scene scene = loadScene(LIGHTPATH_SOURCE_DIR "/tests/render/data/caustic-in-mirror.toml");
    scene.camera.width = 48;
    scene.camera.height = 36;
    // Several tiles, so four threads share them; 4 samples over 3 passes, so a pass chosen by
    // anything but the sample's index shows.
    const Film one = render(scene, classesSet(), "sppm", 4, 1, {5000, 0.0f, 3});
    const Film four = render(scene, classesSet(), "sppm", 4, 4, {5000, 0.0f, 3});
    for (std::size_t l = 0; l < one.layerCount(); ++l) {
        const auto a = one.layer(l), b = four.layer(l);
        CHECK(std::equal(a.begin(), a.end(), b.begin(), b.end()));
    }
}

// The glass ball's caustic from its point light: bdpt's connection of the light to the floor
// through the ball's refractions against sppm's photons, over the image, within 5%. The caustic
// is small, so eye samples dominate the noise: 16 pixel samples read each of the 32 passes, and
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
    // 4 pixel samples read each of 32 passes of 40000 photons (about 200 MiB of photons), the
    // first radius 0.025 (0.7 of the default): measured worst block 1.83%, mean 0.24%.
    const Film sppm = render(scene, classesSet(), "sppm", 128, 0, {40000, 0.025f, 32});
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
