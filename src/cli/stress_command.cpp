#include "cli/stress_command.h"

#include <chrono>
#include <cstdio>
#include <memory>

#include "bench/machine.h"
#include "config/exit_codes.h"
#include "io/text_file.h"
#include "stress/stress_suite.h"

namespace lightpath {
namespace {

struct StressOptions {
    std::string json;
    bool quick = false;
};

void runStress(const StressOptions& options) {
    const auto started = std::chrono::steady_clock::now();
    const std::vector<ScoreRow> rows = runStressSuite({options.quick});
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    char header[512];
    std::snprintf(header, sizeof header, "lightpath stress%s: %.1f s on %s; fixed seeds; targets are the issue's, in float",
                  options.quick ? " --quick" : "", seconds, describeMachine().c_str());
    printScorecard(rows, header);
    if (!options.json.empty()) writeTextFileAtomically(options.json, scorecardJson(rows));
    if (!robustRowsAtTarget(rows)) throw CLI::RuntimeError("a robust row is above its target", kExitFailure);
}

}  // namespace

void addStressCommand(CLI::App& app) {
    auto options = std::make_shared<StressOptions>();
    CLI::App* stress = app.add_subcommand(
        "stress", "Numerical robustness scorecard: robust and naive intersection and ray-offset methods side by side");
    stress->add_flag("--quick", options->quick, "Fewer rays per row (the CI version, a few seconds)");
    stress->add_option("--json", options->json,
                       "Also write the rows as [{\"row\", \"method\", \"precision\", \"metric\", \"value\", \"target\"}, ...]");
    stress->footer(
        "Rows: sphere silhouette, sphere t, sphere spawn, watertight mesh, acne sweep, contact shadows,\n"
        "BVH = brute force, non-finite, render-level acne. Exit code 1 when a robust row is above its target.\n\n"
        "Examples:\n"
        "  lightpath stress --quick\n"
        "  lightpath stress --json out/stress.json");
    stress->callback([options] { runStress(*options); });
}

}  // namespace lightpath
