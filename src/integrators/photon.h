#pragma once
// Photon mapping (Jensen 1996; Jensen 2001, "Realistic Image Synthesis Using Photon Mapping").
// Pass one shoots photons from the lights (photon_map.h) into a caustic map (photons after L S+)
// and a global map (after any other path of at least one bounce). Pass two, per camera sample,
// follows the eye through specular bounces to the first diffuse or glossy vertex; there direct
// light is next-event estimation, as the path tracer does it, and the rest is the photons' density
// within a radius, both maps seen directly (no final gather). A photon's contribution is the
// eye's events, the merge vertex and the photon's events reversed to its light, classified by the
// automaton like any other, so E S+ (D|G) S+ L, a caustic seen in a mirror, which no eye walk or
// light walk joined by a shadow ray can make under a point light, is found.
#include <cstdint>
#include <optional>

#include "geometry/spawn_ray.h"
#include "integrators/direct_light.h"
#include "integrators/integrator.h"
#include "integrators/photon_map.h"
#include "integrators/shading_point.h"
#include "lpe/suffix_reader.h"

namespace lightpath {

struct PhotonStats {
    std::uint64_t shot = 0, causticStored = 0, globalStored = 0;
    std::size_t bytes = 0;
    float radius = 0.0f, causticRadius = 0.0f;
    // Progressive photon mapping's passes, each a map of `shot / passes` photons, and the pixels'
    // mean radius after the last (sppm.h; `radius` is the first); 1 for Jensen's.
    int passes = 1;
    float lastRadius = 0.0f;
    double seconds = 0.0;
};

// The eye's side of photon mapping: follows `ray` through specular bounces, adding emission and
// background as it goes; at the first vertex with a smooth lobe adds direct light by next-event
// estimation, then calls gather(point, throughput, bounces) for the photons' share, and continues
// only through a delta lobe (the smooth ones were gathered).
template <class Gather>
void traceEyeToPhotons(const Ray& cameraRay, PathState& path, const Gather& gather) {
    const RenderContext& ctx = path.context;
    Sampler& sampler = *path.sampler;
    const std::size_t pathStart = path.size();
    Ray ray = cameraRay;
    Rgb throughput{1.0f};
    for (int bounces = 0;; ++bounces) {
        const auto hit = ctx.geometry.intersect(ray);
        if (!hit) {
            addBackground(ray, throughput, path);
            break;
        }
        // Only E S* L reaches an emitter from the eye here: nothing else finds it, weight 1.
        addEmission(*hit, ray, throughput, 1.0f, path);
        if (bounces >= ctx.maxDepth) break;
        const ShadingPoint point = makeShadingPoint(*hit, ray, ctx);
        if (point.bsdf.hasSmoothLobe()) {
            addDirectLight(point, throughput, drawLightChoice(sampler, path.context.lights), DirectLightWeighting::Alone,
                           path);
            gather(point, throughput, bounces);
        }
        // The lobe is chosen by albedo as the path tracer does; a smooth one ends the walk, since
        // its light was gathered above, so a delta lobe's weight (1/its choice) keeps the sum exact.
        const float uLobe = sampler.next1D();
        const Vec2 u = sampler.next2D();
        const auto sample = point.bsdf.sample(point.wo, uLobe, u);
        if (!sample || !point.bsdf.lobe(sample->lobe).delta()) break;
        const bool transmitted = point.bsdf.lobe(sample->lobe).transmits();
        if (!path.push(point.eventOf(sample->lobe))) {
            ++(transmitted ? path.counters.refractionDead : path.counters.reflectionDead);
            break;
        }
        throughput *= sample->weight;
        ++(transmitted ? path.counters.refraction : path.counters.reflection);
        ray = spawnRay(point.hit, sample->wi, ctx.geometry.numerics());
    }
    while (path.size() > pathStart) path.pop();
}

// The photons of `map` around `point`, reached with `throughput` after `eyeBounces` scattering
// events, one contribution per photon and smooth lobe: throughput f(wo, wi_p) Phi_p / (pi r^2)
// (Jensen 2001, eq. 7.6, with the constant kernel), classified with the photon's own events.
// `explain` names the progressive pass when `pass` >= 0.
void addPhotonDensity(const ShadingPoint& point, const Rgb& throughput, int eyeBounces, const PhotonMap& map,
                      float radius, PathState& path, int pass = -1);

// The photons of `map` that addPhotonDensity may merge at `point` by their place alone (within
// `radius`, on a surface facing as the point's), whatever the outputs and the path's length:
// progressive photon mapping's count M.
std::uint64_t countPhotonsWithin(const ShadingPoint& point, const PhotonMap& map, float radius);

// Photon paths shot when no --photons is given (the schema's default says the same), and the most
// one render may shoot: about 100 bytes each are kept.
inline constexpr std::uint64_t kDefaultPhotons = 200000;
inline constexpr std::uint64_t kMaxPhotons = 10000000;

// The default search radius: this share of the diagonal of the scene's bounded shapes.
inline constexpr float kDefaultRadiusShare = 0.01f;
float defaultPhotonRadius(const Scene& scene);

// The reader of the requested outputs backwards from the light, when photons may be filtered by it
// (not when every path is wanted), and the photons of `count` paths kept by it: the one photon
// filter of photon mapping and of its progressive form (sppm.h).
std::optional<lpe::SuffixReader> requestedPhotonReader(const RenderContext& context);
PhotonSet shootRequestedPhotons(const RenderContext& context, const lpe::SuffixReader* reader, std::uint64_t count,
                                std::uint64_t seed);

class PhotonIntegrator final : public Integrator {
public:
    void preprocess(const RenderContext& context) override;
    void traceCameraRay(const Ray& ray, PathState& path) const override;
    const PhotonStats& stats() const { return stats_; }

private:
    PhotonMap caustic_, global_;
    PhotonStats stats_;
};

}  // namespace lightpath
