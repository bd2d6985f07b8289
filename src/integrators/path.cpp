#include "integrators/path.h"

#include "integrators/registry.h"
#include <algorithm>
#include <limits>

#include "geometry/spawn_ray.h"
#include "integrators/direct_light.h"
#include "sampling/russian_roulette.h"
#include "util/hot_path.h"

namespace lightpath {

LIGHTPATH_HOT_PATH
void PathIntegrator::traceCameraRay(const Ray& cameraRay, PathState& path) const {
    const RenderContext& ctx = path.context;
    Sampler& sampler = *path.sampler;
    Ray ray = cameraRay;
    Rgb throughput{1.0f};
    float previousPdf = 0.0f;   // solid-angle density of the direction that led here
    bool previousDelta = true;  // the camera, like a delta lobe, cannot be light-sampled
    const std::size_t pathStart = path.size();
    // The medium the ray travels in: the camera's (media do not nest).
    std::uint32_t mediumIndex = ctx.eyeMedium;
    // The last scattering vertex (or the eye): an interface crossing moves the ray's origin, but
    // MIS weighs an emitter found by the sampled direction from the vertex that sampled it.
    Vec3 lastVertex = ray.origin;
    int crossings = 0;
    int depth = 0;  // scattering vertices so far: an interface crossing is none

    while (true) {
        const auto hit = ctx.geometry.intersect(ray);
        // Free flight through the medium up to the surface (pbrt-v4 14.2, VolPathIntegrator): a
        // scattering there is a V vertex, else the throughput carries the segment's transmittance.
        if (const Medium* medium = ctx.scene.medium(mediumIndex)) {
            const float tMax = hit ? hit->t : std::numeric_limits<float>::infinity();
            float uChannel = 0.0f;  // unread by a medium that chooses no channel: not computed
            if (medium->choosesChannel()) uChannel = sampler.next1D();
            else sampler.skip1D();
            const float uDistance = sampler.next1D();
            const MediumSample flight = medium->sampleDistance(ray, tMax, uChannel, uDistance);
            ++path.counters.mediumSegments;
            throughput *= flight.weight;
            if (isBlack(throughput)) break;
            if (flight.scattered) {
                if (depth >= ctx.maxDepth) break;
                const MediumPoint point{ray.at(flight.t), -ray.direction, *medium, mediumIndex};
                addMediumDirectLight(point, throughput, drawLightChoice(sampler, ctx.lights),
                                     DirectLightWeighting::MultipleImportance, path);
                const PhaseSample scattered = medium->phase(point.point).sample(point.wo, sampler.next2D());
                if (!path.push(point.event())) {
                    ++path.counters.volumeDead;
                    break;
                }
                // The phase function is sampled exactly: its weight p / pdf is 1.
                if (!survivesRussianRoulette(throughput, depth + 1, sampler)) break;
                ++path.counters.volume;
                previousPdf = scattered.pdf;
                previousDelta = false;
                ray = Ray{point.point, scattered.wi};
                lastVertex = ray.origin;
                ++depth;
                continue;
            }
        }
        // An index-matched boundary: the ray goes on into the medium beyond, with no event and no
        // bounce (OSL: crossing a boundary is not a T).
        if (hit && ctx.scene.crossedWithoutEvent(hit->object)) {
            if (++crossings > kMaxInterfaceCrossings) break;
            const bool entering = glm::dot(hit->normal, ray.direction) < 0.0f;
            mediumIndex = ctx.scene.mediumBeyond(hit->object, entering, mediumIndex);
            ray = spawnRay(*hit, ray.direction, ctx.geometry.numerics());
            continue;
        }
        if (!hit) {
            addBackground(ray, throughput, path);
            break;
        }
        // An emitter found by the sampled direction: MIS-weighted against light sampling.
        const float emissionWeight =
            previousDelta ? 1.0f : powerHeuristic(previousPdf, ctx.lights.pdf(lastVertex, *hit));
        addEmission(*hit, ray, throughput, emissionWeight, path);
        if (depth >= ctx.maxDepth) break;

        const ShadingPoint point = makeShadingPoint(*hit, ray, ctx);
        // One set of offset origins for the shadow rays and the bounce (a diffuse bounce leaves on
        // the lit side, from the origin the shadow rays computed).
        RayOrigins origins(point.hit, ctx.geometry.numerics());
        if (point.bsdf.hasSmoothLobe()) {
            addDirectLight(point, origins, throughput, drawLightChoice(sampler, ctx.lights),
                           DirectLightWeighting::MultipleImportance, path, ctx.scene.medium(mediumIndex));
        }

        const float uLobe = sampler.next1D();
        const Vec2 u = sampler.next2D();
        const auto sample = point.bsdf.sample(point.wo, uLobe, u);
        if (!sample) break;
        const LobeInfo& lobe = point.bsdf.lobe(sample->lobe);
        const bool transmitted = lobe.transmits();
        if (!path.push(point.eventOf(sample->lobe))) {
            ++(transmitted ? path.counters.refractionDead : path.counters.reflectionDead);
            break;
        }
        throughput *= sample->weight;
        if (!survivesRussianRoulette(throughput, depth + 1, sampler)) break;
        ++(transmitted ? path.counters.refraction : path.counters.reflection);
        if (transmitted) mediumIndex = ctx.scene.mediumBeyond(point.hit.object, point.entering, mediumIndex);
        previousPdf = sample->pdf;
        previousDelta = lobe.delta();
        ray = spawnRay(origins, sample->wi);
        lastVertex = ray.origin;
        ++depth;
    }
    while (path.size() > pathStart) path.pop();
}

}  // namespace lightpath

// It samples every lobe at every bounce.
LIGHTPATH_REGISTER_INTEGRATOR(lightpath::rendersMedia(lightpath::integratorRow(
    "path", "path tracing with global illumination (physically based reading)",
    "E.*[<L.[^'ambient']>OB]",
    "path tracing follows every bounce but adds no ambient term (ka Ia, which stands in for the indirect light it gathers)",
    [] { return std::unique_ptr<lightpath::Integrator>(std::make_unique<lightpath::PathIntegrator>()); },
    lightpath::ShadowRays::Always, 3)))
