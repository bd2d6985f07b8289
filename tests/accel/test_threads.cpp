// Rendering a mesh scene: the same image for any number of threads, and the same image whatever
// the accelerator finds the hits with (the BVH reports exactly what brute force does).
#include <doctest/doctest.h>

#include <algorithm>
#include <atomic>
#include <memory>

#include "render/renderer.h"
#include "scene/scene_loader.h"
#include "film/aov_presets.h"
#include "util/parallel_chunks.h"

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

TEST_CASE("parallelChunks visits every index once, in the chunks count and grain alone fix") {
    for (const std::size_t count : {0u, 1u, 6u, 7u, 8u, 4095u, 4096u, 4097u, 50001u}) {
        for (const std::size_t grain : {1u, 7u, 4096u}) {
            for (const unsigned threads : {1u, 2u, 5u}) {
                INFO(count << " items, grain " << grain << ", " << threads << " threads");
                const auto visits = std::make_unique<std::atomic<int>[]>(count + 1);
                std::atomic<int> wrongChunks{0};
                parallelChunks(count, grain, threads, [&](std::size_t begin, std::size_t end) {
                    // Chunk k is [k * grain, min(count, (k + 1) * grain)).
                    if (begin % grain != 0 || end != std::min(count, begin + grain) || begin >= end) ++wrongChunks;
                    for (std::size_t i = begin; i < end && i <= count; ++i) ++visits[i];
                });
                CHECK(wrongChunks == 0);
                int wrongVisits = 0;
                for (std::size_t i = 0; i < count; ++i) wrongVisits += visits[i] != 1;
                CHECK(wrongVisits == 0);
                CHECK(visits[count] == 0);
            }
        }
    }
}

}  // namespace
}  // namespace lightpath
