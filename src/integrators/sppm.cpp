#include "integrators/sppm.h"

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

#include "integrators/registry.h"
#include "util/progress.h"

namespace lightpath {
namespace {

// Pass i's photon paths are seeded by this, the render's seed, i and their index alone.
constexpr std::uint64_t kSppmSeed = 0x7370706dull;  // "sppm"

}  // namespace

float sppmRadius(float firstRadius, double alpha, int pass) {
    double r2 = double(firstRadius) * double(firstRadius);
    for (int i = 1; i <= pass; ++i) r2 *= (double(i) + alpha) / double(i + 1);
    return float(std::sqrt(r2));
}

void SppmIntegrator::preprocess(const RenderContext& context) {
    const auto started = std::chrono::steady_clock::now();
    const ParameterValues* p = context.parameters;
    const std::uint64_t count = p ? static_cast<std::uint64_t>(p->integer("photons")) : kDefaultSppmPhotons;
    const int passCount = p && p->has("passes") ? int(p->integer("passes")) : std::max(1, context.samplesPerPixel);
    const float firstRadius = p && p->has("photon-radius") ? p->number("photon-radius") : defaultPhotonRadius(context.scene);
    const double alpha = p && p->has("alpha") ? p->number("alpha") : kDefaultSppmAlpha;
    // Every pass is kept until the last pixel has read it: their photons together are bounded as
    // one photon map's are.
    if (double(count) * double(passCount) > double(kMaxPhotons))
        throw std::invalid_argument("sppm would keep " + std::to_string(count) + " photons x " + std::to_string(passCount) +
                                    " passes, more than " + std::to_string(kMaxPhotons) +
                                    ": lower --photons or --passes (--spp)");
    const std::optional<lpe::SuffixReader> reader = requestedPhotonReader(context);
    passes_.clear();
    passes_.reserve(std::size_t(passCount));
    stats_ = {};
    // A bar of passes while they are shot, as radiosity shows its solve; Ctrl-C stops between passes.
    ProgressBar progress(passCount, context.progress, "photon passes", context.preprocessSteps);
    for (int pass = 0; pass < passCount; ++pass) {
        if (context.cancel != nullptr && context.cancel->load(std::memory_order_relaxed)) break;
        const float radius = sppmRadius(firstRadius, alpha, pass);
        const std::uint64_t seed = mixBits(mixBits(kSppmSeed ^ context.seed) ^ std::uint64_t(pass));
        PhotonSet set = shootRequestedPhotons(context, reader ? &*reader : nullptr, count, seed);
        stats_.shot += set.counts.shot;
        stats_.causticStored += set.counts.caustic;
        stats_.globalStored += set.counts.global;
        Pass maps{PhotonMap(std::move(set.caustic), std::move(set.causticEvents), radius, set.counts.shot),
                  PhotonMap(std::move(set.global), std::move(set.globalEvents), radius, set.counts.shot)};
        stats_.bytes += maps.caustic.bytes() + maps.global.bytes();
        passes_.push_back(std::move(maps));
        stats_.lastRadius = radius;
        progress.tileDone();
    }
    stats_.radius = stats_.causticRadius = firstRadius;
    stats_.passes = passCount;
    stats_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
}

void SppmIntegrator::traceCameraRay(const Ray& ray, PathState& path) const {
    if (passes_.empty()) return;
    const Pass& pass = passes_[std::size_t(path.sampleIndex) % passes_.size()];
    traceEyeToPhotons(ray, path, [&](const ShadingPoint& point, const Rgb& throughput, int bounces) {
        addPhotonDensity(point, throughput, bounces, pass.caustic, pass.caustic.radius(), path);
        addPhotonDensity(point, throughput, bounces, pass.global, pass.global.radius(), path);
    });
}

}  // namespace lightpath

// Reaches what photon mapping reaches (photon.cpp): every bounce from the lights, the background
// only directly or through mirrors and glass.
LIGHTPATH_REGISTER_INTEGRATOR(lightpath::underPointLights(lightpath::integratorRow(
    "sppm", "stochastic progressive photon mapping: photon passes whose radius shrinks, so the blur vanishes",
    "E.*[<L.[^'ambient']>O]|ES*B",
    "progressive photon mapping follows every bounce, but adds no ambient term (ka Ia) and sees the background only "
    "directly or through mirrors and glass",
    [] { return std::unique_ptr<lightpath::Integrator>(std::make_unique<lightpath::SppmIntegrator>()); },
    lightpath::ShadowRays::Always, 6,
    {{.name = "photons", .type = lightpath::ParameterType::Integer, .defaultText = "20000",
      .range = {1.0, static_cast<double>(lightpath::kMaxPhotons)}, .doc = "photon paths shot from the lights per pass"},
     {.name = "passes", .type = lightpath::ParameterType::Integer, .range = {1.0, static_cast<double>(lightpath::kMaxPhotons)},
      .doc = "photon passes; pixel sample k reads pass k mod passes (default: --spp, one pass per sample)"},
     {.name = "photon-radius", .type = lightpath::ParameterType::Number, .unit = "scene units",
      .range = lightpath::kPositive,
      .doc = "the first pass's search radius (default: 1% of the diagonal of the scene's bounded shapes)"},
     {.name = "alpha", .type = lightpath::ParameterType::Number, .defaultText = "0.6667",
      .range = {0.0, 1.0, true, false},
      .doc = "the share of new photons each pass keeps: r_{i+1}^2 = r_i^2 (i + alpha) / (i + 1)"}}),
    "ES*(D|G).*L"))
