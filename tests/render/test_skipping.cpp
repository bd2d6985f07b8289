// Skipping what a scene or a request does not need, proven by counters, and never changing the
// requested outputs (docs/design.md: dead states stop; issue "Skip what a scene, or a request, doesn't need").
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>

#include "film/aov_set.h"
#include "render/renderer.h"
#include "scene/scene_loader.h"
#include "scene_builder.h"
#include "film/aov_presets.h"

namespace lightpath {
namespace {

Scene smallScene(const std::string& name) {
    Scene scene = loadScene(std::string(LIGHTPATH_SOURCE_DIR "/scenes/") + name);
    scene.camera.height = std::max(1, scene.camera.height * 64 / scene.camera.width);
    scene.camera.width = 64;
    return scene;
}

RenderResult renderWith(const Scene& scene, const AovSet& aovs, bool beauty, bool skip) {
    RenderOptions options;
    options.writeBeauty = beauty;
    options.skip = skip;
    options.samplesPerPixel = 2;
    return Renderer(scene, aovs, options).render();
}

bool sameImages(const Film& a, const Film& b) {
    if (a.layerNames() != b.layerNames()) return false;
    for (std::size_t l = 0; l < a.layerCount(); ++l) {
        const auto x = a.layer(l), y = b.layer(l);
        if (!std::equal(x.begin(), x.end(), y.begin())) return false;
    }
    return true;
}

const char* const kSpecularScenes[] = {"mirror-sphere.toml", "glass-sphere.toml", "lecture-room.toml"};

TEST_CASE("a ray-casting request without the beauty casts no reflection or refraction ray") {
    const AovSet aovs(std::vector<lpe::NamedExpression>{{"direct", "E(D|G)L"}});
    for (const char* name : kSpecularScenes) {
        CAPTURE(name);
        const Scene scene = smallScene(name);
        const RayCounters skipped = renderWith(scene, aovs, false, true).stats.rays;
        CHECK(skipped.reflection == 0);
        CHECK(skipped.refraction == 0);
        CHECK(skipped.reflectionDead + skipped.refractionDead > 0);
        // The same request with the beauty must trace them: the beauty keeps everything alive.
        const RayCounters full = renderWith(scene, aovs, true, true).stats.rays;
        CHECK(full.reflection + full.refraction > 0);
    }
}

TEST_CASE("skipping leaves the requested outputs bit-identical") {
    const AovSet classes(classesSet());
    const AovSet direct({{"direct", "E(D|G)L"}, {"through_glass", "E<TS>+.*"}});
    for (const auto& entry : std::filesystem::directory_iterator(LIGHTPATH_SOURCE_DIR "/scenes")) {
        if (entry.path().extension() != ".toml") continue;
        CAPTURE(entry.path().filename().string());
        const Scene scene = smallScene(entry.path().filename().string());
        CHECK(sameImages(renderWith(scene, classes, true, true).film, renderWith(scene, classes, true, false).film));
        CHECK(sameImages(renderWith(scene, direct, false, true).film, renderWith(scene, direct, false, false).film));
    }
}

// A floor seen from straight above fills the whole image: every camera ray hits it.
Scene floorWithLights(Vec3 ks) {
    Scene scene;
    scene.camera = test::centredCamera({0, 5, 0}, {0, 0, 0}, {0, 0, -1}, 15);
    PhongMaterial m;
    m.name = "floor";
    m.kd = Rgb{0.5f};
    m.ks = ks;
    test::addPlane(scene, "floor", test::addMaterial(scene, m), {0, 0, 0}, {0, 1, 0});
    scene.lights.push_back(PointLight{"above", {1, 3, 0}, Rgb{1.0f}, {1, 0, 0}});
    scene.lights.push_back(PointLight{"below", {0, -3, 0}, Rgb{1.0f}, {1, 0, 0}});
    scene.lights.push_back(PointLight{"dark", {0, 3, 1}, Rgb{0.0f}, {1, 0, 0}});
    return scene;
}

TEST_CASE("shadow rays: one per lit-side light sample, none to lights behind or without light") {
    const Scene scene = floorWithLights(Rgb{0.0f});
    const AovSet aovs(classesSet());
    const RayCounters r = renderWith(scene, aovs, true, true).stats.rays;
    const std::uint64_t pixels = 15 * 15 * 2;  // two samples per pixel
    CHECK(r.camera == pixels);
    CHECK(r.shadow == pixels);        // "above": on the lit side, with light
    CHECK(r.shadowBehind == pixels);  // "below": N.(b - p) < 0
    CHECK(r.shadowZero == pixels);    // "dark": intensity 0
    CHECK(r.shadowDead == 0);
}

TEST_CASE("an all-diffuse scene evaluates no highlight, a glossy one does") {
    const AovSet aovs(classesSet());
    const RayCounters diffuse = renderWith(floorWithLights(Rgb{0.0f}), aovs, true, true).stats.rays;
    CHECK(diffuse.glossyEvaluated == 0);
    CHECK(diffuse.glossyAbsent > 0);
    const RayCounters glossy = renderWith(floorWithLights(Rgb{0.3f}), aovs, true, true).stats.rays;
    CHECK(glossy.glossyEvaluated == glossy.shadow + glossy.shadowZero);
}

TEST_CASE("a light group request casts no shadow ray towards the other lights") {
    const Scene scene = floorWithLights(Rgb{0.0f});
    const AovSet aovs(std::vector<lpe::NamedExpression>{{"above", "E.*<L'above'>"}});
    const RayCounters r = renderWith(scene, aovs, false, true).stats.rays;
    CHECK(r.shadow == 15 * 15 * 2);
    CHECK(r.shadowDead == 15 * 15 * 2);  // "dark" is not requested (and "below" is behind)
}

TEST_CASE("without skipping every term is evaluated and every ray cast") {
    const AovSet aovs(classesSet());
    const RayCounters r = renderWith(floorWithLights(Rgb{0.0f}), aovs, true, false).stats.rays;
    CHECK(r.shadow == 3 * 15 * 15 * 2);
    CHECK(r.shadowBehind + r.shadowZero + r.shadowDead + r.glossyAbsent == 0);
}

}  // namespace
}  // namespace lightpath
