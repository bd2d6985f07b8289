#include "integrators/sppm.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

#include "integrators/registry.h"

namespace lightpath {
namespace {

// Pass i's photon paths are seeded by this, the render's seed, i and their index alone.
constexpr std::uint64_t kSppmSeed = 0x7370706dull;  // "sppm"

}  // namespace

SppmRender::SppmRender(const RenderContext& context, const SppmSettings& settings, int samplesPerPixel)
    : context_(context),
      settings_(settings),
      passes_(settings.passes > 0 ? settings.passes : std::max(1, samplesPerPixel)),
      samplesPerPass_(std::max(1, samplesPerPixel / passes_)),
      reader_(requestedPhotonReader(context)),
      pixels_(std::size_t(context.camera.width()) * std::size_t(context.camera.height()), settings.firstRadius),
      found_(pixels_.points(), 0) {
    stats_.radius = stats_.causticRadius = settings.firstRadius;
}

void SppmRender::beginPass(int pass) {
    const auto started = std::chrono::steady_clock::now();
    pass_ = pass;
    caustic_ = {};
    global_ = {};
    // The last pass's photons, one visible point's worth per pixel (the mean over its samples).
    for (std::size_t p = 0; p < pixels_.points(); ++p) {
        pixels_.update(p, double(found_[p]) / double(samplesPerPass_), settings_.alpha);
        found_[p] = 0;
    }
    // The grid's cells fit the largest radius a pixel still has (radii only shrink).
    float largest = 0.0f;
    for (std::size_t p = 0; p < pixels_.points(); ++p) largest = std::max(largest, pixels_.radius(p));
    const std::uint64_t seed = mixBits(mixBits(kSppmSeed ^ context_.seed) ^ std::uint64_t(pass));
    PhotonSet set = shootRequestedPhotons(context_, reader_ ? &*reader_ : nullptr, settings_.photons, seed);
    stats_.shot += set.counts.shot;
    stats_.causticStored += set.counts.caustic;
    stats_.globalStored += set.counts.global;
    caustic_ = PhotonMap(std::move(set.caustic), std::move(set.causticEvents), largest, set.counts.shot);
    global_ = PhotonMap(std::move(set.global), std::move(set.globalEvents), largest, set.counts.shot);
    stats_.bytes = std::max(stats_.bytes, caustic_.bytes() + global_.bytes() + pixels_.bytes() +
                                            found_.capacity() * sizeof(std::uint64_t));
    stats_.passes = pass + 1;
    stats_.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
}

void SppmRender::traceCameraRay(const Ray& ray, PathState& path, int x, int y) {
    const std::size_t pixel = std::size_t(y) * std::size_t(context_.camera.width()) + std::size_t(x);
    const float radius = pixels_.radius(pixel);
    traceEyeToPhotons(ray, path, [&](const ShadingPoint& point, const Rgb& throughput, int bounces) {
        addPhotonDensity(point, throughput, bounces, caustic_, radius, path, pass_);
        addPhotonDensity(point, throughput, bounces, global_, radius, path, pass_);
        // Only this pixel's worker writes its count.
        found_[pixel] += countPhotonsWithin(point, caustic_, radius) + countPhotonsWithin(point, global_, radius);
    });
}

PhotonStats SppmRender::stats() const {
    PhotonStats stats = stats_;
    double sum = 0.0;
    for (std::size_t p = 0; p < pixels_.points(); ++p) sum += pixels_.radius(p);
    stats.lastRadius = pixels_.points() > 0 ? float(sum / double(pixels_.points())) : settings_.firstRadius;
    return stats;
}

void SppmIntegrator::preprocess(const RenderContext& context) {
    const ParameterValues* p = context.parameters;
    settings_ = {};
    if (p) settings_.photons = static_cast<std::uint64_t>(p->integer("photons"));
    if (p && p->has("passes")) settings_.passes = int(p->integer("passes"));
    settings_.firstRadius = p && p->has("photon-radius") ? p->number("photon-radius") : defaultPhotonRadius(context.scene);
    if (p && p->has("alpha")) settings_.alpha = p->number("alpha");
}

void SppmIntegrator::traceCameraRay(const Ray&, PathState&) const {
    throw std::logic_error("sppm renders pass by pass: its camera rays go through startProgressive");
}

std::unique_ptr<ProgressiveRender> SppmIntegrator::startProgressive(const RenderContext& context, int samplesPerPixel) const {
    return std::make_unique<SppmRender>(context, settings_, samplesPerPixel);
}

}  // namespace lightpath

// Reaches what photon mapping reaches (photon.cpp): every bounce from the lights, the background
// only directly or through mirrors and glass.
LIGHTPATH_REGISTER_INTEGRATOR(lightpath::underPointLights(lightpath::integratorRow(
    "sppm", "stochastic progressive photon mapping: photon passes, each pixel's radius shrinking, so the blur vanishes",
    "E.*[<L.[^'ambient']>O]|ES*B",
    "progressive photon mapping follows every bounce, but adds no ambient term (ka Ia) and sees the background only "
    "directly or through mirrors and glass",
    [] { return std::unique_ptr<lightpath::Integrator>(std::make_unique<lightpath::SppmIntegrator>()); },
    lightpath::ShadowRays::Always, 6,
    {{.name = "photons", .type = lightpath::ParameterType::Integer, .defaultText = "20000",
      .range = {1.0, static_cast<double>(lightpath::kMaxPhotons)}, .doc = "photon paths shot from the lights per pass"},
     {.name = "passes", .type = lightpath::ParameterType::Integer, .range = {1.0, static_cast<double>(lightpath::kMaxPhotons)},
      .doc = "photon passes, each taking --spp / passes camera rays per pixel (at least one; default: --spp passes)"},
     {.name = "photon-radius", .type = lightpath::ParameterType::Number, .unit = "scene units",
      .range = lightpath::kPositive,
      .doc = "every pixel's first search radius (default: 1% of the diagonal of the scene's bounded shapes)"},
     {.name = "alpha", .type = lightpath::ParameterType::Number, .defaultText = "0.6667",
      .range = {0.0, 1.0, true, false},
      .doc = "the share of a pass's photons a pixel keeps: N' = N + alpha M, R'^2 = R^2 N' / (N + M)"}}),
    "ES*(D|G).*L"))
