#include "cli/bench_command.h"

#include <cstdio>
#include <filesystem>
#include <memory>
#include <sstream>

#include "accel/simd_path.h"
#include "bench/machine.h"
#include "bench/ray_benchmark.h"
#include "bench/skip_benchmark.h"
#include "cli/bench_error_command.h"
#include "config/exit_codes.h"
#include "cli/shipped_scenes.h"
#include "io/text_file.h"
#include "scene/scene_loader.h"

namespace lightpath {
namespace {

struct SkipOptions {
    std::string scene;
    std::string json;
    bool quick = false;
};

// Each integrator from 1 thread to all, wall and idle-machine estimate, and what the classes AOVs
// cost on each (whitted against whitted with --aovs none).
void printThreadScaling(const ThreadScalingResult& t) {
    std::printf("\nthreads: %s (%dx%d, %d spp), 1 thread and %d, median of %d interleaved runs; wall seconds\n"
                "(radiosity's solve included) and the CPU estimate of the render on an idle machine (its serial\n"
                "CPU time + its busiest worker's: load from other processes does not stretch it)\n\n",
                t.scene.c_str(), t.width, t.height, t.samplesPerPixel, t.threads, t.repetitions);
    std::printf("%-22s %9s %9s %8s %12s %12s %8s\n", "integrator", "wall 1", "wall all", "x", "estimate 1",
                "estimate all", "x");
    for (const ThreadScalingRow& row : t.rows)
        std::printf("%-22s %9.3f %9.3f %7.2fx %12.3f %12.3f %7.2fx\n", row.configuration.c_str(), row.wall[0], row.wall[1],
                    row.wallScaling(), row.cpuEstimate[0], row.cpuEstimate[1], row.cpuScaling());
    const ThreadScalingRow* with = nullptr;
    const ThreadScalingRow* without = nullptr;
    for (const ThreadScalingRow& row : t.rows) {
        if (row.configuration == "whitted") with = &row;
        if (row.configuration == "whitted, --aovs none") without = &row;
    }
    if (with != nullptr && without != nullptr)
        for (int i = 0; i < 2; ++i)
            std::printf("classes AOVs on %d thread%s: %+.1f%% wall, %+.1f%% estimate\n", i == 0 ? 1 : t.threads,
                        i == 0 ? "" : "s", (with->wall[i] / without->wall[i] - 1.0) * 100.0,
                        (with->cpuEstimate[i] / without->cpuEstimate[i] - 1.0) * 100.0);
    std::printf("targets: every integrator >= 1.85x from 1 to 2 threads; the classes AOVs <= +5%% on each\n");
}

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
    std::printf("aovs_over_beauty     %.3f  (the six classes AOVs cost %+.1f%%; target: at most +5%%)\n",
                r.aovsOverBeauty, (r.aovsOverBeauty - 1.0) * 100.0);
    std::printf("media                %zu in the scene: %llu medium segments, %llu shadow rays attenuated%s\n", r.media,
                r.mediumSegments, r.mediumShadowRays,
                r.media == 0 ? " (no medium code ran: media cost this scene nothing)" : "");

