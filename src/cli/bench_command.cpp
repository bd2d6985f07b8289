#include "cli/bench_command.h"

#include <cstdio>
#include <filesystem>
#include <memory>
#include <sstream>

#include "bench/machine.h"
#include "bench/skip_benchmark.h"
#include "cli/exit_codes.h"
#include "io/text_file.h"
#include "scene/scene_loader.h"

namespace lightpath {
namespace {

// A scene shipped in scenes/: found from the working directory, else in the source tree.
std::filesystem::path shippedScene(const std::string& name) {
    const std::filesystem::path local = std::filesystem::path("scenes") / name;
    if (std::filesystem::exists(local)) return local;
    return std::filesystem::path(LIGHTPATH_SOURCE_DIR) / "scenes" / name;
}

struct SkipOptions {
    std::string scene;
    std::string json;
    bool quick = false;
};

void runSkip(const SkipOptions& options) {
    const std::filesystem::path scene =
        options.scene.empty() ? shippedScene("mirror-hall.toml") : std::filesystem::path(options.scene);
    SkipBenchmarkResult r;
    try {
        r = runSkipBenchmark(scene, options.quick);
    } catch (const SceneError& e) {
        throw CLI::RuntimeError(e.what(), kExitBadInput);
    }
    std::printf("bench skip on %s (%dx%d, %d spp, 1 thread), CPU seconds, median of %d interleaved runs\n"
                "machine: %s\n\n", r.scene.c_str(),
                r.width, r.height, r.samplesPerPixel, r.repetitions, describeMachine().c_str());
    std::printf("%-30s %12s %14s\n", "request", "CPU seconds", "rays cast");
    for (const auto& row : r.rows) std::printf("%-30s %12.4f %14llu\n", row.request.c_str(), row.seconds, row.raysCast);
    std::printf("\nrestricted_over_full %.3f  (%.2fx faster; target: at least 1.5x, ratio <= 0.667)\n",
                r.restrictedOverFull, 1.0 / r.restrictedOverFull);
    std::printf("aovs_over_beauty     %.3f  (the five classes AOVs cost %+.1f%%; target: at most +5%%)\n",
                r.aovsOverBeauty, (r.aovsOverBeauty - 1.0) * 100.0);
    if (options.json.empty()) return;
    std::ostringstream json;
    json << "{\"restricted_over_full\": " << r.restrictedOverFull << ", \"aovs_over_beauty\": " << r.aovsOverBeauty
         << ", \"scene\": " << jsonString(r.scene) << ", \"machine\": " << jsonString(describeMachine())
         << ", \"rows\": [";
    for (std::size_t i = 0; i < r.rows.size(); ++i)
        json << (i ? ", " : "") << "{\"request\": " << jsonString(r.rows[i].request) << ", \"seconds\": " << r.rows[i].seconds
             << ", \"rays\": " << r.rows[i].raysCast << "}";
    json << "]}\n";
    writeTextFileAtomically(options.json, json.str());
}

}  // namespace

void addBenchCommand(CLI::App& app) {
    CLI::App* bench = app.add_subcommand("bench", "Benchmarks that print figures: time ratios measured in one run");
    bench->require_subcommand(1);

    auto skip = std::make_shared<SkipOptions>();
    CLI::App* sub = bench->add_subcommand("skip", "What skipping saves: a restricted request and the AOVs, timed against full renders");
    sub->add_option("--scene", skip->scene, "Scene to time (default: scenes/mirror-hall.toml, mirror-heavy)");
    sub->add_option("--json", skip->json, "Also write {\"restricted_over_full\", \"aovs_over_beauty\", ...} to this file");
    sub->add_flag("--quick", skip->quick, "Quarter-size images and 3 runs instead of 7");
    sub->footer(
        "Times, as medians of interleaved runs: the full render (beauty + classes), an E(D|G)L-only\n"
        "request with --no-beauty, and the beauty alone. Prints restricted_over_full and aovs_over_beauty.\n\n"
        "Examples:\n"
        "  lightpath bench skip\n"
        "  lightpath bench skip --quick --json out/skip.json");
    sub->callback([skip] { runSkip(*skip); });
}

}  // namespace lightpath
