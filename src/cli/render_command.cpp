#include "cli/render_command.h"

#include <sys/resource.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>

#include "cli/render_flags.h"
#include "config/exit_codes.h"
#include "config/lpe_verdict.h"
#include "config/messages.h"
#include "io/image_writer.h"
#include "io/text_file.h"

namespace lightpath {
namespace {

struct RenderCommand {
    RenderFlags flags;
    std::string output;
    std::string readyFile;  // created once Ctrl-C is handled and rendering begins (scripts, tests)
    bool stats = false;
};

// Wall time spent writing the output.
struct WriteStats {
    double seconds = 0.0;
    std::size_t files = 0;
};

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double peakMemoryMiB() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_maxrss) / 1024.0;  // Linux reports KiB
}

void printStats(const RenderStats& stats, const WriteStats& write, const std::string& integrator) {
    const RayCounters& r = stats.rays;
    const auto n = [](std::uint64_t v) { return static_cast<unsigned long long>(v); };
    std::printf("rays cast     camera %llu, shadow %llu, reflection %llu, refraction %llu (total %llu)\n",
                n(r.camera), n(r.shadow), n(r.reflection), n(r.refraction), n(r.total()));
    std::printf("rays skipped  camera %llu (no requested output can accept)\n", n(r.cameraDead));
    std::printf("              shadow %llu: %llu light behind the surface, %llu zero contribution, "
                "%llu no requested output accepts the light\n",
                n(r.shadowBehind + r.shadowZero + r.shadowDead), n(r.shadowBehind), n(r.shadowZero), n(r.shadowDead));
    std::printf("              reflection %llu, refraction %llu (no requested output can accept)\n",
                n(r.reflectionDead), n(r.refractionDead));
    std::printf("media         %llu segments through a medium, %llu rays scattered in one (V), %llu single-scattering "
                "points, %llu shadow rays attenuated\n",
                n(r.mediumSegments), n(r.volume), n(r.singleScattering), n(r.mediumShadow));
    std::printf("glossy terms  %llu evaluated, %llu skipped (the material's glossy lobe is zero, e.g. ks = 0)\n",
                n(r.glossyEvaluated), n(r.glossyAbsent));
    std::printf("time          %.3f s on %d thread%s (%.3f s CPU): %.0f samples/s, %.2f M rays/s\n", stats.seconds,
                stats.threads, stats.threads == 1 ? "" : "s", stats.cpuSeconds, static_cast<double>(stats.samples) / stats.seconds,
                static_cast<double>(r.total()) / stats.seconds * 1e-6);
    std::printf("wall time     rendering %.3f s, writing %.3f s (%zu file%s)\n", stats.seconds, write.seconds, write.files,
                write.files == 1 ? "" : "s");
    if (!stats.workerCpuSeconds.empty()) {
        // CPU time is what load on the machine does not stretch: serial + the busiest worker is
        // the render's time on an idle machine.
        std::string workers;
        double busiest = 0.0;
        for (double s : stats.workerCpuSeconds) {
            char text[32];
            std::snprintf(text, sizeof text, "%s%.3f", workers.empty() ? "" : " + ", s);
            workers += text;
            busiest = std::max(busiest, s);
        }
        std::printf("cpu time      workers %s s, serial %.3f s: %.3f s on an idle machine\n", workers.c_str(),
                    stats.serialCpuSeconds, stats.serialCpuSeconds + busiest);
    }
    // What ran before the render and the times above leave out: a radiosity render's solve can be
    // most of the command's time.
    std::printf("preparing     BVH built in %.3f s, the %s integrator's preprocess %.3f s (before the render, "
                "not in the times above)\n",
                stats.accelerator.buildSeconds, integrator.c_str(), stats.preprocessSeconds);
    std::printf("non-finite contributions dropped: %llu\n", n(r.nonFinite));
    if (r.eventOverflow > 0) std::printf("paths cut at the event stack's bound: %llu\n", n(r.eventOverflow));
    std::printf("peak memory   %.1f MiB (resident set, whole process)\n", peakMemoryMiB());
}

void printBdptStats(const BdptStats& b) {
    std::printf("bdpt          light walks per camera sample: %.4g (%s)\n", b.lightWalkFraction, b.reason.c_str());
    if (b.candidates.empty()) return;
    std::printf("              pilot of %llu samples in %.3f s; per sample, variance x work (rays), and the standard\n"
                "              error of its difference from the least:\n",
                static_cast<unsigned long long>(b.pilotSamples), b.seconds);
    for (const BdptStats::Candidate& c : b.candidates)
        std::printf("              %-8.4g %.4g x %.3g = %.4g (+- %.2g)%s\n", c.fraction, c.variance, c.work,
                    c.variance * c.work, c.error, c.fraction == b.lightWalkFraction ? "  <- chosen" : "");
}

