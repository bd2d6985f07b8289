#include "integrators/raycast.h"

#include "integrators/local_illumination.h"

namespace lightpath {

void addBackground(lpe::Automaton::State state, const Rgb& throughput, Tracer& tracer) {
    const Rgb& background = tracer.context.scene.background;
    if (isBlack(background) && tracer.context.skipEnabled) return;
    tracer.emit(state, {lpe::EventType::Background, lpe::Scatter::None, Subject::None},
                tracer.context.symbols.background, throughput * background);
}

void addSurfaceEmission(const SurfaceHit& hit, const Vec3& towardViewer, lpe::Automaton::State state,
                        const Rgb& throughput, Tracer& tracer) {
    const Rgb emitted = tracer.context.emitters.radiance(hit, towardViewer);
    if (isBlack(emitted)) return;
    tracer.emit(state, {lpe::EventType::Emitter, lpe::Scatter::None, Subject::Object, hit.object},
                tracer.context.symbols.objects[hit.object].emission, throughput * emitted);
}

void RaycastIntegrator::traceCameraRay(const Ray& ray, lpe::Automaton::State state, Tracer& tracer) const {
    const auto hit = tracer.context.geometry.intersect(ray);
    if (!hit) {
        addBackground(state, Rgb{1.0f}, tracer);
        return;
    }
    // N points to the side the ray came from (Szymczak: "N should point to the side containing
    // the viewpoint").
    const Vec3 normal = glm::dot(hit->normal, ray.direction) < 0.0f ? hit->shadingNormal : -hit->shadingNormal;
    addSurfaceEmission(*hit, -ray.direction, state, Rgb{1.0f}, tracer);
    addLocalIllumination(*hit, normal, -ray.direction, state, Rgb{1.0f}, tracer);
}

}  // namespace lightpath
