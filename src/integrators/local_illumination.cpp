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

}  // namespace

void addLocalIllumination(const SurfaceHit& hit, const Vec3& normal, const Vec3& towardViewer,
                          lpe::Automaton::State state, const Rgb& throughput, Tracer& tracer) {
    const RenderContext& ctx = tracer.context;
    const Scene& scene = ctx.scene;
    const lpe::Automaton& automaton = ctx.automaton;
    const std::uint32_t materialIndex = scene.objects[hit.object].material;
    const PhongMaterial& material = scene.materials[materialIndex];
    const MaterialTerms& terms = ctx.analysis.materials[materialIndex];
    const bool skip = ctx.skipEnabled;
    RayCounters& counters = tracer.counters;

    const SurfaceSymbols& symbols = ctx.symbols.objects[hit.object];
    const auto afterDiffuse = automaton.step(state, symbols.diffuse);
    const auto afterGlossy = automaton.step(state, symbols.glossy);
    const auto subject = static_cast<std::int32_t>(hit.object);
    const PathEvent diffuseEvent{lpe::EventType::Reflection, lpe::Scatter::Diffuse, subject};
    const PathEvent glossyEvent{lpe::EventType::Reflection, lpe::Scatter::Glossy, subject};

    if ((terms.ambient || !skip) &&
        tracer.wants(automaton.accepts(automaton.step(afterDiffuse, ctx.symbols.ambient)))) {
        tracer.emit(state, diffuseEvent, symbols.diffuse,
                    {lpe::EventType::Emitter, lpe::Scatter::None, kSubjectAmbient}, ctx.symbols.ambient,
                    throughput * material.ka * scene.ambient);
    }

    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        const PointLight& light = scene.lights[i];
        const Vec3 toLight = light.position - hit.point;
        // The lecture's own-primitive test: p is in the shadow of its own surface iff N.(b - p) < 0.
        const bool litSide = glm::dot(normal, toLight) > 0.0f;
        if (!litSide && skip) {
            ++counters.shadowBehind;
            continue;
        }
        const lpe::Automaton::Symbol lightSymbol = ctx.symbols.lights[i];
        const bool diffuseWanted = tracer.wants(automaton.accepts(automaton.step(afterDiffuse, lightSymbol)));
        const bool highlightWanted = tracer.wants(automaton.accepts(automaton.step(afterGlossy, lightSymbol)));
        if (!diffuseWanted && !highlightWanted) {
            ++counters.shadowDead;
            continue;
        }

        const float distance = glm::length(toLight);
        const Vec3 l = toLight / distance;
        const Rgb intensity = litSide ? light.intensity * light.attenuationAt(distance) : Rgb{0.0f};
        Rgb diffuse{0.0f}, highlight{0.0f};
        if (diffuseWanted && (terms.diffuse || !skip)) diffuse = material.kd * intensity * glm::dot(normal, l);
        if (highlightWanted && (terms.highlight || !skip)) {
            ++counters.highlightEvaluated;
            highlight = material.ks * intensity * highlightFactor(normal, l, towardViewer, material.n);
        } else if (!terms.highlight) {
            ++counters.highlightNoKs;
        }
        if (skip && isBlack(diffuse) && isBlack(highlight)) {
            ++counters.shadowZero;
            continue;
        }

        ++counters.shadow;
        if (ctx.geometry.occluded(spawnShadowRay(hit, light.position, ctx.geometry.numerics()))) continue;

        const PathEvent lightEvent{lpe::EventType::Emitter, lpe::Scatter::None, static_cast<std::int32_t>(i)};
        if (diffuseWanted && !(skip && isBlack(diffuse)))
            tracer.emit(state, diffuseEvent, symbols.diffuse, lightEvent, lightSymbol, throughput * diffuse);
        if (highlightWanted && !(skip && isBlack(highlight)))
            tracer.emit(state, glossyEvent, symbols.glossy, lightEvent, lightSymbol, throughput * highlight);
    }
}

}  // namespace lightpath
