// Rendering a mesh scene: the same image for any number of threads, and the same image whatever
// the accelerator finds the hits with (the BVH reports exactly what brute force does).
#include <doctest/doctest.h>

#include <algorithm>

#include "render/renderer.h"
#include "scene/scene_loader.h"
#include "film/aov_presets.h"

namespace lightpath {
namespace {

Film renderCornell(int threads, Accelerator accelerator) {
    Scene scene = loadScene(LIGHTPATH_SOURCE_DIR "/scenes/cornell-mirror.toml");
    scene.camera.width = scene.camera.height = 48;
    static const AovSet aovs(classesSet());
    RenderOptions options;
    options.integrator = "whitted";
    options.samplesPerPixel = 2;
    options.threads = threads;
    options.accelerator = accelerator;
    return Renderer(scene, aovs, options).render().film;
}

bool identical(const Film& a, const Film& b) {
    const auto x = a.interleaved(), y = b.interleaved();
    return x.size() == y.size() && std::equal(x.begin(), x.end(), y.begin());
}

TEST_CASE("a Cornell box renders bit-identically on 1, 2 and 8 threads") {
    const Film one = renderCornell(1, Accelerator::Bvh);
    CHECK(identical(one, renderCornell(2, Accelerator::Bvh)));
    CHECK(identical(one, renderCornell(8, Accelerator::Bvh)));
}

TEST_CASE("a Cornell box renders bit-identically with the BVH and with brute force") {
    CHECK(identical(renderCornell(2, Accelerator::Bvh), renderCornell(2, Accelerator::BruteForce)));
}

}  // namespace
}  // namespace lightpath
