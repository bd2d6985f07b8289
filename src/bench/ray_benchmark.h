#pragma once
// `lightpath bench rays`: ray throughput of our BVH and of Embree on the same rays, in one run.
// Wall-clock time (the figures are rays per second of a multi-threaded loop, which CPU time would
// not show), median of interleaved repetitions. Figures only: nothing here passes or fails.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace lightpath {

struct RayBenchmarkRow {
    std::string scene;   // "CornellBox-Original", "CornellBox-Sphere", "bunny", "dragon", "grid-1M"
    std::string rays;    // primary, random, shadow, build
    std::string accel;   // bvh, embree
    int threads = 1;
    double millionsPerSecond = 0.0;  // rays, or triangles for build
    // Rays per second of the busiest thread's CPU time: what an idle machine would give, as the
    // renders' CPU estimate (load from other processes stretches wall time, barely this).
    double cpuMillionsPerSecond = 0.0;
};

// A render of CornellBox-Mirror (ray casting, Whitted or path tracing), and how much of its time
// is not ray traversal.
struct RenderThroughput {
    std::string integrator;  // raycast, whitted, path
    std::string accel;
    int threads = 1;
    double seconds = 0.0;
    double cpuEstimateSeconds = 0.0;  // serial + busiest worker CPU time: the idle-machine time
    unsigned long long rays = 0;
    double millionRaysPerSecond = 0.0;
    double traversalSeconds = 0.0;  // its rays at the throughputs measured for that scene
    double shadingOverhead = 0.0;   // (seconds - traversalSeconds) / traversalSeconds
    // The same by CPU time: the render's CPU estimate against its rays at the CPU-time throughputs.
    double traversalCpuSeconds = 0.0;
    double shadingOverheadCpu = 0.0;
};

struct RayBenchmarkResult {
    int primarySide = 0;  // primary rays: side x side pinhole image
    int randomRays = 0;
    int repetitions = 0;
    int allThreads = 1;
    bool embree = false;  // whether this build could compare against Embree
    std::string simdPath;  // our BVH's traversal: "avx2", "sse2" or "portable"
    std::vector<RayBenchmarkRow> rows;
    std::vector<RenderThroughput> renders;
    std::vector<std::string> notes;  // e.g. how many closest hits Embree and we disagree on
};

struct RayBenchmarkOptions {
    bool quick = false;
    // Scene names to run (see RayBenchmarkRow::scene; "grid" for the height field); empty: all,
    // and then the render of CornellBox-Mirror too.
    std::vector<std::string> scenes;
    int repetitions = 0;  // 0: 3 (quick: 1)
};

// The scene names `scenes` may hold.
std::vector<std::string> rayBenchmarkScenes();

// `sceneDirectory` holds the shipped scenes (cornell-*.toml, bunny.toml, dragon.toml). `log` receives one line
// per finished measurement, so a long run shows it is alive.
RayBenchmarkResult runRayBenchmark(const std::filesystem::path& sceneDirectory, const RayBenchmarkOptions& options,
                                   const std::function<void(const std::string&)>& log);

}  // namespace lightpath
