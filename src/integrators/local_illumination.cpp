#include "integrators/local_illumination.h"

#include <cmath>

#include "geometry/ray_offset.h"

namespace lightpath {
namespace {

// Shadow segments stop this fraction short of the light, so a light placed on a surface does not
// shadow itself.
constexpr float kShadowShortening = 1e-5f;

Ray spawnShadowRay(const Vec3& point, const Vec3& normal, const Vec3& lightPosition) {
    Ray ray;
    ray.origin = offsetRayOrigin(point, normal);
    const Vec3 toLight = lightPosition - ray.origin;
    const float distance = glm::length(toLight);
    ray.direction = toLight / distance;
    ray.tMax = distance * (1.0f - kShadowShortening);
    return ray;
}

}  // namespace

void addLocalIllumination(const SurfaceHit& hit, const Vec3& normal, const Vec3& towardViewer,
                          lpe::Automaton::State state, const Rgb& throughput, Tracer& tracer) {
    const RenderContext& ctx = tracer.context;
    const Scene& scene = ctx.scene;
    const PhongMaterial& material = scene.materials[scene.objects[hit.object].material];
    const SurfaceSymbols& symbols = ctx.symbols.objects[hit.object];
    const auto subject = static_cast<std::int32_t>(hit.object);
    const PathEvent diffuseEvent{lpe::EventType::Reflection, lpe::Scatter::Diffuse, subject};
    const PathEvent glossyEvent{lpe::EventType::Reflection, lpe::Scatter::Glossy, subject};

    const Rgb ambient = material.ka * scene.ambient;
    if (!isBlack(ambient)) {
        tracer.emit(state, diffuseEvent, symbols.diffuse,
                    {lpe::EventType::Emitter, lpe::Scatter::None, kSubjectAmbient},
                    ctx.symbols.ambient, throughput * ambient);
    }

    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        const PointLight& light = scene.lights[i];
        const Vec3 toLight = light.position - hit.point;
        // The lecture's own-primitive test: p is in the shadow of its own surface iff N.(b - p) < 0.
        if (glm::dot(normal, toLight) <= 0.0f) continue;
        const float distance = glm::length(toLight);
        const Vec3 l = toLight / distance;
        const Rgb intensity = light.intensity * light.attenuationAt(distance);

        const Rgb diffuse = material.kd * intensity * glm::dot(normal, l);
        const Vec3 halfway = l + towardViewer;
        const float halfwayLength = glm::length(halfway);
        const float hDotN = halfwayLength > 0.0f ? glm::max(0.0f, glm::dot(normal, halfway) / halfwayLength) : 0.0f;
        const Rgb highlight = material.ks * intensity * std::pow(hDotN, material.n);
        if (isBlack(diffuse) && isBlack(highlight)) continue;

        ++tracer.counters.shadow;
        if (ctx.geometry.occluded(spawnShadowRay(hit.point, normal, light.position))) continue;

        const PathEvent lightEvent{lpe::EventType::Emitter, lpe::Scatter::None, static_cast<std::int32_t>(i)};
        if (!isBlack(diffuse))
            tracer.emit(state, diffuseEvent, symbols.diffuse, lightEvent, ctx.symbols.lights[i], throughput * diffuse);
        if (!isBlack(highlight))
            tracer.emit(state, glossyEvent, symbols.glossy, lightEvent, ctx.symbols.lights[i], throughput * highlight);
    }
}

}  // namespace lightpath
