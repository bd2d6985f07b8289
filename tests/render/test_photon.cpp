// Photon mapping against references that do not come from it: the path tracer on a diffuse
// Cornell box with an area light (block means within a stated tolerance, a control 15% off that
// must fail), a caustic seen in a mirror that the path tracer and bdpt leave exactly black, the
// AOVs summing to the beauty, and images bit-identical for any thread count.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "film/aov_presets.h"
#include "film/aov_set.h"
#include "integrators/registry.h"
#include "render/renderer.h"
#include "scene/scene_loader.h"
#include "../support/film_checks.h"

namespace lightpath {
namespace {

struct PhotonSettings {
    int photons = 100000;
    float radius = 0.0f;  // 0: the integrator's default
};

RenderResult renderResult(const Scene& scene, const std::vector<lpe::NamedExpression>& set, const char* integrator,
                          int spp, int threads = 0, PhotonSettings photon = {}, bool writeBeauty = true) {
    const AovSet aovs(set);
    RenderOptions options;
    options.writeBeauty = writeBeauty;
    options.integrator = integrator;
    options.samplesPerPixel = spp;
    options.maxDepth = 5;
    options.seed = 7;
    options.threads = threads;
    if (std::string(integrator) == "photon") {
        ParameterValues values(findIntegrator("photon")->schema);
        values.set("photons", photon.photons);
        if (photon.radius > 0.0f) values.set("photon-radius", double(photon.radius));
        options.integratorParameters = values;
    }
    return Renderer(scene, aovs, options).render();
}

Film render(const Scene& scene, const std::vector<lpe::NamedExpression>& set, const char* integrator, int spp,
            int threads = 0, PhotonSettings photon = {}) {
    return renderResult(scene, set, integrator, spp, threads, photon).film;
}

using test::layerOf;
using test::layerSum;
using test::scaled;
using test::worstBlockError;

TEST_CASE("photon: a caustic seen in a mirror, E S+ D S+ <L.>, shows under photon mapping and is exactly black under path and bdpt") {
    const Scene scene = loadScene(LIGHTPATH_SOURCE_DIR "/tests/render/data/caustic-in-mirror.toml");
    auto set = classesSet();
    set.push_back({"sds", "E S+ D S+ <L.>"});
    const Film photon = render(scene, set, "photon", 4);
    const Film path = render(scene, set, "path", 4);
    const Film bdpt = render(scene, set, "bdpt", 4);
    const std::size_t sds = layerOf(photon, "sds");
    REQUIRE(sds < photon.layerCount());
    CHECK(layerSum(photon, sds) > 1.0);
    CHECK(layerSum(path, sds) == 0.0);
    CHECK(layerSum(bdpt, sds) == 0.0);
    // The classes (layers 1..5) and `rest` sum to the beauty per pixel, and classes leave nothing to
    // `rest`; sds overlaps them and is left out of the sum.
    const std::size_t rest = photon.layerCount() - 1;
    double worst = 0.0;
    for (int y = 0; y < photon.height(); ++y)
        for (int x = 0; x < photon.width(); ++x) {
            Rgb sum = photon.at(rest, x, y);
            for (std::size_t l = 1; l < sds; ++l) sum += photon.at(l, x, y);
            const Rgb beauty = photon.at(0, x, y);
            for (int c = 0; c < 3; ++c)
                worst = std::max(worst, std::fabs(double(sum[c]) - beauty[c]) / (1e-5 * std::fabs(beauty[c]) + 1e-7));
        }
    CHECK(worst <= 1.0);
    CHECK(layerSum(photon, rest) == 0.0);
}

TEST_CASE("photon: the classes AOVs sum to the beauty, rest is zero, on the Cornell box") {
    Scene scene = loadScene(LIGHTPATH_SOURCE_DIR "/tests/render/data/cornell-lamp.toml");
    scene.camera.width = scene.camera.height = 16;
    const Film film = render(scene, classesSet(), "photon", 2, 0, {20000, 0.0f});
    CHECK(test::worstSumError(film) <= 1.0);
    CHECK(layerSum(film, film.layerCount() - 1) == 0.0);
    CHECK(layerSum(film, layerOf(film, "indirect")) > 0.0);
}

TEST_CASE("photon: the same image, bit for bit, on one thread and on four") {
    Scene scene = loadScene(LIGHTPATH_SOURCE_DIR "/tests/render/data/caustic-in-mirror.toml");
    scene.camera.width = 16;
    scene.camera.height = 12;
    const Film one = render(scene, classesSet(), "photon", 2, 1, {20000, 0.0f});
    const Film four = render(scene, classesSet(), "photon", 2, 4, {20000, 0.0f});
    for (std::size_t l = 0; l < one.layerCount(); ++l) {
        const auto a = one.layer(l), b = four.layer(l);
        CHECK(std::equal(a.begin(), a.end(), b.begin(), b.end()));
    }
}

TEST_CASE("photon: with E S+ D S+ <L.> alone requested, photons no output can accept are not stored, and its image is unchanged") {
    const Scene scene = loadScene(LIGHTPATH_SOURCE_DIR "/tests/render/data/caustic-in-mirror.toml");
    auto set = classesSet();
    set.push_back({"sds", "E S+ D S+ <L.>"});
    const RenderResult full = renderResult(scene, set, "photon", 2);
    const RenderResult alone = renderResult(scene, {{"sds", "E S+ D S+ <L.>"}}, "photon", 2, 0, {}, false);
    REQUIRE(full.stats.photon);
    REQUIRE(alone.stats.photon);
    // Every caustic photon (L S+) may end such a path; no global one may: its events hold a D or
    // a G, and the merge adds another (E S+ (D|G) ... D ... L), which the expression refuses.
    CHECK(full.stats.photon->globalStored > 0);
    CHECK(alone.stats.photon->globalStored == 0);
    CHECK(alone.stats.photon->causticStored == full.stats.photon->causticStored);
    const auto a = full.film.layer(layerOf(full.film, "sds")), b = alone.film.layer(layerOf(alone.film, "sds"));
    CHECK(layerSum(full.film, layerOf(full.film, "sds")) > 1.0);
    CHECK(std::equal(a.begin(), a.end(), b.begin(), b.end()));
}

// Photon mapping is biased by its radius (a blur), so agreement is within a tolerance that the
// radius and photon count below meet and a 15% brighter path tracer does not.
constexpr double kBlockTolerance = 0.08;

TEST_CASE("photon: converges to the path tracer on the diffuse Cornell box with its area light (4x4 block means within 8%)" * doctest::test_suite("statistical")) {
    Scene scene = loadScene(LIGHTPATH_SOURCE_DIR "/tests/render/data/cornell-lamp.toml");
    scene.camera.width = scene.camera.height = 24;
    const Film photon = render(scene, classesSet(), "photon", 64, 0, {1000000, 0.025f});
    const Film path = render(scene, classesSet(), "path", 1024);
    const double error = worstBlockError(photon, path, 4);
    MESSAGE("worst 4x4 block error " << error << ", mean ratio " << layerSum(photon, 0) / layerSum(path, 0));
    CHECK(error < kBlockTolerance);
    CHECK(worstBlockError(photon, scaled(path, 1.15f), 4) > kBlockTolerance);
}

}  // namespace
}  // namespace lightpath
