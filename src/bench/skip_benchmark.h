#pragma once
// `lightpath bench skip`: what skipping buys, as time ratios measured in one run.
//   restricted_over_full  time of an E(D|G)L-only request (no beauty) / time of the full render
//                         (beauty + classes) on a mirror-heavy scene; target <= 1/1.5
//   aovs_over_beauty      time of beauty + the five classes AOVs / time of the beauty alone;
//                         target <= 1.05
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
};

SkipBenchmarkResult runSkipBenchmark(const std::filesystem::path& scene, bool quick);

}  // namespace lightpath
