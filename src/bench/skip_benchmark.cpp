#include "bench/skip_benchmark.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <functional>
#include <thread>

#include "util/timing.h"
#include "film/aov_set.h"
#include "render/renderer.h"
#include "scene/scene_loader.h"
#include "film/aov_presets.h"

namespace lightpath {

SkipBenchmarkResult runSkipBenchmark(const std::filesystem::path& scenePath, bool quick) {
    SkipBenchmarkResult result;
    Scene scene = loadScene(scenePath);
    if (quick) {
        scene.camera.height = scene.camera.height * 320 / scene.camera.width;
        scene.camera.width = 320;
    }
    result.scene = scenePath.filename().string();
    result.width = scene.camera.width;
    result.height = scene.camera.height;
    result.samplesPerPixel = 2;
    result.repetitions = quick ? 3 : 7;

    const AovSet classes(classesSet());
    const AovSet rayCasting(std::vector<lpe::NamedExpression>{{"raycast", "E(D|G)L"}});
    const AovSet none(std::vector<lpe::NamedExpression>{});
    RenderOptions withBeauty;
    withBeauty.samplesPerPixel = result.samplesPerPixel;
    withBeauty.threads = 1;  // one worker: CPU time then measures the render, not thread scheduling
    RenderOptions withoutBeauty = withBeauty;
    withoutBeauty.writeBeauty = false;

    struct Config {
        std::string request;
        const AovSet& aovs;
        RenderOptions options;
    };
    const std::vector<Config> configs = {
        {"full: beauty + classes", classes, withBeauty},
        {"E(D|G)L only, --no-beauty", rayCasting, withoutBeauty},
        {"beauty only, --aovs none", none, withBeauty},
    };
    std::vector<unsigned long long> rays(configs.size());
    std::vector<RayCounters> counters(configs.size());
    std::vector<std::function<void()>> jobs;
    for (std::size_t i = 0; i < configs.size(); ++i) {
        jobs.push_back([&, i] {
            const Renderer renderer(scene, configs[i].aovs, configs[i].options);
            counters[i] = renderer.render().stats.rays;
            rays[i] = counters[i].total();
        });
    }
    const std::vector<double> seconds = medianSeconds(jobs, result.repetitions);
    for (std::size_t i = 0; i < configs.size(); ++i) result.rows.push_back({configs[i].request, seconds[i], rays[i]});
    result.restrictedOverFull = seconds[1] / seconds[0];
    result.aovsOverBeauty = seconds[0] / seconds[2];
    result.media = scene.media.size();
    for (const RayCounters& c : counters) {
        result.mediumSegments += c.mediumSegments;
        result.mediumShadowRays += c.mediumShadow;
    }
    return result;
}

namespace {

struct ScalingConfiguration {
    std::string name;
    std::string integrator;
    const AovSet& aovs;
};

}  // namespace

ThreadScalingResult runThreadScalingBenchmark(const std::filesystem::path& scenePath, bool quick) {
    ThreadScalingResult result;
    Scene scene = loadScene(scenePath);
    const int width = quick ? 160 : 320;
    scene.camera.height = std::max(1, scene.camera.height * width / scene.camera.width);
    scene.camera.width = width;
    result.scene = scenePath.filename().string();
    result.width = scene.camera.width;
    result.height = scene.camera.height;
    result.samplesPerPixel = 2;
    result.repetitions = quick ? 1 : 5;
    result.threads = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));

    const AovSet classes(classesSet());
    const AovSet none(std::vector<lpe::NamedExpression>{});
    const std::vector<ScalingConfiguration> configurations{
        {"raycast", "raycast", classes}, {"whitted", "whitted", classes}, {"path", "path", classes},
        {"bdpt", "bdpt", classes},       {"radiosity", "radiosity", classes},
        {"whitted, --aovs none", "whitted", none}};
    const int threadCounts[2] = {1, result.threads};
    struct Samples {
        std::vector<double> wall, cpu;
    };
    std::vector<std::array<Samples, 2>> samples(configurations.size());
    using Clock = std::chrono::steady_clock;
    for (int r = 0; r < result.repetitions; ++r) {
        for (std::size_t c = 0; c < configurations.size(); ++c) {  // interleaved: load hits all alike
            for (int t = 0; t < 2; ++t) {
                RenderOptions options;
                options.integrator = configurations[c].integrator;
                options.samplesPerPixel = result.samplesPerPixel;
                options.threads = threadCounts[t];
                const auto started = Clock::now();
                // The renderer's construction is radiosity's parallel solve (and every integrator's
                // BVH build, the same for all): timed with the render.
                const Renderer renderer(scene, configurations[c].aovs, options);
                const RenderStats stats = renderer.render().stats;
                samples[c][t].wall.push_back(std::chrono::duration<double>(Clock::now() - started).count());
                const double busiest = *std::max_element(stats.workerCpuSeconds.begin(), stats.workerCpuSeconds.end());
                samples[c][t].cpu.push_back(stats.serialCpuSeconds + busiest);
            }
        }
    }
    for (std::size_t c = 0; c < configurations.size(); ++c) {
        ThreadScalingRow row;
        row.configuration = configurations[c].name;
        for (int t = 0; t < 2; ++t) {
            row.wall[t] = median(samples[c][t].wall);
            row.cpuEstimate[t] = median(samples[c][t].cpu);
        }
        result.rows.push_back(row);
    }
    return result;
}

}  // namespace lightpath