    ThreadScalingResult t;
    try {
        t = runThreadScalingBenchmark(scene, options.quick);
    } catch (const SceneError& e) {
        throw CLI::RuntimeError(e.what(), kExitBadInput);
    }
    printThreadScaling(t);
    if (options.json.empty()) return;
    std::ostringstream json;
    json << "{\"restricted_over_full\": " << r.restrictedOverFull << ", \"aovs_over_beauty\": " << r.aovsOverBeauty
         << ", \"medium_segments\": " << r.mediumSegments << ", \"medium_shadow_rays\": " << r.mediumShadowRays
         << ", \"scene\": " << jsonString(r.scene) << ", \"machine\": " << jsonString(describeMachine())
         << ", \"rows\": [";
    for (std::size_t i = 0; i < r.rows.size(); ++i)
        json << (i ? ", " : "") << "{\"request\": " << jsonString(r.rows[i].request) << ", \"seconds\": " << r.rows[i].seconds
             << ", \"rays\": " << r.rows[i].raysCast << "}";
    json << "], \"threads\": " << t.threads << ", \"scaling\": [";
    for (std::size_t i = 0; i < t.rows.size(); ++i) {
        const ThreadScalingRow& row = t.rows[i];
        json << (i ? ", " : "") << "{\"configuration\": " << jsonString(row.configuration) << ", \"wall_seconds\": ["
             << row.wall[0] << ", " << row.wall[1] << "], \"cpu_estimate_seconds\": [" << row.cpuEstimate[0] << ", "
             << row.cpuEstimate[1] << "]}";
    }
    json << "]}\n";
    writeTextFileAtomically(options.json, json.str());
}

struct RaysOptions {
    std::string json;
    RayBenchmarkOptions benchmark;
    std::string simd;
};

// The figure of `accel` for the same scene, kind and thread count as `row`, or 0.
double counterpart(const RayBenchmarkResult& r, const RayBenchmarkRow& row, const std::string& accel, int threads) {
    for (const RayBenchmarkRow& other : r.rows)
        if (other.scene == row.scene && other.rays == row.rays && other.accel == accel && other.threads == threads)
            return other.millionsPerSecond;
    return 0.0;
}

void printRaysTable(const RayBenchmarkResult& r) {
    std::printf("%-20s %-8s %-7s %7s %12s %14s %12s\n", "scene", "rays", "accel", "threads", "M/s", "ours/embree",
                "x 1 thread");
    for (const RayBenchmarkRow& row : r.rows) {
        std::string ratio = "", scaling = "";
        char text[32];
        // Embree builds on all threads: our build is compared on as many.
        const double embree = row.rays == "build" ? counterpart(r, row, "embree", r.allThreads)
                                                  : counterpart(r, row, "embree", row.threads);
        if (row.accel == "bvh" && embree > 0.0 && (row.rays != "build" || row.threads == r.allThreads)) {
            std::snprintf(text, sizeof text, "%.2f", row.millionsPerSecond / embree);
            ratio = text;
        }
        const double single = counterpart(r, row, row.accel, 1);
        if (row.threads > 1 && single > 0.0) {
            std::snprintf(text, sizeof text, "%.2fx", row.millionsPerSecond / single);
            scaling = text;
        }
        std::printf("%-20s %-8s %-7s %7d %12.2f %14s %12s\n", row.scene.c_str(), row.rays.c_str(), row.accel.c_str(),
                    row.threads, row.millionsPerSecond, ratio.c_str(), scaling.c_str());
    }
}

void runRays(const RaysOptions& options) {
    RayBenchmarkResult r;
    if (!options.simd.empty()) simd::setPath(options.simd == "avx2" ? simd::Path::Avx2 : simd::Path::Baseline);
    try {
        r = runRayBenchmark(std::filesystem::path(shippedScene("bunny.toml")).parent_path(), options.benchmark,
                            [](const std::string& line) { std::fprintf(stderr, "bench rays: %s\n", line.c_str()); });
    } catch (const SceneError& e) {
        throw CLI::RuntimeError(e.what(), kExitBadInput);
    }
    // The machine first: figures from two vendors must not be mistaken for one another (issue #27).
    std::printf("machine: %s; our BVH traverses with %s\n"
                "bench rays: million rays per second (build: million triangles per second), wall time,\n"
                "median of %d interleaved runs; primary %dx%d pinhole, %d random rays, shadow rays from the\n"
                "primary hits to the first light. Triangles only, the same rays for every accelerator.\n"
                "Builds: ours on 1 thread and on %d (the same tree), Embree's on %d (its device creation not\n"
                "counted).%s\n\n",
                describeMachine().c_str(), r.simdPath.c_str(), r.repetitions, r.primarySide, r.primarySide, r.randomRays, r.allThreads, r.allThreads,
                r.embree ? "" : " This build has no Embree (LIGHTPATH_EMBREE=OFF): no comparison.");
    printRaysTable(r);
    std::printf("\n");
    for (const RenderThroughput& t : r.renders) {
        std::string scaling;
        for (const RenderThroughput& single : r.renders) {
            if (t.threads > 1 && single.threads == 1 && single.accel == t.accel && single.integrator == t.integrator) {
                char text[96];
                std::snprintf(text, sizeof text, "; %.2fx 1 thread (CPU estimate %.2fx)", single.seconds / t.seconds,
                              single.cpuEstimateSeconds / t.cpuEstimateSeconds);
                scaling = text;
            }
        }
        std::printf("render   CornellBox-Mirror, %s, %s, %d thread%s: %.3f s, %llu rays, %.2f M rays/s; "
                    "shading overhead %.0f%% of the estimated traversal time (%.3f s), by CPU time %.0f%% (%.3f s of "
                    "%.3f s)%s\n",
                    t.integrator.c_str(), t.accel.c_str(), t.threads, t.threads == 1 ? "" : "s", t.seconds, t.rays,
                    t.millionRaysPerSecond, 100.0 * t.shadingOverhead, t.traversalSeconds, 100.0 * t.shadingOverheadCpu,
                    t.traversalCpuSeconds, t.cpuEstimateSeconds, scaling.c_str());
    }
    for (const std::string& note : r.notes) std::printf("note     %s\n", note.c_str());
    std::printf("\ntargets (figures, not tests; issue #27): bunny and dragon ours/embree >= 1.2 primary, >= 1.0\n"
                "shadow and random, on 1 thread and on 2, on Intel and on AMD; build >= 3 M triangles/s on 2\n"
                "threads; >= 1.85x from 1 to 2 threads; shading overhead <= 50%% for raycast and whitted (path: reported)\n");
    if (options.json.empty()) return;
    std::ostringstream json;
    json << "[";
    bool first = true;
    const auto separator = [&] {
        json << (first ? "\n  " : ",\n  ");
        first = false;
    };
    for (const RayBenchmarkRow& row : r.rows) {
        separator();
        json << "{\"scene\": " << jsonString(row.scene) << ", \"rays\": " << jsonString(row.rays)
             << ", \"accel\": " << jsonString(row.accel) << ", \"threads\": " << row.threads << ", \""
             << (row.rays == "build" ? "mtris_per_s" : "mrays_per_s") << "\": " << row.millionsPerSecond << "}";
    }
    for (const RenderThroughput& t : r.renders) {
        separator();
        json << "{\"scene\": \"CornellBox-Mirror\", \"rays\": \"render\", \"integrator\": " << jsonString(t.integrator)
             << ", \"accel\": " << jsonString(t.accel) << ", \"shading_overhead\": " << t.shadingOverhead
             << ", \"shading_overhead_cpu\": " << t.shadingOverheadCpu
             << ", \"threads\": " << t.threads << ", \"mrays_per_s\": " << t.millionRaysPerSecond << "}";
    }
    json << "\n]\n";
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
        "request with --no-beauty, and the beauty alone. Prints restricted_over_full and aovs_over_beauty.\n"
        "Then every integrator (raycast, whitted, path, bdpt, radiosity) on 1 thread and on all, at 320\n"
        "pixels wide (--quick: 160), wall time and the idle-machine estimate from the workers' CPU time,\n"
        "and the classes AOVs' cost on each.\n\n"
        "Examples:\n"
        "  lightpath bench skip\n"
        "  lightpath bench skip --quick --json out/skip.json");
    sub->callback([skip] { runSkip(*skip); });

