#include "integrators/photon.h"

#include <chrono>
#include <cmath>

#include "integrators/registry.h"
#include "lpe/suffix_reader.h"
#include "scene/framing.h"

namespace lightpath {
namespace {

// Photons are merged only on a surface facing as the eye's point does (Jensen 2001, 7.2: the
// disc rather than the sphere), so a corner's other wall does not leak into it.
constexpr float kNormalAgreement = 0.9f;
// Photon paths are seeded by this, the render's seed and their index alone.
constexpr std::uint64_t kPhotonSeed = 0x70686f746f6eull;  // "photon"

// Pushes a photon's events, its last scattering first, down to its first: the light's walk
// reversed. False, with nothing left pushed, when the automaton dies on the way.
bool pushPhotonEvents(PathState& path, std::span<const PathEvent> history, int bounces) {
    const std::size_t before = path.size();
    for (int i = bounces; i >= 1; --i) {
        if (!path.push(history[std::size_t(i)])) {
            while (path.size() > before) path.pop();
            return false;
        }
    }
    return true;
}

// Whether `photon`, `distance2` from `point`, lies on the point's side of a surface facing as
// its own (within `radius`): the merge's geometric test.
bool mergeable(const Photon& photon, const ShadingPoint& point, float distance2, float radius) {
    return distance2 < radius * radius && std::fabs(glm::dot(photon.normal, point.normal)) >= kNormalAgreement;
}

struct PhotonUse {
    const lpe::SuffixReader* reader;
    const EventSymbols* symbols;
};

// Whether a path ending in these light-side events (the light first) after one of the merge
// events may be accepted by a requested output: they are read backwards from the light, then the
// merge; the eye's events, not known yet, are any prefix.
bool completesAcceptedPath(const void* state, std::span<const PathEvent> lightSide, std::span<const PathEvent> merges) {
    const PhotonUse& use = *static_cast<const PhotonUse*>(state);
    thread_local lpe::SuffixReader::StateSet suffix, longer;
    use.reader->prepend(use.reader->accepting(), (*use.symbols)(lightSide[0]), suffix);
    for (std::size_t i = 1; i < lightSide.size(); ++i) {
        use.reader->prepend(suffix, (*use.symbols)(lightSide[i]), longer);
        std::swap(suffix, longer);
    }
    for (const PathEvent& merge : merges) {
        use.reader->prepend(suffix, (*use.symbols)(merge), longer);
        if (use.reader->completable(longer)) return true;
    }
    return false;
}

}  // namespace

float defaultPhotonRadius(const Scene& scene) {
    const Bounds bounds = sceneBounds(scene);
    if (bounds.empty()) return 1.0f;
    const float diagonal = glm::length(bounds.hi - bounds.lo);
    return diagonal > 0.0f ? kDefaultRadiusShare * diagonal : 1.0f;
}

void addPhotonDensity(const ShadingPoint& point, const Rgb& throughput, int eyeBounces, const PhotonMap& map,
                      float radius, PathState& path, int pass) {
    const RenderContext& ctx = path.context;
    const float kernel = 1.0f / (kPi * radius * radius);
    const std::span<const PathEvent> events = map.events();
    const std::size_t before = path.size();
    for (int lobe = 0; lobe < int(point.bsdf.lobes().size()); ++lobe) {
        if (point.bsdf.lobe(lobe).delta() || !point.bsdf.has(lobe)) continue;
        if (!path.push(point.eventOf(lobe))) continue;
        const std::size_t withMerge = path.size();
        map.forEachWithin(point.hit.point, [&](const Photon& photon, std::uint32_t index, float distance2) {
            if (!mergeable(photon, point, distance2, radius)) return;
            if (eyeBounces + 1 + photon.bounces > ctx.maxDepth) return;
            const float cosine = std::fabs(glm::dot(point.normal, photon.wi));
            if (!(cosine > 0.0f)) return;
            // eval is f |cos theta_i|; the photon's flux already holds the cosine of its arrival.
            const Rgb f = point.bsdf.eval(lobe, point.wo, photon.wi) / cosine;
            if (isBlack(f)) return;
            const std::span<const PathEvent> history = events.subspan(photon.history, std::size_t(photon.bounces) + 1);
            const PathEvent& light = history[0];
            if (pushPhotonEvents(path, history, photon.bounces) && path.wants(light)) {
                const Rgb value = throughput * f * photon.power * kernel;
                if (path.explaining()) {
                    const TermFactor factors[] = {{"throughput", throughput},
                                                  {"f", f},
                                                  {"photon power", photon.power},
                                                  {"kernel 1/(pi r^2)", Rgb(kernel)},
                                                  {"photon", Rgb(float(index)), false},
                                                  {"distance", Rgb(std::sqrt(distance2)), false},
                                                  {"pass", Rgb(float(pass)), false}};
                    path.emit(light, value, std::span(factors).first(pass >= 0 ? 7 : 6));
                } else {
                    path.emit(light, value);
                }
            }
            while (path.size() > withMerge) path.pop();
        });
        while (path.size() > before) path.pop();
    }
}

std::uint64_t countPhotonsWithin(const ShadingPoint& point, const PhotonMap& map, float radius) {
    std::uint64_t found = 0;
    map.forEachWithin(point.hit.point, [&](const Photon& photon, std::uint32_t, float distance2) {
        found += mergeable(photon, point, distance2, radius) ? 1 : 0;
    });
    return found;
}

std::optional<lpe::SuffixReader> requestedPhotonReader(const RenderContext& context) {
    // Unless every path is wanted, a photon is kept only when some requested output may accept a
    // path ending in its events (the automaton read backwards, lpe/suffix_reader.h).
    std::optional<lpe::SuffixReader> reader;
    if (!context.keepAllPaths) reader.emplace(context.automaton, context.requested);
    return reader;
}

PhotonSet shootRequestedPhotons(const RenderContext& context, const lpe::SuffixReader* reader, std::uint64_t count,
                                std::uint64_t seed) {
    const PhotonUse use{reader, &context.symbols};
    return shootPhotons(context, count, seed, reader ? &completesAcceptedPath : nullptr, &use);
}

void PhotonIntegrator::preprocess(const RenderContext& context) {
    const auto started = std::chrono::steady_clock::now();
    const ParameterValues* p = context.parameters;
    const std::uint64_t count = p ? static_cast<std::uint64_t>(p->integer("photons")) : kDefaultPhotons;
    const float radius = p && p->has("photon-radius") ? p->number("photon-radius") : defaultPhotonRadius(context.scene);
    const float causticRadius = p && p->has("caustic-radius") ? p->number("caustic-radius") : radius;
    const std::optional<lpe::SuffixReader> reader = requestedPhotonReader(context);
    PhotonSet set = shootRequestedPhotons(context, reader ? &*reader : nullptr, count, mixBits(kPhotonSeed ^ context.seed));
    caustic_ = PhotonMap(std::move(set.caustic), std::move(set.causticEvents), causticRadius, set.counts.shot);
    global_ = PhotonMap(std::move(set.global), std::move(set.globalEvents), radius, set.counts.shot);
    stats_ = {};
    stats_.shot = set.counts.shot;
    stats_.causticStored = set.counts.caustic;
    stats_.globalStored = set.counts.global;
    stats_.bytes = caustic_.bytes() + global_.bytes();
    stats_.radius = radius;
    stats_.causticRadius = causticRadius;
    stats_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
}

void PhotonIntegrator::traceCameraRay(const Ray& ray, PathState& path) const {
    traceEyeToPhotons(ray, path, [&](const ShadingPoint& point, const Rgb& throughput, int bounces) {
        addPhotonDensity(point, throughput, bounces, caustic_, caustic_.radius(), path);
        addPhotonDensity(point, throughput, bounces, global_, global_.radius(), path);
    });
}

}  // namespace lightpath

