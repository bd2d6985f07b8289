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
};

// The Whitted render of CornellBox-Mirror, and how much of its time is not ray traversal.
struct RenderThroughput {
    std::string accel;
    int threads = 1;
    double seconds = 0.0;
    double cpuEstimateSeconds = 0.0;  // serial + busiest worker CPU time: the idle-machine time
    unsigned long long rays = 0;
    double millionRaysPerSecond = 0.0;
    double traversalSeconds = 0.0;  // its rays at the throughputs measured for that scene
    double shadingOverhead = 0.0;   // (seconds - traversalSeconds) / traversalSeconds
};

struct RayBenchmarkResult {
    int primarySide = 0;  // primary rays: side x side pinhole image
    int randomRays = 0;
    int repetitions = 0;
    int allThreads = 1;
    bool embree = false;  // whether this build could compare against Embree
    std::vector<RayBenchmarkRow> rows;
    std::vector<RenderThroughput> renders;
    std::vector<std::string> notes;  // e.g. how many closest hits Embree and we disagree on
};

// `sceneDirectory` holds the shipped scenes (cornell-*.toml, bunny.toml, dragon.toml). `log` receives one line
// per finished measurement, so a long run shows it is alive.
RayBenchmarkResult runRayBenchmark(const std::filesystem::path& sceneDirectory, bool quick,
                                   const std::function<void(const std::string&)>& log);

}  // namespace lightpath
