#include "integrators/path.h"

#include <algorithm>

#include "geometry/spawn_ray.h"
#include "integrators/raycast.h"
#include "materials/phong_bsdf.h"

namespace lightpath {
namespace {

// Paths shorter than this are never cut by Russian roulette.
constexpr int kRouletteDepth = 3;

float powerHeuristic(float pdf, float otherPdf) {
    // Squared in double: a pdf above 1.8e19 (a small light seen edge-on) squares to infinity in
    // float, and inf / inf is NaN.
    const double a = double(pdf) * pdf, b = double(otherPdf) * otherPdf;
    return a + b > 0.0 ? static_cast<float>(a / (a + b)) : 0.0f;
}

lpe::Scatter scatterOf(Lobe lobe) {
    switch (lobe) {
        case Lobe::Diffuse: return lpe::Scatter::Diffuse;
        case Lobe::Glossy: return lpe::Scatter::Glossy;
        default: return lpe::Scatter::Specular;
    }
}

// The surface events of a vertex for the two smooth lobes, in Lobe order.
struct SmoothLobe {
    Lobe lobe;
    lpe::Scatter scatter;
};
constexpr SmoothLobe kSmoothLobes[] = {{Lobe::Diffuse, lpe::Scatter::Diffuse}, {Lobe::Glossy, lpe::Scatter::Glossy}};

// The state of one camera path between bounces.
struct PathVertex {
    const SurfaceHit& hit;
    Vec3 normal;        // shading normal on the side of wo
    Vec3 wo;            // towards the previous vertex
    const PhongBsdf& bsdf;
    lpe::Automaton::State state;
    Rgb throughput;
};

lpe::Automaton::Symbol surfaceSymbol(const SurfaceSymbols& symbols, Lobe lobe) {
    return lobe == Lobe::Diffuse ? symbols.diffuse : symbols.glossy;
}

// One light sample seen from a vertex: the radiance arriving along wi divided by the sample's
// density (for a point light, I / d^2), and the solid-angle density used for MIS (0 for a delta
// light, which BSDF sampling can never hit).
struct LightSample {
    Vec3 position;
    Vec3 wi;
    Rgb incident;
    float lightPdf;
    PathEvent event;
    lpe::Automaton::Symbol symbol;
};

// Next-event estimation of one light sample through both smooth lobes, with one shadow ray.
void addLightSample(const PathVertex& v, const LightSample& light, Tracer& tracer) {
    const RenderContext& ctx = tracer.context;
    const float cosTheta = glm::dot(v.normal, light.wi);
    if (cosTheta <= 0.0f || isBlack(light.incident)) {
        ++tracer.counters.shadowBehind;
        return;
    }
    const SurfaceSymbols& symbols = ctx.symbols.objects[v.hit.object];
    Rgb contribution[2];
    bool any = false;
    for (int l = 0; l < 2; ++l) {
        const Lobe lobe = kSmoothLobes[l].lobe;
        const auto accepted = ctx.automaton.accepts(
            ctx.automaton.step(ctx.automaton.step(v.state, surfaceSymbol(symbols, lobe)), light.symbol));
        if (!tracer.wants(accepted)) continue;
        const float weight = light.lightPdf > 0.0f ? powerHeuristic(light.lightPdf, v.bsdf.pdf(lobe, v.wo, light.wi)) : 1.0f;
        contribution[l] = v.throughput * v.bsdf.evaluate(lobe, v.wo, light.wi) * light.incident * (cosTheta * weight);
        any |= !isBlack(contribution[l]);
    }
    if (!any) {
        ++tracer.counters.shadowZero;
        return;
    }
    ++tracer.counters.shadow;
    if (ctx.geometry.occluded(spawnShadowRay(v.hit, light.position, ctx.geometry.numerics()))) return;
    for (int l = 0; l < 2; ++l) {
        if (isBlack(contribution[l])) continue;
        tracer.emit(v.state, {lpe::EventType::Reflection, kSmoothLobes[l].scatter, Subject::Object, v.hit.object},
                    surfaceSymbol(symbols, kSmoothLobes[l].lobe), light.event, light.symbol, contribution[l]);
    }
}

// Every point light (inverse-square law), then one point on an area light chosen by power.
void sampleLights(const PathVertex& v, Tracer& tracer) {
    const RenderContext& ctx = tracer.context;
    for (std::size_t i = 0; i < ctx.scene.lights.size(); ++i) {
        const PointLight& light = ctx.scene.lights[i];
        const Vec3 toLight = light.position - v.hit.point;
        const float distance2 = glm::dot(toLight, toLight);
        addLightSample(v,
                       {light.position, toLight / std::sqrt(distance2), light.intensity / distance2, 0.0f,
                        {lpe::EventType::Emitter, lpe::Scatter::None, Subject::PointLight, static_cast<std::uint32_t>(i)},
                        ctx.symbols.lights[i]},
                       tracer);
    }
    const float uPick = tracer.sampler->next1D();
    const Vec2 u = tracer.sampler->next2D();
    if (ctx.emitters.empty()) return;
    const EmitterSample sample = ctx.emitters.sample(v.hit.point, uPick, u);
    const float lightPdf = areaToSolidAngle(sample.pdfArea, v.hit.point, sample.point, sample.normal);
    if (!(lightPdf > 0.0f)) return;
    addLightSample(v,
                   {sample.point, glm::normalize(sample.point - v.hit.point), sample.radiance / lightPdf, lightPdf,
                    {lpe::EventType::Emitter, lpe::Scatter::None, Subject::Object, sample.object},
                    ctx.symbols.objects[sample.object].emission},
                   tracer);
}

}  // namespace

void PathIntegrator::traceCameraRay(const Ray& cameraRay, lpe::Automaton::State state, Tracer& tracer) const {
    const RenderContext& ctx = tracer.context;
    Ray ray = cameraRay;
    Rgb throughput{1.0f};
    float previousPdf = 0.0f;       // solid-angle density of the direction that led here
    bool previousSpecular = true;   // the camera, like a specular bounce, cannot be light-sampled
    const std::size_t pathStart = tracer.path.size();

    for (int depth = 0;; ++depth) {
        const auto hit = ctx.geometry.intersect(ray);
        if (!hit) {
            addBackground(state, throughput, tracer);
            break;
        }
        const bool entering = glm::dot(hit->normal, ray.direction) < 0.0f;
        const Vec3 normal = entering ? hit->shadingNormal : -hit->shadingNormal;
        const Vec3 wo = -ray.direction;

        // An emitter found by the sampled direction: MIS-weighted against light sampling.
        const Rgb emitted = ctx.emitters.radiance(*hit, wo);
        if (!isBlack(emitted)) {
            float weight = 1.0f;
            if (!previousSpecular) {
                const float lightPdf = areaToSolidAngle(ctx.emitters.pdfArea(hit->primitive), ray.origin, hit->point, hit->normal);
                weight = powerHeuristic(previousPdf, lightPdf);
            }
            tracer.emit(state, {lpe::EventType::Emitter, lpe::Scatter::None, Subject::Object, hit->object},
                        ctx.symbols.objects[hit->object].emission, throughput * emitted * weight);
        }
        if (depth >= ctx.maxDepth) break;

        const PhongMaterial& material = ctx.scene.materials[ctx.scene.objects[hit->object].material];
        const PhongBsdf bsdf(material, normal, entering);
        const PathVertex vertex{*hit, normal, wo, bsdf, state, throughput};
        if (bsdf.hasSmoothLobe()) sampleLights(vertex, tracer);

        const float uLobe = tracer.sampler->next1D();
        const Vec2 u = tracer.sampler->next2D();
        const auto sample = bsdf.sample(wo, uLobe, u);
        if (!sample) break;
        const lpe::EventType type = sample->transmitted ? lpe::EventType::Transmission : lpe::EventType::Reflection;
        const SurfaceSymbols& symbols = ctx.symbols.objects[hit->object];
        const lpe::Automaton::Symbol symbol =
            sample->transmitted ? symbols.refraction
                                : (sample->lobe == Lobe::Diffuse ? symbols.diffuse
                                                                 : (sample->lobe == Lobe::Glossy ? symbols.glossy : symbols.mirror));
        const auto next = ctx.automaton.step(state, symbol);
        if (!tracer.alive(next)) {
            ++(sample->transmitted ? tracer.counters.refractionDead : tracer.counters.reflectionDead);
            break;
        }

        throughput *= sample->weight;
        if (depth + 1 >= kRouletteDepth) {
            // Russian roulette: continue with probability q, dividing by q keeps the estimate unbiased.
            const float q = std::min(0.95f, maxComponent(throughput));
            if (tracer.sampler->next1D() >= q) break;
            throughput /= q;
        }
        ++(sample->transmitted ? tracer.counters.refraction : tracer.counters.reflection);
        tracer.path.push({type, scatterOf(sample->lobe), Subject::Object, hit->object});
        state = next;
        previousPdf = sample->pdf;
        previousSpecular = sample->lobe == Lobe::Mirror || sample->lobe == Lobe::Dielectric;
        ray = spawnRay(*hit, sample->direction, ctx.geometry.numerics());
    }
    while (tracer.path.size() > pathStart) tracer.path.pop();
}

}  // namespace lightpath
