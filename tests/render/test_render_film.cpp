// The renderer's film is allocated without being cleared (Film::Unset, so that its pages are first
// touched by the workers in parallel): every pixel must then be written by the render itself,
// including those a cancelled render never reached, which must come out black, never as whatever
// the memory held before.
#include <doctest/doctest.h>

#include <atomic>
#include <vector>

#include "film/aov_presets.h"
#include "film/aov_set.h"
#include "render/renderer.h"
#include "scene/scene_loader.h"

namespace lightpath {
namespace {

TEST_CASE("a render cancelled before its first pixel returns a black film, not the memory it was given") {
    Scene scene = loadScene(LIGHTPATH_SOURCE_DIR "/scenes/lecture-room.toml");
    scene.camera.width = 40;
    scene.camera.height = 24;
    const AovSet aovs(classesSet());
    const std::atomic<bool> cancel{true};
    RenderOptions options;
    options.integrator = "whitted";
    options.threads = 2;
    options.cancel = &cancel;
    const Renderer renderer(scene, aovs, options);
    const std::size_t bytes = renderer.layerNames().size() * 40 * 24 * sizeof(Rgb);
    for (int attempt = 0; attempt < 8; ++attempt) {
        // Leave a freed block of the film's size full of a bright pattern (1.0f), where the heap will
        // most likely hand out the film.
        {
            const std::vector<float> bright(bytes / sizeof(float), 1.0f);
            CHECK(bright.front() == 1.0f);
        }
        const RenderResult result = renderer.render();
        CHECK(result.cancelled);
        std::size_t lit = 0;
        for (const Rgb& value : result.film.interleaved()) lit += value != Rgb{0.0f} ? 1 : 0;
        CHECK(lit == 0);
    }
}

}  // namespace
}  // namespace lightpath
