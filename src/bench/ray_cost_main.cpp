// ray_cost: a fixed, small set of queries for `valgrind --tool=callgrind`, whose instruction
// counts are the stable figure on a loaded machine (wall time is not). Only castRays() (or, for
// `build`, buildGeometry() on one thread) is meant to be collected:
//   valgrind --tool=callgrind --toggle-collect='*castRays*' build/ray_cost bunny shadow bvh
// then instructions per ray = the collected total / the ray count this prints. cornell-mirror is
// `bench rays`' render scene: its sets against the traversal counted inside a render say whether
// the render line's traversal estimate is fair (docs/performance.md, Shading). A fourth
// argument, `baseline`, traverses our BVH on the SSE2 path even where AVX2 is available.
#include <cstdio>
#include <cstdlib>
#include <initializer_list>
#include <string>

#include "accel/simd_path.h"
#include "bench/ray_sets.h"
#include "util/timing.h"
#include "accel/scene_geometry.h"
#include "scene/scene_loader.h"

namespace lightpath {
namespace {

constexpr int kPrimarySide = 64;  // 4096 primary rays
constexpr int kRandomRays = 4096;

[[gnu::noinline]] std::size_t castRays(const SceneGeometry& geometry, const std::vector<Ray>& rays, bool closest) {
    std::size_t found = 0;
    for (const Ray& ray : rays) found += closest ? geometry.closestPrimitive(ray).has_value() : geometry.occluded(ray);
    return found;
}

[[gnu::noinline]] SceneGeometry buildGeometry(const std::vector<Triangle>& triangles, Accelerator accelerator,
                                              unsigned threads) {
    return SceneGeometry({}, {}, triangles, {}, accelerator, {}, threads);
}

// `build`: the build on 1 thread and on 2, five times each, interleaved; wall-clock medians.
int timeBuilds(const std::vector<Triangle>& triangles, Accelerator accelerator) {
    std::vector<double> seconds[2];
    for (int r = 0; r < 5; ++r)
        for (unsigned threads : {1u, 2u})
            seconds[threads - 1].push_back(buildGeometry(triangles, accelerator, threads).acceleratorStats().buildSeconds);
    for (unsigned threads : {1u, 2u})
        std::printf("build on %u thread%s: %.2f M triangles/s (median of 5)\n", threads, threads > 1 ? "s" : "",
                    static_cast<double>(triangles.size()) / median(seconds[threads - 1]) * 1e-6);
    return 0;
}

int run(const std::string& sceneName, const std::string& kind, const std::string& accel) {
    const Scene scene = sceneName == "grid" ? heightFieldScene(708)
                                            : loadScene(std::string(LIGHTPATH_SOURCE_DIR "/scenes/") + sceneName + ".toml");
    const Accelerator accelerator = accel == "embree" ? Accelerator::Embree : Accelerator::Bvh;
    if (kind == "build") return timeBuilds(scene.triangles, accelerator);
    const SceneGeometry geometry = buildGeometry(scene.triangles, accelerator, 1);
    const Bounds box = triangleBox(scene.triangles);
    std::vector<Ray> rays;
    if (kind == "random") {
        rays = randomRays(box, kRandomRays);
    } else {
        rays = primaryRays(scene, kPrimarySide);
        if (kind == "shadow") {
            const Vec3 light = scene.lights.empty() ? box.hi : scene.lights.front()->position();
            rays = shadowRays(geometry, rays, light, 1e-4f * glm::length(box.hi - box.lo));
        }
    }
    const std::size_t hits = castRays(geometry, rays, kind != "shadow");
    std::printf("%s %s %s (%s): %zu rays, %zu hits\n", sceneName.c_str(), kind.c_str(), accel.c_str(),
                std::string(simd::pathName(simd::activePath())).c_str(), rays.size(), hits);
    return 0;
}

}  // namespace
}  // namespace lightpath

int main(int argc, char** argv) {
    const auto oneOf = [](const std::string& word, std::initializer_list<const char*> choices) {
        for (const char* choice : choices)
            if (word == choice) return true;
        return false;
    };
    if (argc < 4 || argc > 5 || !oneOf(argv[1], {"bunny", "dragon", "grid", "cornell-mirror"}) ||
        !oneOf(argv[2], {"primary", "shadow", "random", "build"}) || !oneOf(argv[3], {"bvh", "embree"}) ||
        (argc == 5 && std::string(argv[4]) != "baseline")) {
        std::fprintf(stderr, "ray_cost: expected bunny|dragon|grid|cornell-mirror primary|shadow|random|build bvh|embree [baseline]\n");
        return 2;
    }
    if (argc == 5) lightpath::simd::setPath(lightpath::simd::Path::Baseline);
    return lightpath::run(argv[1], argv[2], argv[3]);
}