void printRadiosityStats(const RadiosityStats& r) {
    std::printf("radiosity     %zu patches (size %.4g) in %zu clusters, %llu form-factor rays, %llu shadow rays\n",
                r.patches, double(r.patchSize), r.clusters, static_cast<unsigned long long>(r.formFactorRays),
                static_cast<unsigned long long>(r.shadowRays));
    if (r.refineRounds > 0) {
        std::printf("              refined: %zu patches cut into four in %d rounds (where the error estimate asked)\n",
                    r.refined, r.refineRounds);
        if (r.clustersCut > 0)
            std::printf("              refined: %zu clusters cut into the eighths of their cells\n", r.clustersCut);
    }
    std::printf("              %d iterations (%d light-bounces over %d lights solved), residual %.3g, solved in %.3f s\n",
                r.iterations, r.lightBouncesSolved, r.lightsSolved, r.residual, r.seconds);
    if (!r.unresolved.empty()) std::printf("              not resolved: %s\n", r.unresolved.c_str());
}

void printPhotonStats(const PhotonStats& p) {
    if (p.passes > 1) {
        std::printf("photons       %llu shot in %d passes, %llu stored (%llu caustic, %llu global), radius %.4g, "
                    "after the last pass %.4g (pixels' mean), %.1f MiB, shot in %.3f s\n",
                    static_cast<unsigned long long>(p.shot), p.passes,
                    static_cast<unsigned long long>(p.causticStored + p.globalStored),
                    static_cast<unsigned long long>(p.causticStored), static_cast<unsigned long long>(p.globalStored),
                    double(p.radius), double(p.lastRadius), double(p.bytes) / (1024.0 * 1024.0), p.seconds);
        return;
    }
    std::printf("photons       %llu shot, %llu stored (%llu caustic within %.4g, %llu global within %.4g), %.1f MiB, "
                "shot in %.3f s\n",
                static_cast<unsigned long long>(p.shot), static_cast<unsigned long long>(p.causticStored + p.globalStored),
                static_cast<unsigned long long>(p.causticStored), double(p.causticRadius),
                static_cast<unsigned long long>(p.globalStored), double(p.radius), double(p.bytes) / (1024.0 * 1024.0),
                p.seconds);
}

void printAcceleratorStats(const std::string& accel, const AcceleratorStats& a) {
    if (accel == "none") {
        std::printf("accelerator   none: every ray tests every primitive\n");
        return;
    }
    std::printf("accelerator   %s: built in %.1f ms, BVH %zu nodes (%.1f KiB)%s\n", accel.c_str(), a.buildSeconds * 1e3,
                a.nodes, static_cast<double>(a.nodeBytes) / 1024.0,
                accel == "embree" ? " over the spheres; Embree holds the triangles" : "");
}

// Ctrl-C stops the workers after their current tile; nothing is written. Set from the signal
// handler, so it must be lock-free.
std::atomic<bool> interrupted{false};
static_assert(std::atomic<bool>::is_always_lock_free, "set from a signal handler");

