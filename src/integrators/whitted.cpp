#include "integrators/whitted.h"

#include <optional>

#include "integrators/registry.h"
#include "geometry/spawn_ray.h"
#include "integrators/direct_light.h"
#include "util/hot_path.h"

namespace lightpath {

LIGHTPATH_HOT_PATH
void WhittedIntegrator::traceCameraRay(const Ray& ray, PathState& path) const {
    trace(ray, Rgb{1.0f}, 0, path.context.eyeMedium, path);
}

LIGHTPATH_HOT_PATH
void WhittedIntegrator::trace(const Ray& firstRay, const Rgb& firstThroughput, int depth, std::uint32_t firstMedium,
                              PathState& path) const {
    const RenderContext& ctx = path.context;
    // Across index-matched boundaries without an event, into the media beyond. A scene without
    // such boundaries crosses none: its hit is not copied through crossInterfaces (about 50
    // instructions a ray).
    const std::optional<SurfaceHit> first = ctx.geometry.intersect(firstRay);
    std::optional<BeyondInterfaces> beyond;
    if (ctx.scene.interfaces) beyond = crossInterfaces(first, firstRay, firstMedium, firstThroughput, path);
    const std::optional<SurfaceHit>& hit = beyond ? beyond->hit : first;
    const Ray& ray = beyond ? beyond->ray : firstRay;
    const std::uint32_t mediumIndex = beyond ? beyond->medium : firstMedium;
    // Single scattering along this ray (E S* V L), and its transmittance on all beyond.
    const Rgb seen = throughMedium(hit, ray, mediumIndex, beyond ? beyond->throughput : firstThroughput, path);
    if (isBlack(seen) && ctx.skipEnabled) return;
    if (!hit) {
        addBackground(ray, seen, path);
        return;
    }
    addEmission(*hit, ray, seen, 1.0f, path);
    if (depth >= ctx.maxDepth) return;
    const ShadingPoint point = makeShadingPoint(*hit, ray, ctx);
    addLocalIllumination(point, seen, path, ctx.scene.medium(mediumIndex));

    // Every delta lobe's branch, while some requested output can still accept the path (the
    // automaton's dead states); the BSDF returns only branches with weight.
    std::array<SpecularBranch, 2> branches;
    const int count = point.bsdf.specularBranches(point.wo, branches);
    for (int b = 0; b < count; ++b) {
        const bool reflection = !point.bsdf.lobe(branches[b].lobe).transmits();
        if (!path.push(point.eventOf(branches[b].lobe))) {
            ++(reflection ? path.counters.reflectionDead : path.counters.refractionDead);
            continue;
        }
        ++(reflection ? path.counters.reflection : path.counters.refraction);
        const std::uint32_t next =
            reflection ? mediumIndex : ctx.scene.mediumBeyond(point.hit.object, point.entering, mediumIndex);
        trace(spawnRay(point.hit, branches[b].wi, ctx.geometry.numerics()), seen * branches[b].weight,
              depth + 1, next, path);
        path.pop();
    }
}

}  // namespace lightpath

// Mirror and refraction rays (S*) before ray casting's shading.
LIGHTPATH_REGISTER_INTEGRATOR(lightpath::rendersMedia(lightpath::integratorRow(
    "whitted", "adds mirror and refraction rays (Whitted ray tracing)", "ES*(D|G)L|ES*L|ES*<Vx>L",
    "Whitted ray tracing follows specular bounces only: no diffuse or glossy interreflection",
    [] { return std::unique_ptr<lightpath::Integrator>(std::make_unique<lightpath::WhittedIntegrator>()); },
    lightpath::ShadowRays::Optional, 2)))
