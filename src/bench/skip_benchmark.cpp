#include "bench/skip_benchmark.h"

#include <functional>

#include "bench/timing.h"
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
    std::vector<std::function<void()>> jobs;
    for (std::size_t i = 0; i < configs.size(); ++i) {
        jobs.push_back([&, i] {
            const Renderer renderer(scene, configs[i].aovs, configs[i].options);
            rays[i] = renderer.render().stats.rays.total();
        });
    }
    const std::vector<double> seconds = medianSeconds(jobs, result.repetitions);
    for (std::size_t i = 0; i < configs.size(); ++i) result.rows.push_back({configs[i].request, seconds[i], rays[i]});
    result.restrictedOverFull = seconds[1] / seconds[0];
    result.aovsOverBeauty = seconds[0] / seconds[2];
    return result;
}

}  // namespace lightpath
