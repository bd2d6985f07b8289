// The central promise (docs/design.md): the AOVs and `rest` sum to the beauty, for every shipped
// scene and every integrator, and `rest` is zero for the `classes` partition: every path an
// integrator produces falls in exactly one class. The sums alone hold whatever AOV a term is sent
// to, so a light group is also checked against an independent render: the scene lit by that light
// alone (test_routing.cpp checks each term's events).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <vector>

#include "film/aov_set.h"
#include "render/renderer.h"
#include "lights/point_light.h"
#include "../support/shipped_scenes.h"
#include "../support/film_checks.h"
#include "scene/scene_loader.h"
#include "film/aov_presets.h"

namespace lightpath {
namespace {

using test::shippedScenes;

Film renderSmall(const std::filesystem::path& file, const AovSet& aovs, const std::string& integrator,
                 int threads = 0) {
    Scene scene = loadScene(file);
    // Keep the scene's aspect ratio at about 64 pixels wide.
    scene.camera.height = std::max(1, scene.camera.height * 64 / scene.camera.width);
    scene.camera.width = 64;
    RenderOptions options;
    options.integrator = integrator;
    options.samplesPerPixel = 2;
    options.threads = threads;
    return Renderer(scene, aovs, options).render().film;
}

// Sum of every layer but the beauty, against the beauty, per pixel and channel.
void checkLayersSumToBeauty(const Film& film) { CHECK(test::worstSumError(film) <= 1.0); }

TEST_CASE("every shipped scene and integrator: the classes AOVs sum to the beauty and rest is zero") {
    const AovSet aovs(classesSet());
    const auto scenes = shippedScenes();
    REQUIRE(scenes.size() >= 5);
    for (const auto& file : scenes) {
        for (const char* integrator : {"raycast", "whitted", "path"}) {
            CAPTURE(file.filename().string());
            CAPTURE(integrator);
            const Film film = renderSmall(file, aovs, integrator);
            checkLayersSumToBeauty(film);
            const auto rest = film.layer(film.layerCount() - 1);
            CHECK(std::all_of(rest.begin(), rest.end(), [](const Rgb& v) { return v == Rgb{0.0f}; }));
            const auto beauty = film.layer(0);
            CHECK(std::any_of(beauty.begin(), beauty.end(), [](const Rgb& v) { return v != Rgb{0.0f}; }));
        }
    }
}

TEST_CASE("every shipped scene: a partial set plus rest sums to the beauty") {
    // Two AOVs that cover only part of the light; rest must carry everything else.
    const AovSet aovs({{"ambient", "E.*<L'ambient'>"}, {"highlights", "E S* G L"}});
    for (const auto& file : shippedScenes()) {
        CAPTURE(file.filename().string());
        checkLayersSumToBeauty(renderSmall(file, aovs, "whitted"));
    }
}

TEST_CASE("the Cornell box under the path tracer: indirect light is non-zero") {
    const AovSet aovs(classesSet());
    const Film film = renderSmall(LIGHTPATH_SOURCE_DIR "/scenes/cornell-original.toml", aovs, "path");
    const auto names = aovs.layerNames();
    const std::size_t indirect = static_cast<std::size_t>(std::find(names.begin(), names.end(), "indirect") - names.begin());
    const auto layer = film.layer(indirect);
    CHECK(std::count_if(layer.begin(), layer.end(), [](const Rgb& v) { return v != Rgb{0.0f}; }) > film.width() * film.height() / 2);
}

TEST_CASE("the lecture room: all default AOVs but indirect and volume (it has no medium) are non-zero under Whitted") {
    const AovSet aovs(classesSet());
    const Film film = renderSmall(LIGHTPATH_SOURCE_DIR "/scenes/lecture-room.toml", aovs, "whitted");
    const auto names = aovs.layerNames();
    for (std::size_t l = 1; l + 1 < film.layerCount(); ++l) {
        CAPTURE(names[l]);
        const auto layer = film.layer(l);
        const bool nonZero = std::any_of(layer.begin(), layer.end(), [](const Rgb& v) { return v != Rgb{0.0f}; });
        CHECK(nonZero == (names[l] != "indirect" && names[l] != "volume"));
    }
}

TEST_CASE("every shipped scene: a point light's group AOV is the scene lit by that light alone") {
    int lit = 0;  // groups with light in them (a lamp may sit inside its fixture and light nothing)
    for (const auto& file : shippedScenes()) {
        const Scene full = loadScene(file);
        for (std::size_t k = 0; k < full.lights.size(); ++k) {
            if (full.lights[k]->name.empty()) continue;
            // Only light k shines: the other lights, emitters, the ambient term and the sky go dark.
            Scene alone = full;
            for (std::size_t i = 0; i < alone.lights.size(); ++i)
                if (i != k) pointLightOf(alone.lights[i]).intensity = Rgb{0.0f};
            for (MaterialSlot& m : alone.materials) m->emission = Rgb{0.0f};
            alone.ambient = alone.background = Rgb{0.0f};
            const std::string name = full.lights[k]->name;
            const AovSet group({{"group", "E.*<L'" + name + "'>"}});
            const AovSet none(std::vector<lpe::NamedExpression>{});
            for (const std::string integrator : {"raycast", "whitted"}) {
                CAPTURE(file.filename().string());
                CAPTURE(name);
                CAPTURE(integrator);
                auto render = [&](const Scene& scene, const AovSet& aovs) {
                    Scene small = scene;
                    small.camera.height = std::max(1, small.camera.height * 48 / small.camera.width);
                    small.camera.width = 48;
                    RenderOptions options;
                    options.integrator = integrator;
                    return Renderer(small, aovs, options).render().film;
                };
                const Film withGroup = render(full, group), single = render(alone, none);
                double worst = 0.0, total = 0.0;
                for (int y = 0; y < single.height(); ++y) {
                    for (int x = 0; x < single.width(); ++x) {
                        for (int c = 0; c < 3; ++c) {
                            const double a = withGroup.at(1, x, y)[c], b = single.at(0, x, y)[c];
                            worst = std::max(worst, std::fabs(a - b) / (1e-5 * std::fabs(b) + 1e-7));
                            total += b;
                        }
                    }
                }
                lit += total > 0.0;
                CHECK(worst <= 1.0);
            }
        }
    }
    CHECK(lit >= 10);
}

TEST_CASE("the image is bit-identical for 1, 2 and 8 threads, and across runs") {
    const AovSet aovs(classesSet());
    const auto file = std::filesystem::path(LIGHTPATH_SOURCE_DIR "/scenes/lecture-room.toml");
    const Film one = renderSmall(file, aovs, "whitted", 1);
    for (int threads : {1, 2, 8}) {
        const Film many = renderSmall(file, aovs, "whitted", threads);
        for (std::size_t l = 0; l < one.layerCount(); ++l) {
            const auto a = one.layer(l), b = many.layer(l);
            CHECK(std::equal(a.begin(), a.end(), b.begin()));
        }
    }
}

}  // namespace
}  // namespace lightpath
