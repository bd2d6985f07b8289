#include "integrators/direct_light.h"

#include "geometry/spawn_ray.h"
#include "integrators/integrator.h"

namespace lightpath {
namespace {

// Where the background's event is drawn: a point this far along the escaping ray.
constexpr float kBackgroundDistance = 100.0f;

// One light sample through both smooth lobes, with one shadow ray.
void addLightSample(const ShadingPoint& p, const Rgb& throughput, const LightSample& sample, float choiceProbability,
                    const Light& light, DirectLightWeighting weighting, PathState& path) {
    const RenderContext& ctx = path.context;
    const bool skip = ctx.skipEnabled;
    RayCounters& counters = path.counters;
    // The lecture's own-primitive test: p is in the shadow of its own surface iff N.(b - p) <= 0.
    const float cosTheta = glm::dot(p.normal, sample.wi);
    const bool litSide = cosTheta > 0.0f && sample.distance > 0.0f;
    if (!litSide && skip) {
        ++counters.shadowBehind;
        return;
    }
    PathEvent lightEvent = light.event();
    lightEvent.position = sample.point;
    const PathEvent events[2] = {p.eventOf(Lobe::Diffuse), p.eventOf(Lobe::Highlight)};
    const bool wanted[2] = {path.wants(events[0], lightEvent), path.wants(events[1], lightEvent)};
    if (!wanted[0] && !wanted[1]) {
        ++counters.shadowDead;
        return;
    }

    const Rgb incident = litSide ? sample.weight / choiceProbability : Rgb{0.0f};
    const float lightPdf = sample.pdf * choiceProbability;
    Rgb value[2] = {Rgb{0.0f}, Rgb{0.0f}};
    for (int l = 0; l < 2; ++l) {
        const Lobe lobe = kSmoothLobes[l];
        const bool present = lobe == Lobe::Diffuse ? p.terms.diffuse : p.terms.highlight;
        if (!wanted[l] || !(present || !skip)) {
            if (lobe == Lobe::Highlight && !present) ++counters.highlightNoKs;
            continue;
        }
        if (lobe == Lobe::Highlight) ++counters.highlightEvaluated;
        float weight = 1.0f;
        if (weighting == DirectLightWeighting::MultipleImportance && lightPdf > 0.0f)
            weight = powerHeuristic(lightPdf, p.bsdf.pdf(lobe, p.wo, sample.wi));
        value[l] = throughput * p.bsdf.eval(lobe, p.wo, sample.wi) * incident * weight;
    }
    if (skip && isBlack(value[0]) && isBlack(value[1])) {
        ++counters.shadowZero;
        return;
    }

    ++counters.shadow;
    if (ctx.geometry.occluded(spawnShadowRay(p.hit, sample.point, ctx.geometry.numerics()))) return;
    for (int l = 0; l < 2; ++l)
        if (wanted[l] && !(skip && isBlack(value[l]))) path.emit(events[l], lightEvent, value[l]);
}

}  // namespace

float powerHeuristic(float pdf, float otherPdf) {
    // Squared in double: a pdf above 1.8e19 (a small light seen edge-on) squares to infinity in
    // float, and inf / inf is NaN.
    const double a = double(pdf) * pdf, b = double(otherPdf) * otherPdf;
    return a + b > 0.0 ? static_cast<float>(a / (a + b)) : 0.0f;
}

void addDirectLight(const ShadingPoint& point, const Rgb& throughput, const LightChoiceSample& u,
                    DirectLightWeighting weighting, PathState& path) {
    const LightSet& lights = path.context.lights;
    for (const Light* light : lights.deltaLights())
        addLightSample(point, throughput, light->sample(point.hit.point, u.uPoint), 1.0f, *light, weighting, path);
    const ChosenLight chosen = lights.chooseAreaLight(u.uChoice);
    if (chosen.light == nullptr) return;
    addLightSample(point, throughput, chosen.light->sample(point.hit.point, u.uPoint), chosen.probability,
                   *chosen.light, weighting, path);
}

void addAmbient(const ShadingPoint& point, const Rgb& throughput, PathState& path) {
    const RenderContext& ctx = path.context;
    if (!point.terms.ambient && ctx.skipEnabled) return;
    const PathEvent ambient{lpe::EventType::Emitter, lpe::Scatter::None, Subject::Ambient, 0, point.hit.point};
    const PathEvent diffuse = point.eventOf(Lobe::Diffuse);
    if (!path.wants(diffuse, ambient)) return;
    path.emit(diffuse, ambient, throughput * point.material.ka * ctx.scene.ambient);
}

void addLocalIllumination(const ShadingPoint& point, const Rgb& throughput, PathState& path) {
    addAmbient(point, throughput, path);
    if (path.sampler == nullptr) return;
    Sampler vertex = path.sampler->forVertex(path.key());
    const float uChoice = vertex.next1D();
    const Vec2 uPoint = vertex.next2D();
    addDirectLight(point, throughput, {uChoice, uPoint}, DirectLightWeighting::Alone, path);
}

void addEmission(const SurfaceHit& hit, const Ray& ray, const Rgb& throughput, float weight, PathState& path) {
    const Light* light = path.context.lights.lightOfObject(hit.object);
    if (light == nullptr) return;
    const Rgb emitted = light->radiance(hit, -ray.direction);
    if (isBlack(emitted)) return;
    PathEvent event = light->event();
    event.position = hit.point;
    path.emit(event, throughput * emitted * weight);
}

void addBackground(const Ray& ray, const Rgb& throughput, PathState& path) {
    const Rgb& background = path.context.scene.background;
    if (isBlack(background) && path.context.skipEnabled) return;
    path.emit({lpe::EventType::Background, lpe::Scatter::None, Subject::None, 0, ray.at(kBackgroundDistance)},
              throughput * background);
}

}  // namespace lightpath
