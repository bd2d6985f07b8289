#include "integrators/local_illumination.h"

#include <cmath>

#include "geometry/spawn_ray.h"

namespace lightpath {
namespace {

// (H.N)^n with H the halfway vector of l and v (Blinn's form of Phong's highlight).
float highlightFactor(const Vec3& normal, const Vec3& l, const Vec3& v, float exponent) {
    const Vec3 halfway = l + v;
    const float length = glm::length(halfway);
    if (length == 0.0f) return 0.0f;
    return std::pow(glm::max(0.0f, glm::dot(normal, halfway) / length), exponent);
}

// One light as the illumination formula sees it at the shaded point: where it is, the
// intensity arriving there (attenuation applied), and the events that name it.
struct LightAtPoint {
    Vec3 position;
    Rgb intensity;
    PathEvent event;
    lpe::Automaton::Symbol symbol;
};

// The diffuse and highlight terms of one light, with its shadow ray. Shared by point lights and
// the sampled points of area lights.
void shadeFromLight(const SurfaceHit& hit, const Vec3& normal, const Vec3& towardViewer, lpe::Automaton::State state,
                    const Rgb& throughput, const LightAtPoint& light, Tracer& tracer) {
    const RenderContext& ctx = tracer.context;
    const lpe::Automaton& automaton = ctx.automaton;
    const std::uint32_t materialIndex = ctx.scene.objects[hit.object].material;
    const PhongMaterial& material = ctx.scene.materials[materialIndex];
    const MaterialTerms& terms = ctx.analysis.materials[materialIndex];
    const SurfaceSymbols& symbols = ctx.symbols.objects[hit.object];
    const bool skip = ctx.skipEnabled;
    RayCounters& counters = tracer.counters;

    const Vec3 toLight = light.position - hit.point;
    // The lecture's own-primitive test: p is in the shadow of its own surface iff N.(b - p) < 0.
    const bool litSide = glm::dot(normal, toLight) > 0.0f;
    if (!litSide && skip) {
        ++counters.shadowBehind;
        return;
    }
    const bool diffuseWanted = tracer.wants(automaton.accepts(automaton.step(automaton.step(state, symbols.diffuse), light.symbol)));
    const bool highlightWanted = tracer.wants(automaton.accepts(automaton.step(automaton.step(state, symbols.glossy), light.symbol)));
    if (!diffuseWanted && !highlightWanted) {
        ++counters.shadowDead;
        return;
    }

    const Vec3 l = glm::normalize(toLight);
    const Rgb intensity = litSide ? light.intensity : Rgb{0.0f};
    Rgb diffuse{0.0f}, highlight{0.0f};
    // N.L clamped: for a light at a grazing angle, N.(b - p) > 0 may round to a negative N.L once
    // b - p is normalised, and the lecture's kd (N.L) is never negative light.
    if (diffuseWanted && (terms.diffuse || !skip)) diffuse = material.kd * intensity * glm::max(0.0f, glm::dot(normal, l));
    if (highlightWanted && (terms.highlight || !skip)) {
        ++counters.highlightEvaluated;
        highlight = material.ks * intensity * highlightFactor(normal, l, towardViewer, material.n);
    } else if (!terms.highlight) {
        ++counters.highlightNoKs;
    }
    if (skip && isBlack(diffuse) && isBlack(highlight)) {
        ++counters.shadowZero;
        return;
    }

    ++counters.shadow;
    if (ctx.geometry.occluded(spawnShadowRay(hit, light.position, ctx.geometry.numerics()))) return;

    const PathEvent diffuseEvent{lpe::EventType::Reflection, lpe::Scatter::Diffuse, Subject::Object, hit.object};
    const PathEvent glossyEvent{lpe::EventType::Reflection, lpe::Scatter::Glossy, Subject::Object, hit.object};
    if (diffuseWanted && !(skip && isBlack(diffuse)))
        tracer.emit(state, diffuseEvent, symbols.diffuse, light.event, light.symbol, throughput * diffuse);
    if (highlightWanted && !(skip && isBlack(highlight)))
        tracer.emit(state, glossyEvent, symbols.glossy, light.event, light.symbol, throughput * highlight);
}

}  // namespace

void addLocalIllumination(const SurfaceHit& hit, const Vec3& normal, const Vec3& towardViewer,
                          lpe::Automaton::State state, const Rgb& throughput, Tracer& tracer) {
    const RenderContext& ctx = tracer.context;
    const Scene& scene = ctx.scene;
    const lpe::Automaton& automaton = ctx.automaton;
    const std::uint32_t materialIndex = scene.objects[hit.object].material;
    const SurfaceSymbols& symbols = ctx.symbols.objects[hit.object];

    if ((ctx.analysis.materials[materialIndex].ambient || !ctx.skipEnabled) &&
        tracer.wants(automaton.accepts(automaton.step(automaton.step(state, symbols.diffuse), ctx.symbols.ambient)))) {
        tracer.emit(state, {lpe::EventType::Reflection, lpe::Scatter::Diffuse, Subject::Object, hit.object},
                    symbols.diffuse, {lpe::EventType::Emitter, lpe::Scatter::None, Subject::Ambient},
                    ctx.symbols.ambient, throughput * scene.materials[materialIndex].ka * scene.ambient);
    }

    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        const PointLight& light = scene.lights[i];
        const float distance = glm::length(light.position - hit.point);
        shadeFromLight(hit, normal, towardViewer, state, throughput,
                       {light.position, light.intensity * light.attenuationAt(distance),
                        {lpe::EventType::Emitter, lpe::Scatter::None, Subject::PointLight, static_cast<std::uint32_t>(i)},
                        ctx.symbols.lights[i]},
                       tracer);
    }

    // Area lights: one sampled point per pixel sample, acting as a point light whose radiant
    // intensity towards p is Le cos(theta_light) / pdf_area, with inverse-square falloff. Over
    // many samples per pixel this gives soft shadows.
    if (ctx.emitters.empty() || tracer.sampler == nullptr) return;
    Sampler vertex = tracer.sampler->forVertex(tracer.path.key());
    const float uPick = vertex.next1D();
    const Vec2 u = vertex.next2D();
    const EmitterSample sample = ctx.emitters.sample(hit.point, uPick, u);
    const Vec3 toLight = sample.point - hit.point;
    const float distance2 = glm::dot(toLight, toLight);
    const float cosLight = std::fabs(glm::dot(sample.normal, toLight)) / std::sqrt(distance2);
    shadeFromLight(hit, normal, towardViewer, state, throughput,
                   {sample.point, sample.radiance * (cosLight / (sample.pdfArea * distance2)),
                    {lpe::EventType::Emitter, lpe::Scatter::None, Subject::Object, sample.object},
                    ctx.symbols.objects[sample.object].emission},
                   tracer);
}

}  // namespace lightpath