    auto rays = std::make_shared<RaysOptions>();
    CLI::App* raysCommand =
        bench->add_subcommand("rays", "Ray throughput of our BVH and of Embree on the same rays, 1 thread and all");
    raysCommand->add_option("--json", rays->json,
                            "Also write the rows [{\"scene\", \"rays\", \"accel\", \"threads\", \"mrays_per_s\"}, ...]; the renders'\n"
                            "rows add \"integrator\", \"shading_overhead\" and \"shading_overhead_cpu\"");
    raysCommand->add_flag("--quick", rays->benchmark.quick,
                          "256x256 primary rays, 65536 random rays, a 100k-triangle height field, 1 run: for CI");
    raysCommand->add_option("--scenes", rays->benchmark.scenes, "Only these scenes (no render line)")
        ->delimiter(',')
        ->check(CLI::IsMember(rayBenchmarkScenes()));
    raysCommand->add_option("--runs", rays->benchmark.repetitions, "Interleaved runs whose median is printed (default 3)")
        ->check(CLI::Range(1, 99));
    std::vector<std::string> paths{"baseline"};
    if (simd::supported(simd::Path::Avx2)) paths.push_back("avx2");
    raysCommand->add_option("--simd", rays->simd, "Our BVH's SIMD path (default: the widest this processor has)")
        ->check(CLI::IsMember(paths));
    raysCommand->footer(
        "Primary (pinhole), random (origins in the bounding box, uniform directions) and shadow rays, and\n"
        "the build, on CornellBox-Original, CornellBox-Sphere, the bunny (69k triangles), the dragon\n"
        "(100k) and the memory test's height field (1M; --quick: 100k); then renders of CornellBox-Mirror\n"
        "by ray casting, Whitted and path tracing, each with its shading overhead: the render's time beyond\n"
        "its rays' at the throughputs measured here, by wall time and by CPU time (the busiest thread's;\n"
        "read this one on a loaded machine). Prints M rays/s, ours/Embree and the 1 -> 2 thread scaling.\n\n"
        "Examples:\n"
        "  lightpath bench rays\n"
        "  lightpath bench rays --scenes bunny,dragon --runs 5\n"
        "  lightpath bench rays --quick --json out/rays.json");
    raysCommand->callback([rays] { runRays(*rays); });

    addBenchErrorCommand(*bench);
}

}  // namespace lightpath
