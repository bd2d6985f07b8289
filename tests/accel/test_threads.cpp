// Rendering a mesh scene: the same image for any number of threads, and the same image whatever
// the accelerator finds the hits with (the BVH reports exactly what brute force does).
#include <doctest/doctest.h>

#include <algorithm>
#include <atomic>
#include <memory>
#include <stdexcept>
#include <thread>

#include "render/renderer.h"
#include "scene/scene_loader.h"
#include "film/aov_presets.h"
#include "util/parallel_chunks.h"
#include "util/worker_threads.h"

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

TEST_CASE("parallelChunks rethrows a worker's exception on the calling thread") {
    // Without this an exception in a helper std::jthread calls std::terminate: in `serve` that takes
    // the server down. The chunk that throws is taken by whichever thread comes first.
    for (const unsigned threads : {1u, 2u, 5u}) {
        CAPTURE(threads);
        constexpr std::size_t kCount = 100000;
        std::atomic<std::size_t> visited{0};
        const auto body = [&](std::size_t begin, std::size_t end) {
            if (begin == 3) throw std::runtime_error("chunk 3 failed");
            visited += end - begin;
        };
        CHECK_THROWS_WITH_AS(parallelChunks(kCount, 1, threads, body), "chunk 3 failed", std::runtime_error);
        if (threads == 1) CHECK(visited == 3);  // chunks 0 to 2, then none after the throw
    }
}

TEST_CASE("parallelChunks rethrows an exception thrown on a helper thread, not std::terminate") {
    // The calling thread's chunks wait until a helper has thrown, so the helper surely throws.
    for (const unsigned threads : {2u, 5u}) {
        CAPTURE(threads);
        const std::thread::id caller = std::this_thread::get_id();
        std::atomic<bool> helperThrew{false};
        const auto body = [&](std::size_t, std::size_t) {
            if (std::this_thread::get_id() != caller) {
                helperThrew = true;
                throw std::runtime_error("a helper failed");
            }
            while (!helperThrew) std::this_thread::yield();
        };
        CHECK_THROWS_WITH_AS(parallelChunks(1000, 1, threads, body), "a helper failed", std::runtime_error);
    }
}

TEST_CASE("runWorkers: a helper's exception reaches the caller, the others see failed()") {
    WorkerErrors errors;
    std::atomic<int> stopped{0};
    const auto work = [&](unsigned worker) {
        if (worker == 2) throw std::invalid_argument("worker 2 failed");
        while (!errors.failed()) std::this_thread::yield();  // until worker 2 has thrown
        ++stopped;
    };
    CHECK_THROWS_WITH_AS(runWorkers(4, errors, work), "worker 2 failed", std::invalid_argument);
    CHECK(stopped == 3);
    // Without a failure nothing is thrown and every worker ran.
    WorkerErrors none;
    std::atomic<int> ran{0};
    runWorkers(3, none, [&](unsigned) { ++ran; });
    CHECK(ran == 3);
}

}  // namespace
}  // namespace lightpath
