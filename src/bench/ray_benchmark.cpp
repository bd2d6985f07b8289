#include "bench/ray_benchmark.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <memory>
#include <optional>
#include <thread>

#include "accel/simd_path.h"
#include "bench/ray_sets.h"
#include "util/timing.h"
#include "film/aov_set.h"
#include "accel/scene_geometry.h"
#include "lights/point_light.h"
#include "math/random.h"
#include "render/renderer.h"
#include "scene/camera.h"
#include "scene/scene_loader.h"
#include "film/aov_presets.h"

namespace lightpath {
namespace {

using Clock = std::chrono::steady_clock;

struct BenchScene {
    std::string name;
    std::string file;  // a shipped scene, or empty for the generated height field
};

struct Timed {
    double wall = 0.0;
    double busiestCpu = 0.0;  // CPU seconds of the thread that worked longest
};

// Rays handed out in chunks from an atomic counter: the same dynamic scheme as the renderer.
Timed timeParallel(std::size_t count, int threads, const std::function<void(std::size_t, std::size_t)>& work) {
    constexpr std::size_t kChunk = 4096;
    std::atomic<std::size_t> next{0};
    std::vector<double> cpu(static_cast<std::size_t>(threads), 0.0);
    const auto loop = [&](int thread) {
        const double started = threadCpuSeconds();
        for (std::size_t begin = next.fetch_add(kChunk); begin < count; begin = next.fetch_add(kChunk))
            work(begin, std::min(begin + kChunk, count));
        cpu[static_cast<std::size_t>(thread)] = threadCpuSeconds() - started;
    };
    const auto started = Clock::now();
    {
        std::vector<std::jthread> workers;
        for (int t = 1; t < threads; ++t) workers.emplace_back(loop, t);
        loop(0);
    }
    return {std::chrono::duration<double>(Clock::now() - started).count(), *std::max_element(cpu.begin(), cpu.end())};
}

struct Measured {
    std::string rays;
    std::string accel;
    int threads;
    std::vector<double> rates;
    std::vector<double> cpuRates;
};

}  // namespace

std::vector<std::string> rayBenchmarkScenes() {
    return {"CornellBox-Original", "CornellBox-Sphere", "bunny", "dragon", "grid"};
}

RayBenchmarkResult runRayBenchmark(const std::filesystem::path& directory, const RayBenchmarkOptions& options,
                                   const std::function<void(const std::string&)>& log) {
    const bool quick = options.quick;
    RayBenchmarkResult result;
    result.primarySide = quick ? 256 : 1024;
    result.randomRays = quick ? 1 << 16 : 1 << 20;
    result.repetitions = options.repetitions > 0 ? options.repetitions : quick ? 1 : 3;
    result.simdPath = std::string(simd::pathName(simd::activePath()));
    result.allThreads = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
    result.embree = embreeAvailable();

    std::vector<std::string> accels{"bvh"};
    if (result.embree) accels.push_back("embree");
    std::vector<int> threadCounts{1};
    if (result.allThreads > 1) threadCounts.push_back(result.allThreads);

    const std::size_t gridSide = quick ? 224 : 708;
    const std::string gridName = quick ? "grid-100k" : "grid-1M";
    const bool all = options.scenes.empty();
    const auto chosen = [&](const std::string& name) {
        return all || std::find(options.scenes.begin(), options.scenes.end(), name) != options.scenes.end();
    };
    std::vector<BenchScene> scenes;
    for (const BenchScene& scene : std::vector<BenchScene>{{"CornellBox-Original", "cornell-original.toml"},
                                                           {"CornellBox-Sphere", "cornell-sphere.toml"},
                                                           {"bunny", "bunny.toml"},
                                                           {"dragon", "dragon.toml"},
                                                           {gridName, ""}})
        if (chosen(scene.file.empty() ? "grid" : scene.name)) scenes.push_back(scene);
    if (all) scenes.push_back({"CornellBox-Mirror", "cornell-mirror.toml"});
    // Throughputs of the render scene (not tabled), to estimate the render's traversal time.
    std::vector<RayBenchmarkRow> renderSceneRows;
    for (const BenchScene& benchScene : scenes) {
        const bool renderSceneOnly = benchScene.name == "CornellBox-Mirror";
        const Scene scene =
            benchScene.file.empty() ? heightFieldScene(gridSide) : loadScene(directory / benchScene.file);
        // Triangles only: the comparison with Embree is on exactly the same primitives.
        const std::vector<Triangle>& triangles = scene.triangles;
        const double triangleCount = static_cast<double>(triangles.size());

        // Our build on 1 thread and on all, Embree's (on all its threads), interleaved.
        struct Build {
            std::string accel;
            int threads;
            std::vector<double> rates;
        };
        std::vector<Build> builds;
        for (int threads : threadCounts) builds.push_back({"bvh", threads, {}});
        if (result.embree) builds.push_back({"embree", result.allThreads, {}});
        std::vector<std::optional<SceneGeometry>> built(accels.size());
        for (int r = 0; r < result.repetitions; ++r) {
            for (Build& build : builds) {
                SceneGeometry geometry({}, {}, triangles, {}, build.accel == "bvh" ? Accelerator::Bvh : Accelerator::Embree,
                                       {}, static_cast<unsigned>(build.threads));
                build.rates.push_back(triangleCount / geometry.acceleratorStats().buildSeconds * 1e-6);
                if (r + 1 == result.repetitions) built[build.accel == "bvh" ? 0 : 1] = std::move(geometry);
            }
        }
        if (!renderSceneOnly)
            for (const Build& build : builds)
                result.rows.push_back({benchScene.name, "build", build.accel, build.threads, median(build.rates)});
        std::vector<SceneGeometry> geometries;
        for (std::optional<SceneGeometry>& geometry : built) geometries.push_back(std::move(*geometry));

        const Bounds box = triangleBox(triangles);
        const std::vector<Ray> primary = primaryRays(scene, result.primarySide);
        const std::vector<Ray> random = randomRays(box, result.randomRays);
        const Vec3 light = scene.lights.empty() ? box.hi : scene.lights.front()->position();
        const float lift = 1e-4f * glm::length(box.hi - box.lo);
        const std::vector<Ray> shadow = shadowRays(geometries.front(), primary, light, lift);

        if (result.embree) {
            // Same rays, two answers: how often the closest primitive differs (ties, shared edges).
            std::size_t differ = 0;
            for (const Ray& ray : random) {
                const auto ours = geometries[0].closestPrimitive(ray);
                const auto theirs = geometries[1].closestPrimitive(ray);
                if (ours.has_value() != theirs.has_value() || (ours && ours->primitive != theirs->primitive)) ++differ;
            }
            result.notes.push_back(benchScene.name + ": closest primitive differs from Embree's on " +
                                   std::to_string(differ) + " of " + std::to_string(random.size()) + " random rays");
        }

        std::vector<Measured> measured;
        for (const char* kind : {"primary", "random", "shadow"})
            for (const std::string& accel : accels)
                for (int threads : threadCounts) measured.push_back({kind, accel, threads, {}});
        for (int r = 0; r < result.repetitions; ++r) {
            for (Measured& m : measured) {  // interleaved: a burst of load hits every configuration
                const SceneGeometry& geometry = geometries[m.accel == "bvh" ? 0 : 1];
                const std::vector<Ray>& rays = m.rays == "primary" ? primary : m.rays == "random" ? random : shadow;
                std::atomic<std::size_t> hits{0};  // keeps the queries from being optimised away
                const bool closest = m.rays != "shadow";
                const Timed timed = timeParallel(rays.size(), m.threads, [&](std::size_t begin, std::size_t end) {
                    std::size_t found = 0;
                    for (std::size_t i = begin; i < end; ++i)
                        found += closest ? geometry.closestPrimitive(rays[i]).has_value() : geometry.occluded(rays[i]);
                    hits += found;
                });
                m.rates.push_back(static_cast<double>(rays.size()) / timed.wall * 1e-6);
                m.cpuRates.push_back(static_cast<double>(rays.size()) / timed.busiestCpu * 1e-6);
            }
        }
        for (const Measured& m : measured) {
            RayBenchmarkRow row{benchScene.name, m.rays, m.accel, m.threads, median(m.rates), median(m.cpuRates)};
            (renderSceneOnly ? renderSceneRows : result.rows).push_back(row);
        }
        log(benchScene.name + " done");
    }

    // End to end: renders of CornellBox-Mirror by ray casting, Whitted and path tracing, every ray
    // they cast per second; the configurations interleaved, as the ray sets are.
    if (!all) return result;
    Scene scene = loadScene(directory / "cornell-mirror.toml");
    scene.camera.width = scene.camera.height = quick ? 256 : 1024;
    const AovSet aovs(classesSet());
    struct RenderRun {
        std::string integrator;
        std::string accel;
        int threads;
        std::unique_ptr<Renderer> renderer;
        std::vector<double> seconds, cpuEstimates;
        RenderStats stats;
    };
    std::vector<RenderRun> runs;
    for (const char* integrator : {"raycast", "whitted", "path"}) {
        for (const std::string& accel : accels) {
            for (int threads : threadCounts) {
                RenderOptions options;
                options.integrator = integrator;
                options.threads = threads;
                options.accelerator = accel == "bvh" ? Accelerator::Bvh : Accelerator::Embree;
                runs.push_back({integrator, accel, threads, std::make_unique<Renderer>(scene, aovs, options), {}, {}, {}});
            }
        }
    }
    for (int r = 0; r < result.repetitions; ++r) {
        for (RenderRun& run : runs) {
            run.stats = run.renderer->render().stats;
            run.seconds.push_back(run.stats.seconds);
            run.cpuEstimates.push_back(run.stats.serialCpuSeconds + *std::max_element(run.stats.workerCpuSeconds.begin(),
                                                                                      run.stats.workerCpuSeconds.end()));
        }
    }
    for (const RenderRun& run : runs) {
        RenderThroughput t;
        t.integrator = run.integrator;
        t.accel = run.accel;
        t.threads = run.threads;
        t.seconds = median(run.seconds);
        t.cpuEstimateSeconds = median(run.cpuEstimates);
        t.rays = run.stats.rays.total();
        t.millionRaysPerSecond = static_cast<double>(t.rays) / t.seconds * 1e-6;
        const auto rate = [&](const char* kind, bool cpu) {
            for (const RayBenchmarkRow& row : renderSceneRows)
                if (row.rays == kind && row.accel == run.accel && row.threads == run.threads)
                    return (cpu ? row.cpuMillionsPerSecond : row.millionsPerSecond) * 1e6;
            return 0.0;
        };
        const RayCounters& c = run.stats.rays;
        // Camera rays are coherent like the primary set, mirror, glass and the path tracer's bounce
        // rays incoherent like the random set, shadow rays like the shadow set.
        const auto traversal = [&](bool cpu) {
            return static_cast<double>(c.camera) / rate("primary", cpu) +
                   static_cast<double>(c.reflection + c.refraction) / rate("random", cpu) +
                   static_cast<double>(c.shadow) / rate("shadow", cpu);
        };
        t.traversalSeconds = traversal(false);
        t.shadingOverhead = (t.seconds - t.traversalSeconds) / t.traversalSeconds;
        t.traversalCpuSeconds = traversal(true);
        t.shadingOverheadCpu = (t.cpuEstimateSeconds - t.traversalCpuSeconds) / t.traversalCpuSeconds;
        result.renders.push_back(t);
    }
    log("renders done");
    return result;
}

}  // namespace lightpath