// Every bounce from the lights; the background only seen directly or through mirrors and glass.
// Under point lights: every path from the eye's first diffuse or glossy vertex on, photons and
// shadow rays reaching the light by any bounces.
LIGHTPATH_REGISTER_INTEGRATOR(lightpath::underPointLights(lightpath::integratorRow(
    "photon", "photon mapping (Jensen): photons from the lights, caustics seen in mirrors included",
    "E.*[<L.[^'ambient']>O]|ES*B",
    "photon mapping follows every bounce, but adds no ambient term (ka Ia) and sees the background only directly or "
    "through mirrors and glass",
    [] { return std::unique_ptr<lightpath::Integrator>(std::make_unique<lightpath::PhotonIntegrator>()); },
    lightpath::ShadowRays::Always, 6,
    {{.name = "photons", .type = lightpath::ParameterType::Integer, .defaultText = "200000",
      .range = {1.0, static_cast<double>(lightpath::kMaxPhotons)}, .doc = "photon paths shot from the lights"},
     {.name = "photon-radius", .type = lightpath::ParameterType::Number, .unit = "scene units",
      .range = lightpath::kPositive,
      .doc = "the global map's search radius (default: 1% of the diagonal of the scene's bounded shapes)"},
     {.name = "caustic-radius", .type = lightpath::ParameterType::Number, .unit = "scene units",
      .range = lightpath::kPositive, .doc = "the caustic map's search radius (default: --photon-radius)"}}),
    "ES*(D|G).*L"))
