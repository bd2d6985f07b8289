#include "cli/bench_error_command.h"

#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <sstream>
#include <utility>

#include "bench/error_benchmark.h"
#include "bench/machine.h"
#include "config/exit_codes.h"
#include "cli/shipped_scenes.h"
#include "io/text_file.h"

namespace lightpath {
namespace {

struct ErrorOptions {
    bool quick = false;
    bool integratorsOnly = false;
    std::string json;
    std::string csv = "out/bench-error.csv";
    std::string plot = "out/bench-error.png";
    std::string cache = "out/bench-cache";
};

std::string toCsv(const ErrorBenchmarkResult& r) {
    std::ostringstream csv;
    csv << "scene,integrator,sampler,spp,patches,seconds,rmse,relmse\n";
    for (const auto& row : r.rows)
        csv << row.scene << ',' << row.integrator << ',' << row.sampler << ',' << row.spp << ',' << row.patches << ','
            << row.seconds << ',' << row.rmse << ',' << row.relmse << '\n';
    return csv.str();
}

std::string toJson(const ErrorBenchmarkResult& r) {
    std::ostringstream json;
    json << "[";
    for (std::size_t i = 0; i < r.rows.size(); ++i) {
        const auto& row = r.rows[i];
        json << (i ? ",\n " : "") << "{\"scene\": " << jsonString(row.scene) << ", \"integrator\": " << jsonString(row.integrator)
             << ", \"sampler\": " << jsonString(row.sampler) << ", \"spp\": " << row.spp << ", \"patches\": " << row.patches
             << ", \"seconds\": " << row.seconds
             << ", \"rmse\": " << row.rmse << ", \"relmse\": " << row.relmse << "}";
    }
    json << "]\n";
    return json.str();
}

// plot_error.py's exit code when python3-matplotlib is missing; any other failure is the script's.
constexpr int kPlotWithoutMatplotlib = 3;

void run(const ErrorOptions& options) {
    // The outputs are written after minutes of rendering: refuse one that cannot be, first.
    for (const auto& [option, path] : {std::pair{"--csv", options.csv}, {"--json", options.json}, {"--plot", options.plot}})
        if (!path.empty())
            if (const auto why = whyCannotWrite(path)) throw CLI::RuntimeError(std::string(option) + ": " + *why, kExitBadInput);
    std::printf("bench error: path tracer and radiosity, CPU seconds on 1 thread, error against closed forms or a cached "
                "path-traced reference\n"
                "machine: %s\n\n", describeMachine().c_str());
    const ErrorBenchmarkResult r = runErrorBenchmark(options.quick, options.integratorsOnly, shippedScenesDirectory(), options.cache);
    std::printf("%-18s %-9s %-12s %6s %8s %10s %12s %12s\n", "scene", "method", "sampler", "spp", "patches", "seconds",
                "rmse", "relmse");
    for (const auto& row : r.rows)
        std::printf("%-18s %-9s %-12s %6d %8zu %10.4f %12.6f %12.6f\n", row.scene.c_str(), row.integrator.c_str(),
                    row.sampler.c_str(), row.spp, row.patches, row.seconds, row.rmse, row.relmse);
    std::printf("\n%-18s %-12s %10s %26s\n", "scene", "sampler", "slope", "time to reference error");
    std::printf("(samplers and radiosity: independent's error at its largest budget; path/bdpt: the path tracer's)\n");
    for (const auto& s : r.summaries) {
        if (s.timeRatio > 0.0) std::printf("%-18s %-12s %10.3f %25.2fx", s.scene.c_str(), s.sampler.c_str(), s.slope, s.timeRatio);
        else std::printf("%-18s %-12s %10.3f %26s", s.scene.c_str(), s.sampler.c_str(), s.slope, "-");
        if (s.raysPerSample > 0.0) std::printf("   %.2f rays/sample", s.raysPerSample);
        if (s.equalTimeErrorRatio > 0.0) std::printf("   error at path's time %.2fx", s.equalTimeErrorRatio);
        std::printf("\n");
    }
    std::printf("\ntargets: independent slope -0.5 +- 0.05; on area-light-plane sobol <= 0.5x and adaptive <= 0.33x of "
                "independent's time; on mirror-caustic path's error never falls and bdpt's does; on cornell-lamp\n"
                "bdpt within the cost of its extra strategies of path's time\n");

    writeTextFileAtomically(options.csv, toCsv(r));
    std::printf("wrote %s\n", options.csv.c_str());
    if (!options.json.empty()) {
        writeTextFileAtomically(options.json, toJson(r));
        std::printf("wrote %s\n", options.json.c_str());
    }
    if (!options.plot.empty()) {
        // The plot is drawn by Debian's python3 with python3-matplotlib; without them, the CSV stands.
        const std::filesystem::path script = shippedScenesDirectory().parent_path() / "scripts" / "plot_error.py";
        const std::string command = "/usr/bin/python3 '" + script.string() + "' '" + options.csv + "' '" + options.plot + "'";
        std::fflush(stdout);
        const int status = std::system(command.c_str());
        const int code = status != -1 && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
        if (code == 0) std::printf("wrote %s\n", options.plot.c_str());
        else if (code == kPlotWithoutMatplotlib)
            std::fprintf(stderr, "warning: no plot: python3-matplotlib is missing (apt-get install python3-matplotlib); "
                                 "the CSV stands\n");
        else std::fprintf(stderr, "warning: no plot: %s failed (exit %d, its message is above); the CSV stands\n",
                          script.string().c_str(), code);
    }
}

}  // namespace

void addBenchErrorCommand(CLI::App& bench) {
    auto options = std::make_shared<ErrorOptions>();
    CLI::App* sub = bench.add_subcommand("error", "Run time against error for each sampler and adaptive sampling");
    sub->add_flag("--quick", options->quick,
                  "Small images, budgets up to 32 spp (radiosity: 1024 patches), closed-form scenes only");
    sub->add_flag("--integrators", options->integratorsOnly,
                  "Only path tracing against bdpt (each render 3 times, interleaved, median CPU time)");
    sub->add_option("--json", options->json,
                    "Also write rows {scene, integrator, sampler, spp, patches, seconds, rmse, relmse}");
    sub->add_option("--csv", options->csv, "Where the CSV goes")->capture_default_str();
    sub->add_option("--plot", options->plot, "Where the log-log plot goes (empty: none)")->capture_default_str();
    sub->add_option("--cache", options->cache, "Folder for the cached high-sample reference of the lecture scene")
        ->capture_default_str();
    sub->footer(
        "Renders each scene at budgets 1, 2, 4, ... spp with independent, stratified and Sobol sampling and\n"
        "with adaptive sampling, prints RMSE against time, the fitted convergence slope, and the time each\n"
        "needs to reach the error independent sampling reaches with its largest budget. Then path tracing\n"
        "against bdpt on a mirror caustic (closed form), a glass ball's caustic under a small area light\n"
        "and the Cornell box under its lamp (cached path-traced references): bdpt's time to reach the\n"
        "path tracer's error at its largest budget, as a ratio, and its error at that budget's time.\n\n"
        "Examples:\n"
        "  lightpath bench error\n"
        "  lightpath bench error --quick --json out/error.json");
    sub->callback([options] { run(*options); });
}

}  // namespace lightpath
