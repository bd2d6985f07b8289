#include "integrators/whitted.h"

#include <cmath>

#include "geometry/spawn_ray.h"
#include "integrators/local_illumination.h"
#include "integrators/raycast.h"

namespace lightpath {
namespace {

// Snell's law for unit vectors; false on total internal reflection. `normal` faces the incoming
// ray and eta = n_incident / n_transmitted.
bool refractDirection(const Vec3& incident, const Vec3& normal, float eta, Vec3& transmitted) {
    const float cosIncident = -glm::dot(incident, normal);
    const float sin2Transmitted = eta * eta * (1.0f - cosIncident * cosIncident);
    if (sin2Transmitted >= 1.0f) return false;
    const float cosTransmitted = std::sqrt(1.0f - sin2Transmitted);
    transmitted = glm::normalize(eta * incident + (eta * cosIncident - cosTransmitted) * normal);
    return true;
}

}  // namespace

void WhittedIntegrator::traceCameraRay(const Ray& ray, lpe::Automaton::State state, Tracer& tracer) const {
    trace(ray, state, Rgb{1.0f}, 0, tracer);
}

void WhittedIntegrator::trace(const Ray& ray, lpe::Automaton::State state, const Rgb& throughput,
                              int depth, Tracer& tracer) const {
    const RenderContext& ctx = tracer.context;
    const auto hit = ctx.geometry.intersect(ray);
    if (!hit) {
        addBackground(state, throughput, tracer);
        return;
    }
    const bool entering = glm::dot(hit->normal, ray.direction) < 0.0f;
    const Vec3 normal = entering ? hit->shadingNormal : -hit->shadingNormal;
    addSurfaceEmission(*hit, -ray.direction, state, throughput, tracer);
    addLocalIllumination(*hit, normal, -ray.direction, state, throughput, tracer);
    if (depth >= ctx.maxDepth) return;

    const std::uint32_t materialIndex = ctx.scene.objects[hit->object].material;
    const PhongMaterial& material = ctx.scene.materials[materialIndex];
    const MaterialTerms& terms = ctx.analysis.materials[materialIndex];
    const SurfaceSymbols& symbols = ctx.symbols.objects[hit->object];
    const std::uint32_t subject = hit->object;
    const PathEvent mirrorEvent{lpe::EventType::Reflection, lpe::Scatter::Specular, Subject::Object, subject};
    const Vec3 mirrorDirection = glm::reflect(ray.direction, normal);
    const NumericsOptions& numerics = ctx.geometry.numerics();

    // Secondary rays only from surfaces that have the term (scene analysis), and only while some
    // requested output can still accept the path (the automaton's dead states).
    if (terms.mirror || !ctx.skipEnabled) {
        traceSpecular(spawnRay(*hit, mirrorDirection, numerics), mirrorEvent, symbols.mirror, state,
                      throughput * material.kr, depth, tracer);
    }
    if (terms.refraction || !ctx.skipEnabled) {
        // Entering the surface goes from vacuum (1) into the material (ior), leaving goes back.
        const float eta = entering ? 1.0f / material.ior : material.ior;
        Vec3 transmitted;
        if (refractDirection(ray.direction, normal, eta, transmitted)) {
            traceSpecular(spawnRay(*hit, transmitted, numerics),
                          {lpe::EventType::Transmission, lpe::Scatter::Specular, Subject::Object, subject},
                          symbols.refraction, state, throughput * material.kt, depth, tracer);
        } else {
            // Total internal reflection: the transmitted share is reflected instead.
            traceSpecular(spawnRay(*hit, mirrorDirection, numerics), mirrorEvent, symbols.mirror,
                          state, throughput * material.kt, depth, tracer);
        }
    }
}

void WhittedIntegrator::traceSpecular(const Ray& ray, const PathEvent& event, lpe::Automaton::Symbol symbol,
                                      lpe::Automaton::State state, const Rgb& throughput, int depth,
                                      Tracer& tracer) const {
    const bool reflection = event.type == lpe::EventType::Reflection;
    const auto next = tracer.context.automaton.step(state, symbol);
    if (!tracer.alive(next)) {
        ++(reflection ? tracer.counters.reflectionDead : tracer.counters.refractionDead);
        return;
    }
    ++(reflection ? tracer.counters.reflection : tracer.counters.refraction);
    tracer.path.push(event);
    trace(ray, next, throughput, depth + 1, tracer);
    tracer.path.pop();
}

}  // namespace lightpath
