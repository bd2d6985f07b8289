#pragma once
// `lightpath bench skip`: what skipping buys, as time ratios measured in one run.
//   restricted_over_full  time of an E(D|G)L-only request (no beauty) / time of the full render
//                         (beauty + classes) on a mirror-heavy scene; target <= 1/1.5
//   aovs_over_beauty      time of beauty + the six classes AOVs / time of the beauty alone;
//                         target <= 1.05
// and the media work every render did (segments through a medium, attenuated shadow rays): zero in
// a scene without media, which runs no medium code at all (issue #24: media cost such a scene nothing)
// and every integrator's scaling from 1 thread to all (target >= 1.85x on 2 threads), with the
// classes AOVs' cost on 1 thread and on all (target <= 5% on each).
#include <filesystem>
#include <string>
#include <vector>

namespace lightpath {

struct SkipBenchmarkRow {
    std::string request;
    double seconds = 0.0;
    unsigned long long raysCast = 0;
};

struct SkipBenchmarkResult {
    std::string scene;
    int width = 0, height = 0, samplesPerPixel = 0, repetitions = 0;
    std::vector<SkipBenchmarkRow> rows;  // full (beauty + classes), restricted, beauty only
    double restrictedOverFull = 0.0;
    double aovsOverBeauty = 0.0;
    std::size_t media = 0;                      // the scene's [media]
    unsigned long long mediumSegments = 0;      // summed over the rows' renders
    unsigned long long mediumShadowRays = 0;    // summed over the rows' renders
};

SkipBenchmarkResult runSkipBenchmark(const std::filesystem::path& scene, bool quick);

// One configuration's render on 1 thread and on every hardware thread, medians of interleaved runs.
// Wall seconds are what a user waits for, and what load from other processes stretches; the CPU
// estimate (the render's serial CPU time plus its busiest worker's, RenderStats) is what the
// render would take on an idle machine, and grows with the thread count only through the render
// itself (serial parts, idle workers at the end, cache lines passed between cores).
struct ThreadScalingRow {
    std::string configuration;  // "whitted", ..., "whitted, --aovs none"
    double wall[2] = {0.0, 0.0};         // 1 thread, all threads
    double cpuEstimate[2] = {0.0, 0.0};  // 1 thread, all threads
    double wallScaling() const { return wall[0] / wall[1]; }
    double cpuScaling() const { return cpuEstimate[0] / cpuEstimate[1]; }
};

struct ThreadScalingResult {
    std::string scene;
    int width = 0, height = 0, samplesPerPixel = 0, repetitions = 0, threads = 1;
    // raycast, whitted, path, bdpt, radiosity (its solve included in the wall time), then Whitted
    // with the beauty alone (--aovs none) for the cost of the classes AOVs.
    std::vector<ThreadScalingRow> rows;
};

// Every integrator's scaling from 1 thread to all, and the classes AOVs' cost on each.
ThreadScalingResult runThreadScalingBenchmark(const std::filesystem::path& scene, bool quick);

}  // namespace lightpath
