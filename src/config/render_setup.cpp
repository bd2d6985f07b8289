#include "config/render_setup.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <optional>

#include "config/cli_errors.h"
#include "config/exit_codes.h"
#include "config/lpe_verdict.h"
#include "film/aov_presets.h"
#include "integrators/event_symbols.h"
#include "integrators/registry.h"
#include "lpe/analysis.h"
#include "lpe/error.h"
#include "lpe/path_string.h"
#include "lpe/reading.h"
#include "render/memory_limit.h"
#include "scene/scene_loader.h"

namespace lightpath {
namespace {

constexpr int kMaxResolution = 16384;
constexpr int kMaxSamplesPerPixel = 1 << 20;

[[noreturn]] void badInput(const std::string& message) { throw CLI::RuntimeError(message, kExitBadInput); }

}  // namespace

void RenderSetup::addOptions(CLI::App& command) {
    command.add_option("scene", scenePath, "Scene file (TOML, see scenes/README.md)")->required();
    std::string integratorHelp;
    for (const IntegratorInfo& info : integrators())
        integratorHelp += (integratorHelp.empty() ? "" : "; ") + std::string(info.name) + ": " + info.summary + " (" +
                          info.pathLanguage + ")";
    command.add_option("--integrator", integrator, integratorHelp)->check(oneOf(integratorNames()))->capture_default_str();
    command.add_option("--lpe", lpes,
                       "An AOV as [name=]EXPR, e.g. --lpe 'direct=E(D|G)L'; repeatable. Replaces the default "
                       "classes set unless --aovs classes is also given");
    std::vector<std::string> presets = aovPresetNames();
    presets.emplace_back("none");
    command.add_option("--aovs", aovs, "Predefined AOV set: " + aovPresetHelp())->check(oneOf(presets));
    command.add_option("--spp", samplesPerPixel, "Samples per pixel (1 = through the pixel centre)")
        ->check(CLI::Range(1, kMaxSamplesPerPixel))
        ->capture_default_str();
    command.add_option("--sampler", sampler,
                       "Pixel sample sequence: sobol (Owen-scrambled, low discrepancy), stratified, or independent")
        ->check(oneOf({"independent", "stratified", "sobol"}))
        ->capture_default_str();
    command.add_option("--filter", filter,
                       "Pixel reconstruction filter, by filter importance sampling: box (the pixel's square), "
                       "tent (radius 1), gaussian (sigma 0.5, radius 1.5) or blackman-harris (radius 1.5, as "
                       "Cycles' default); a single sample per pixel always goes through the centre")
        ->check(oneOf({"box", "tent", "gaussian", "blackman-harris"}))
        ->capture_default_str();
    command.add_option("--target-error", targetError,
                       "Adaptive sampling: stop a pixel once the standard error of its mean is below this "
                       "fraction of it (e.g. 0.02); --spp is then the most a pixel may take")
        ->check(CLI::Range(0.0, 1.0));
    command.add_option("--max-depth", maxDepth, "Most specular bounces (whitted), scattering events (path) or bounces (radiosity)")
        ->check(CLI::Range(0, kMaxDepth))
        ->capture_default_str();
    command.add_option("--resolution", resolution,
                       "Image size WxH, overriding the scene's; the vertical field of view is kept");
    command.add_option("--threads", threads, "Worker threads (0 = all cores)")->check(CLI::Range(0, 1024));
    command.add_option("--seed", seed, "Seed of the per-pixel sample sequences");
    command.add_flag("--no-beauty", noBeauty,
                     "Compute only the requested AOVs (no beauty, no rest): paths none of them accepts are not traced");
    command.add_option("--accel", accel,
                       "Closest-hit and shadow-ray search: bvh (ours), embree (if built with it; triangles) "
                       "or none (test every primitive)")
        ->check(oneOf({"bvh", "embree", "none"}))
        ->capture_default_str();
    command.add_flag("--quiet", quiet,
                     "No progress bar (shown on a terminal for renders over a second) and no warnings; errors are "
                     "always shown");
    command.add_option("--robust", robust,
                       "Numerics: on (stable sphere test, watertight triangles, error-bound ray offsets) or off "
                       "(the lecture's b^2-4ac, Moller-Trumbore with |det| < 1e-6, t_min = --epsilon)")
        ->check(oneOf({"on", "off"}))
        ->capture_default_str();
    command.add_option("--sphere-test", sphereTest, "Override --robust for spheres: stable or naive")
        ->check(oneOf({"stable", "naive"}));
    command.add_option("--triangle-test", triangleTest, "Override --robust for triangles: watertight or moller-trumbore")
        ->check(oneOf({"watertight", "moller-trumbore"}));
    command.add_option("--ray-offset", rayOffset,
                       "Override --robust for secondary ray origins: robust, wachter-binder, epsilon, none or "
                       "own-primitive (the lecture's: ignore the surface the ray leaves)")
        ->check(oneOf({"robust", "wachter-binder", "epsilon", "none", "own-primitive"}));
    command.add_option("--epsilon", epsilon, "t_min of --ray-offset epsilon")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    CLI::Option* size = command.add_option("--patch-size", patchSize,
                                           "radiosity: target patch edge in scene units (default: from --patches)")
                            ->check(CLI::PositiveNumber);
    command.add_option("--patches", patchBudget, "radiosity: the most patches; the finest patch size within it")
        ->check(CLI::Range(std::size_t{1}, std::size_t{1} << 18))
        ->capture_default_str()
        ->excludes(size);
    command.add_option("--form-factor-rays", formFactorRays,
                       "radiosity: hemisphere rays per side of each patch (a square number, stratified)")
        ->check(CLI::Range(1, 1 << 16))
        ->capture_default_str();
    command.add_option("--light-samples", lightSamples, "radiosity: shadow rays per side of each patch and light")
        ->check(CLI::Range(1, 1 << 16))
        ->capture_default_str();
    command.add_option("--radiosity-display", radiosityDisplay,
                       "radiosity: smooth (vertex radiosities interpolated, Gouraud) or flat (one value per patch)")
        ->check(CLI::IsMember({"smooth", "flat"}))
        ->capture_default_str();
    command.add_option("--shadows", shadows,
                       "Shadow rays of raycast and whitted: on (default) or off (every light counts as visible: "
                       "Szymczak's formula with S_i = 1, what the raster integrator shows)")
        ->check(oneOf({"on", "off"}));
    command.add_flag("--no-skip", noSkip,
                     "Trace every ray and evaluate every term, even those that cannot contribute (for comparison)");
}

Scene RenderSetup::loadScene() const {
    Scene scene;
    try {
        scene = lightpath::loadScene(scenePath);
    } catch (const SceneError& e) {
        badInput(e.what());
    }
    const Warnings warn(quiet);
    for (const std::string& warning : scene.warnings) warn(warning);
    if (!resolution.empty()) {
        int width = 0, height = 0;
        char x = 0, extra = 0;
        const int read = std::sscanf(resolution.c_str(), "%d%c%d%c", &width, &x, &height, &extra);
        if (read != 3 || (x != 'x' && x != 'X'))
            badInput("--resolution: expected WIDTHxHEIGHT such as 640x480, got \"" + resolution + "\"");
        if (width < 1 || height < 1 || width > kMaxResolution || height > kMaxResolution)
            badInput("--resolution: each side must be 1.." + std::to_string(kMaxResolution) + ", got " + resolution);
        scene.camera.width = width;
        scene.camera.height = height;
    }
    return scene;
}

std::vector<lpe::NamedExpression> RenderSetup::expressions(const Scene* scene) const {
    std::vector<lpe::NamedExpression> set;
    const std::string preset = aovs.empty() ? (lpes.empty() ? "classes" : "none") : aovs;
    if (const AovPreset* found = findAovPreset(preset)) set = found->expressions(scene);
    for (std::size_t i = 0; i < lpes.size(); ++i) set.push_back(parseNamedExpression(lpes[i], i + 1));
    return set;
}

// The one judge (config/lpe_verdict.h) decides: an --lpe no path of this integrator can match in any
// scene is refused before the render, with the reason; one only black in this scene (a label it
// lacks, a volume) is rendered with one short warning; a preset's AOV the integrator cannot fill is
// written black and said in --stats, not warned about.
void RenderSetup::refuseNeverFilled(const std::vector<lpe::NamedExpression>& set, const Scene& scene,
                                    const std::function<void(const std::string&)>& warn) const {
    const IntegratorInfo* info = findIntegrator(integrator);
    if (!info) badInput("--integrator: " + choiceMessage(integrator, integratorNames()));
    for (const auto& e : set) {
        const Judgement judgement = judgeExpression(e, info, &scene);
        if (judgement.verdict == Verdict::Refused)
            badInput("--lpe " + e.name + ": " + refusalMessage(e, info, judgement.reason));
        if (judgement.verdict != Verdict::PresetBlack && !judgement.reason.empty()) warn(warningMessage(e, judgement));
    }
}

AovSet RenderSetup::buildAovSet(const Scene& scene, std::vector<std::string>* warnings) const {
    const auto set = expressions(&scene);
    std::optional<AovSet> aovs;
    try {
        aovs.emplace(set);
    } catch (const lpe::SyntaxError& e) {
        for (const auto& expression : set)
            if (expression.expression == e.text()) badInput("--lpe " + expression.name + ": " + e.what());
        badInput(e.what());
    } catch (const std::exception& e) {
        badInput(std::string("--lpe: ") + e.what());
    }
    const Warnings printed(quiet);
    const auto warn = [&](const std::string& message) {
        if (warnings != nullptr) warnings->push_back(message);
        else printed(message);
    };
    refuseNeverFilled(set, scene, warn);
    // Presets never warn about themselves: the taxonomy's AOVs overlap on purpose.
    for (const auto& e : set)
        if (!isPresetMember(e))
            for (const std::string& warning : lpe::readExpression(e.expression).warnings) warn("--lpe " + e.name + ": " + warning);
    if (set.size() > 1) {
        // Overlapping AOVs count the same light twice; say so with a path both accept. Not among a
        // preset's own AOVs, nor for an AOV black in this scene (it counts nothing).
        const IntegratorInfo* info = findIntegrator(integrator);
        const auto blackHere = [&](const lpe::NamedExpression& e) {
            return judgeExpression(e, info, &scene).verdict == Verdict::BlackHere;
        };
        for (const lpe::Overlap& o : lpe::analyse(set, "E.*L").overlaps) {
            const auto& a = set[o.first];
            const auto& b = set[o.second];
            if ((isPresetMember(a) && isPresetMember(b)) || blackHere(a) || blackHere(b)) continue;
            warn("AOVs " + a.name + " and " + b.name + " overlap: both accept " + lpe::toCompactString(o.example) + " (" +
                 lpe::toExpressionString(o.example) + "); their sum counts such light twice");
        }
    }
    return std::move(*aovs);
}

void RenderSetup::warnEmptyAovs(const Film& film, const AovSet& aovs, const Scene& scene) const {
    const IntegratorInfo* info = findIntegrator(integrator);
    const Warnings warn(quiet);
    for (std::size_t o = 0; o < aovs.expressions().size(); ++o) {
        const std::size_t layer = o + 1;  // after the beauty
        bool empty = true;
        for (int y = 0; y < film.height() && empty; ++y)
            for (int x = 0; x < film.width() && empty; ++x) empty = isBlack(film.at(layer, x, y));
        const auto& e = aovs.expressions()[o];
        // AOVs that can never be filled here were refused, warned about or noted before the render.
        if (!empty || !info || judgeExpression(e, info, &scene).verdict != Verdict::Fillable) continue;
        warn("AOV " + e.name + " (" + e.expression + ") received nothing in this render: --integrator " + integrator +
             " can produce its paths, but none reached it at " + std::to_string(film.width()) + "x" +
             std::to_string(film.height()) + ", " + std::to_string(samplesPerPixel) + " spp, --max-depth " +
             std::to_string(maxDepth));
    }
}

void RenderSetup::refuseBeyondMemory(const PixelMemory& memory, std::uint64_t outputBytes) const {
    const std::uint64_t needed = memory.total() + outputBytes;
    const MemoryLimit limit = memoryLimit();
    if (needed <= limit.bytes) return;
    std::string parts;
    const auto part = [&](std::uint64_t bytes, const std::string& what) {
        if (bytes > 0) parts += (parts.empty() ? "" : ", ") + what + " " + formatBytes(bytes);
    };
    part(memory.film, "film");
    part(memory.splats, "splat film");
    part(memory.preprocess, integrator + "'s preprocess");
    part(outputBytes, "PNG encoding");
    // Every part grows with the pixels: scaling both sides by sqrt(limit / needed) fits.
    const double scale = std::sqrt(static_cast<double>(limit.bytes) / static_cast<double>(needed));
    const int width = std::max(1, static_cast<int>(memory.width * scale));
    const int height = std::max(1, static_cast<int>(memory.height * scale));
    std::string change = "render fewer pixels (--resolution " + std::to_string(width) + "x" + std::to_string(height) + " fits)";
    if (memory.film > 0)
        change = "render fewer layers (--aovs none keeps beauty and rest; fewer --lpe; --no-beauty) or " + change;
    badInput(memory.describe() + " needs " + formatBytes(needed) + " of memory (" + parts + "), more than the " +
             formatBytes(limit.bytes) + " that " + limit.bound + " leaves this process: " + change);
}

RenderOptions RenderSetup::renderOptions() const {
    RenderOptions options;
    options.integrator = integrator;
    options.maxDepth = maxDepth;
    options.samplesPerPixel = samplesPerPixel;
    options.threads = threads;
    options.seed = seed;
    parseSamplerKind(sampler, options.sampler);  // validated by the option's oneOf check
    parsePixelFilterKind(filter, options.filter);  // likewise
    options.targetError = targetError;
    options.writeBeauty = !noBeauty;
    options.skip = !noSkip;
    if (!shadows.empty()) options.shadows = shadows == "on";
    options.accelerator = accel == "embree" ? Accelerator::Embree
                          : accel == "none" ? Accelerator::BruteForce
                                            : Accelerator::Bvh;
    options.progress = !quiet;
    options.numerics = robust == "off" ? NumericsOptions::naive() : NumericsOptions{};
    if (!sphereTest.empty()) options.numerics.sphere = sphereTest == "naive" ? SphereTest::Naive : SphereTest::Stable;
    if (!triangleTest.empty())
        options.numerics.triangle = triangleTest == "watertight" ? TriangleTest::Watertight : TriangleTest::MollerTrumbore;
    if (!rayOffset.empty())
        options.numerics.offset = rayOffset == "robust"           ? RayOffset::Robust
                                  : rayOffset == "wachter-binder" ? RayOffset::WachterBinder
                                  : rayOffset == "epsilon"        ? RayOffset::FixedEpsilon
                                  : rayOffset == "none"           ? RayOffset::None
                                                                  : RayOffset::OwnPrimitive;
    options.numerics.epsilon = epsilon;
    options.radiosity.patchSize = patchSize;
    options.radiosity.patchBudget = patchBudget;
    options.radiosity.formFactorRays = formFactorRays;
    options.radiosity.lightSamples = lightSamples;
    options.radiosity.display = radiosityDisplay == "flat" ? RadiosityDisplay::Flat : RadiosityDisplay::Smooth;
    return options;
}

}  // namespace lightpath