void run(const RenderCommand& command) {
    const RenderConfig& config = command.flags.config();
    std::signal(SIGINT, [](int) { interrupted.store(true); });
    setActivity("loading " + config.scenePath);
    const Scene scene = config.loadScene();
    const Judge judge = config.judge(scene);
    const AovSet aovs = config.buildAovSet(scene, judge);
    RenderOptions options = config.renderOptions();
    options.cancel = &interrupted;
    PixelMemory memory;
    try {
        memory = Renderer::pixelMemory(scene, aovs, options);
    } catch (const std::invalid_argument& e) {
        throw CLI::RuntimeError(e.what(), kExitBadInput);
    }
    // Check the output name, that every file of it can be written, and that the film fits in
    // memory, before spending time on the scene's structures or the render.
    const Film probe(1, 1, memory.layers);
    try {
        for (const auto& file : outputFiles(probe, command.output))
            if (const auto why = whyCannotWrite(file)) throw ImageWriteError(*why);
    } catch (const ImageWriteError& e) {
        throw CLI::RuntimeError(std::string("-o: ") + e.what(), kExitBadInput);
    }
    config.refuseBeyondMemory(
        memory, encodingBytes(command.output, memory.width, memory.height, memory.layers.size(), options.threads));
    setActivity("preparing to render " + memory.describe());
    std::unique_ptr<Renderer> renderer;
    try {
        renderer = std::make_unique<Renderer>(scene, aovs, options);
    } catch (const std::invalid_argument& e) {
        throw CLI::RuntimeError(e.what(), kExitBadInput);
    }

    if (!command.readyFile.empty() && !std::ofstream(command.readyFile))
        throw CLI::RuntimeError("--ready-file: cannot create " + command.readyFile, kExitFailure);

    setActivity("rendering " + memory.describe());
    const RenderResult result = renderer->render();
    if (result.cancelled) throw CLI::RuntimeError("interrupted: no image written", kExitInterrupted);
    ImageMetadata metadata{{"lightpath:scene", config.scenePath},
                           {"lightpath:integrator", options.integrator},
                           {"lightpath:spp", std::to_string(options.samplesPerPixel)},
                           {"lightpath:max_depth", std::to_string(options.maxDepth)},
                           {"lightpath:seconds", std::to_string(result.stats.seconds)},
                           // the workers' own CPU time, which load on the machine does not stretch
                           {"lightpath:cpu_seconds", std::to_string(result.stats.cpuSeconds)}};
    for (const auto& e : aovs.expressions()) metadata.emplace_back("lightpath:lpe:" + e.name, e.expression);
    // A preset's AOV this integrator or this scene cannot fill is written black, so the set still
    // sums to the beauty; said here and in --stats, not as a warning (config/lpe_verdict.h).
    const std::vector<BlackAov> black = blackPresetAovs(aovs.expressions(), judge);
    for (const BlackAov& b : black) metadata.emplace_back("lightpath:black:" + b.name, b.reason);
    WriteStats write;
    const auto writeStart = std::chrono::steady_clock::now();
    try {
        setActivity("writing " + command.output);
        const auto files = writeFilm(result.film, command.output, metadata, options.threads);
        write.seconds = secondsSince(writeStart);
        write.files = files.size();
        for (const auto& file : files) std::cout << "wrote " << file.string() << "\n";
    } catch (const ImageWriteError& e) {
        throw CLI::RuntimeError(e.what(), kExitFailure);
    }
    config.warnEmptyAovs(result.film, aovs, judge);
    if (result.stats.radiosity && !result.stats.radiosity->unresolved.empty())
        Warnings(config.quiet)(result.stats.radiosity->unresolved);
    if (command.stats) {
        printStats(result.stats, write, options.integrator);
        printAcceleratorStats(config.accel, result.stats.accelerator);
        for (const BlackAov& b : black) {
            const std::string as = b.inThisScene ? "as this scene leaves it under --integrator " + options.integrator
                                                 : "as --integrator " + options.integrator + " always leaves it";
            std::printf("black AOV     %s, %s (%s); written, so the AOVs still sum to the beauty\n", b.name.c_str(),
                        as.c_str(), b.reason.c_str());
        }
        if (result.stats.radiosity) printRadiosityStats(*result.stats.radiosity);
        if (result.stats.photon) printPhotonStats(*result.stats.photon);
        if (result.stats.bdpt) printBdptStats(*result.stats.bdpt);
    }
}

}  // namespace

void addRenderCommand(CLI::App& app) {
    auto command = std::make_shared<RenderCommand>();
    CLI::App* sub = app.add_subcommand("render", "Render a scene into a beauty image and its light path AOVs");
    command->flags.addOptions(*sub);
    sub->add_option("-o,--output", command->output,
                    "Output: NAME.exr (one multi-layer EXR) or NAME.png (NAME.png + NAME.<aov>.png)")
        ->required();
    sub->add_flag("--stats", command->stats, "Print rays cast by kind, time and throughput, rendering and writing time");
    sub->add_option("--ready-file", command->readyFile,
                    "Create this (empty) file once Ctrl-C is handled and rendering begins: a script may then "
                    "interrupt the render");
    sub->footer(
        "Without --lpe the `classes` AOVs are written: raycast E(D|G)L, raytrace ES+(D|G)L, mirror ES+L,\n"
        "emission EL, indirect ES*(D|G)(D|G|S)+L. `rest` (light no AOV accepts) is always written.\n\n"
        "Examples:\n"
        "  lightpath render scenes/lecture-room.toml -o out/room.png\n"
        "  lightpath render scenes/mirror-sphere.toml -o out/m.exr --integrator whitted --max-depth 8 --stats\n"
        "  lightpath render scenes/szymczak-three-lights.toml -o out/s.png --lpe \"ambient=E.*<L.'ambient'>\"\n"
        "      --lpe \"red=E.*<L.'red-lamp'>\"\n"
        "  lightpath render scenes/glass-sphere.toml -o out/g.png --spp 16 --resolution 320x240");
    sub->callback([command] {
        reportingConfigErrors([&] {
            command->flags.apply();
            run(*command);
        });
    });
}

}  // namespace lightpath
