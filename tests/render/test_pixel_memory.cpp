// The bytes a render holds in proportion to its pixels (Renderer::pixelMemory, issue #28) against
// a hand count for a 4x3 image: what a render that cannot get them is refused by.
#include <doctest/doctest.h>

#include "film/aov_presets.h"
#include "film/aov_set.h"
#include "render/renderer.h"
#include "scene/scene_loader.h"

namespace lightpath {
namespace {

// 4x3 pixels; the classes set: beauty, raycast, raytrace, mirror, emission, indirect, volume, rest.
constexpr std::uint64_t kPixels = 4 * 3;
constexpr std::uint64_t kLayers = 8;

PixelMemory memoryOf(const std::string& integrator, bool writeBeauty = true) {
    Scene scene = loadScene(LIGHTPATH_SOURCE_DIR "/scenes/lecture-room.toml");
    scene.camera.width = 4;
    scene.camera.height = 3;
    RenderOptions options;
    options.integrator = integrator;
    options.writeBeauty = writeBeauty;
    return Renderer::pixelMemory(scene, AovSet(classesSet()), options);
}

TEST_CASE("a film holds three 4-byte floats per layer per pixel") {
    const PixelMemory memory = memoryOf("whitted");
    CHECK(memory.width == 4);
    CHECK(memory.height == 3);
    CHECK(memory.layers.size() == kLayers);
    CHECK(memory.film == kPixels * kLayers * 3 * 4);  // 1152
    CHECK(memory.splats == 0);
    CHECK(memory.preprocess == 0);
    CHECK(memory.total() == 1152);
    CHECK(memory.describe() == "a 4x3 image of 8 layers (beauty, raycast, raytrace, mirror, emission, indirect, volume, rest)");
}

TEST_CASE("without the beauty the film holds the AOVs alone") {
    CHECK(memoryOf("whitted", false).film == kPixels * (kLayers - 2) * 3 * 4);  // 864
}

TEST_CASE("bdpt's splat film adds three 16-byte (128-bit) fixed-point sums per layer per pixel") {
    const PixelMemory memory = memoryOf("bdpt");
    CHECK(memory.splats == kPixels * kLayers * 3 * 16);  // 4608
    CHECK(memory.total() == 1152 + 4608);
}

TEST_CASE("the rasteriser's z-buffer adds one fragment per pixel: depth, primitive id, barycentrics") {
    CHECK(memoryOf("raster").preprocess == kPixels * (4 + 4 + 3 * 4));  // 240
}

}  // namespace
}  // namespace lightpath
