#include "integrators/photon_map.h"

#include <algorithm>
#include <bit>

#include "geometry/spawn_ray.h"
#include "integrators/light_ray.h"
#include "integrators/integrator.h"
#include "integrators/shading_point.h"
#include "sampling/russian_roulette.h"
#include "sampling/sampler.h"
#include "util/parallel_chunks.h"

namespace lightpath {
namespace {

// Photons traced per chunk of work: chunks depend on the count alone, so on any thread count the
// photons come out in the same order.
constexpr std::size_t kPhotonsPerChunk = 4096;

// One map's photons and the histories they point into, for one chunk of paths.
struct MapPart {
    std::vector<Photon> photons;
    std::vector<PathEvent> events;
    // The current path's events copied so far, and where they start: the photons of one path share
    // the prefix of its history.
    std::size_t pathStart = 0, copied = 0;

    void beginPath() { copied = 0; }
    void store(Photon photon, std::span<const PathEvent> history) {
        if (copied == 0) pathStart = events.size();
        for (; copied < history.size(); ++copied) events.push_back(history[copied]);
        photon.history = static_cast<std::uint32_t>(pathStart);
        photons.push_back(photon);
    }
};

struct ChunkResult {
    MapPart caustic, global;
    std::uint64_t shot = 0;
};

// The events of the smooth lobes at `sp`, the merges the eye's side may read a photon there with
// (every smooth lobe, as addPhotonDensity reads them), in `out`.
std::span<const PathEvent> smoothEvents(const ShadingPoint& sp, std::array<PathEvent, kMaxLobes>& out) {
    std::size_t n = 0;
    for (int lobe = 0; lobe < int(sp.bsdf.lobes().size()) && n < out.size(); ++lobe)
        if (!sp.bsdf.lobe(lobe).delta()) out[n++] = sp.eventOf(lobe);
    return {out.data(), n};
}

void tracePhoton(const RenderContext& ctx, std::uint64_t index, std::uint64_t seed, double scale, PhotonFilter keep,
                 const void* keepState, ChunkResult& out) {
    Sampler sampler(SamplerKind::Independent, mixBits(seed ^ mixBits(index)), 0, 1);
    ++out.shot;
    const ChosenLight chosen = ctx.lights.chooseEmitter(sampler.next1D());
    const Vec2 uPoint = sampler.next2D(), uDirection = sampler.next2D();
    if (chosen.light == nullptr || !(chosen.probability > 0.0f)) return;
    const Light& light = *chosen.light;
    const EmittedRay e = light.sampleEmission(uPoint, uDirection);
    if (!(e.pdfPosition > 0.0f) || !(e.pdfDirection > 0.0f) || isBlack(e.radiance)) return;

    std::array<PathEvent, kMaxDepth + 1> history;
    std::array<PathEvent, kMaxLobes> merges;
    history[0] = light.event();
    history[0].position = e.ray.origin;
    int bounces = 0;
    bool allSpecular = true;
    out.caustic.beginPath();
    out.global.beginPath();

    const LightRay leaving = leaveLight(light, e, ctx.geometry);
    Ray ray = leaving.ray;
    const float cosine = leaving.cosine;
    // Phi = Le cos / (p(light) p(x) p(w) N): the flux one photon of N carries (Jensen 2001, 5.1).
    Rgb power = e.radiance * static_cast<float>(double(cosine) / (double(chosen.probability) * e.pdfPosition *
                                                                  e.pdfDirection * scale));
    Rgb throughput{1.0f};  // the product of the scattering weights so far
    for (;;) {
        const auto hit = ctx.geometry.intersect(ray);
        if (!hit) break;
        if (bounces == 0) {
            // The light's falloff as the light says (the lecture's attenuation) over the 1/d^2 the
            // photons' density already carries.
            const float d = glm::length(hit->point - e.ray.origin);
            power *= light.falloff(d) * d * d;
        }
        // A photon here ends a path of the eye's events, this hit, its `bounces` and the light.
        if (bounces + 1 > ctx.maxDepth) break;
        const ShadingPoint sp = makeShadingPoint(*hit, ray, ctx, TransportMode::Importance);
        if (bounces >= 1 && sp.bsdf.hasSmoothLobe() &&
            (keep == nullptr || keep(keepState, {history.data(), std::size_t(bounces) + 1}, smoothEvents(sp, merges)))) {
            const Photon photon{hit->point, sp.wo, sp.normal, power, 0, static_cast<std::uint8_t>(bounces)};
            (allSpecular ? out.caustic : out.global).store(photon, {history.data(), std::size_t(bounces) + 1});
        }
        if (bounces + 2 > ctx.maxDepth) break;  // a photon further on could not be merged within maxDepth
        const float uLobe = sampler.next1D();
        const Vec2 u = sampler.next2D();
        const auto sample = sp.bsdf.sample(sp.wo, uLobe, u);
        if (!sample) break;
        const LobeInfo& lobe = sp.bsdf.lobe(sample->lobe);
        power *= sample->weight;
        throughput *= sample->weight;
        if (bounces + 1 >= kRouletteVertices) {
            // Russian roulette on the path's throughput (not its flux, which carries 1/N), as
            // survivesRussianRoulette does it, with the flux divided by the same q.
            const float q = std::min(0.95f, maxComponent(throughput));
            if (!(q > 0.0f) || sampler.next1D() >= q) break;
            power /= q;
            throughput /= q;
        }
        history[std::size_t(++bounces)] = sp.eventOf(sample->lobe);
        allSpecular = allSpecular && lobe.delta();
        ray = spawnRay(sp.hit, sample->wi, ctx.geometry.numerics());
    }
}

void append(MapPart& to, MapPart&& part) {
    const auto offset = static_cast<std::uint32_t>(to.events.size());
    for (Photon& p : part.photons) p.history += offset;
    to.events.insert(to.events.end(), part.events.begin(), part.events.end());
    to.photons.insert(to.photons.end(), part.photons.begin(), part.photons.end());
}

}  // namespace

PhotonMap::PhotonMap(std::vector<Photon> photons, std::vector<PathEvent> events, float radius, std::uint64_t shot)
    : events_(std::move(events)), radius_(radius), cellSize_(2.0f * radius) {
    // Twice as many buckets as photons (a power of two), so few cells share one.
    bucketCount_ = std::bit_ceil(static_cast<std::uint32_t>(std::max<std::uint64_t>({1, 2 * shot, 2 * photons.size()})));
    bucketStart_.assign(std::size_t(bucketCount_) + 1, 0);
    std::vector<std::uint32_t> bucket(photons.size());
    for (std::size_t i = 0; i < photons.size(); ++i) {
        bucket[i] = bucketOf(cellOf(photons[i].position));
        ++bucketStart_[bucket[i] + 1];
    }
    for (std::size_t b = 0; b < bucketCount_; ++b) bucketStart_[b + 1] += bucketStart_[b];
    // A stable counting sort: photons keep their shooting order within a bucket.
    photons_.resize(photons.size());
    std::vector<std::uint32_t> next(bucketStart_.begin(), bucketStart_.end() - 1);
    for (std::size_t i = 0; i < photons.size(); ++i) photons_[next[bucket[i]]++] = photons[i];
}

std::size_t PhotonMap::bytes() const {
    return photons_.capacity() * sizeof(Photon) + events_.capacity() * sizeof(PathEvent) +
           bucketStart_.capacity() * sizeof(std::uint32_t);
}

PhotonSet shootPhotons(const RenderContext& context, std::uint64_t count, std::uint64_t seed, PhotonFilter keep,
                       const void* keepState) {
    const std::size_t chunks = (count + kPhotonsPerChunk - 1) / kPhotonsPerChunk;
    std::vector<ChunkResult> results(chunks);
    parallelChunks(count, kPhotonsPerChunk, threadsOrAll(context.threads), [&](std::size_t begin, std::size_t end) {
        ChunkResult& out = results[begin / kPhotonsPerChunk];
        for (std::size_t i = begin; i < end; ++i) {
            if (context.cancel != nullptr && context.cancel->load(std::memory_order_relaxed)) return;
            tracePhoton(context, i, seed, double(count), keep, keepState, out);
        }
    });
    PhotonSet set;
    MapPart caustic, global;
    for (ChunkResult& r : results) {
        set.counts.shot += r.shot;
        append(caustic, std::move(r.caustic));
        append(global, std::move(r.global));
    }
    set.counts.caustic = caustic.photons.size();
    set.counts.global = global.photons.size();
    set.caustic = std::move(caustic.photons);
    set.causticEvents = std::move(caustic.events);
    set.global = std::move(global.photons);
    set.globalEvents = std::move(global.events);
    return set;
}

}  // namespace lightpath
