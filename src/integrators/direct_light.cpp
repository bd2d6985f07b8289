#include "integrators/direct_light.h"

#include <limits>

#include <cmath>
#include <cstdio>

#include "geometry/spawn_ray.h"
#include "integrators/integrator.h"
#include "util/hot_path.h"

namespace lightpath {
namespace {

// Where the background's event is drawn: a point this far along the escaping ray.
constexpr float kBackgroundDistance = 100.0f;

std::string formatted(const char* format, double a, double b = 0.0) {
    char text[160];
    std::snprintf(text, sizeof text, format, a, b);
    return text;
}

// `explain`: the factors of one term. Under a point light and without MIS they are Szymczak's
// (kd, N.L, I, attenuation; ks, (H.N)^n, I, attenuation), whose product is the value; otherwise
// the Monte Carlo estimate's (f |cos|, incident light over its density, the two densities, the
// MIS weight). In a medium the shadow ray's transmittance is a factor of its own.
std::size_t termFactors(const ShadingPoint& p, int lobe, const LightSample& sample, const Light& light,
                        const Rgb& incident, const Rgb& transmittance, float lightPdf, float weight,
                        DirectLightWeighting weighting, const Rgb& throughput,
                        std::array<TermFactor, kMaxTermFactors>& factors) {
    std::size_t n = 0;
    if (light.isDelta() && !light.atInfinity() && weighting == DirectLightWeighting::Alone) {
        const float falloff = light.falloff(sample.distance);
        NamedFactors named;
        const int count = p.bsdf.factors(lobe, p.wo, sample.wi, named);
        for (int i = 0; i < count; ++i) factors[n++] = {named[i].name, named[i].value};
        // A spot's cone is a factor of its own, so that I reads as the scene file's intensity.
        const float share = light.intensityShare(-sample.wi);
        factors[n++] = {"I", share > 0.0f ? incident / (kPi * falloff * share) : incident / (kPi * falloff)};
        if (share != 1.0f) factors[n++] = {"cone", Rgb{share}};
        factors[n++] = {"attenuation", Rgb{falloff}};
    } else {
        factors[n++] = {"f cos", p.bsdf.eval(lobe, p.wo, sample.wi)};
        factors[n++] = {"Li/pdf", incident};
        if (weighting == DirectLightWeighting::MultipleImportance) {
            factors[n++] = {"light pdf", Rgb{lightPdf}, false};
            factors[n++] = {"bsdf pdf", Rgb{p.bsdf.pdf(lobe, p.wo, sample.wi)}, false};
            factors[n++] = {"mis weight", Rgb{weight}};
        }
    }
    if (transmittance != Rgb{1.0f} && n < kMaxTermFactors) factors[n++] = {"transmittance", transmittance};
    if (throughput != Rgb{1.0f} && n < kMaxTermFactors) factors[n++] = {"throughput", throughput};
    return n;
}

// A shading point's smooth lobes (those light sampling can reach, any number the material
// declares) and where the path stands before them, shared by its ambient term and every light
// sample: each term reads the outputs its lobes reach from the per-render table
// (lobe_step_table.h) instead of stepping the automaton per lobe.
struct SmoothLobeEvents {
    const ShadingPoint& point;
    PathState::SurfaceLobes at;

    SmoothLobeEvents(const ShadingPoint& p, const PathState& path) : point(p), at(path.surfaceLobes(p.hit.object)) {}
    const SmoothLobes& smooth() const { return at.lobes; }
    PathEvent event(int slot) const { return point.eventOf(at.lobes.lobe[slot]); }
};

// `explain`: why a light sample added nothing through any lobe.
std::string zeroReason(const ShadingPoint& p, const SmoothLobeEvents& lobes, const LightSample& sample, bool litSide) {
    if (!litSide) return formatted("the light is behind the surface (N.L = %.3f)", glm::dot(p.normal, sample.wi));
    if (isBlack(sample.weight)) return "the light sends nothing this way (a one-sided emitter seen from behind, or dark)";
    std::string absent;  // "kd = 0 and ks = 0" when no smooth lobe scatters anything
    for (int l = 0; l < lobes.smooth().count; ++l) {
        if (p.terms.lobes[lobes.smooth().lobe[l]]) return "the term is zero here";
        absent += std::string(absent.empty() ? "" : " and ") + p.bsdf.lobe(lobes.smooth().lobe[l]).coefficient + " = 0";
    }
    return "the term is zero: " + absent;
}

// `explain`: a light sample that added nothing through any lobe (cold: see emitExplained).
[[gnu::cold, gnu::noinline]] void rejectZero(const ShadingPoint& p, const SmoothLobeEvents& lobes,
                                             const LightSample& sample, bool litSide, const PathEvent& lightEvent,
                                             PathState& path) {
    path.reject(lobes.event(0), lightEvent, zeroReason(p, lobes, sample, litSide));
}

// `explain`: the shadow ray of a light sample is blocked; by what, and where.
[[gnu::cold, gnu::noinline]] void rejectBlocked(const SmoothLobeEvents& lobes, const Ray& shadowRay,
                                                const PathEvent& lightEvent, float distance, PathState& path) {
    const RenderContext& ctx = path.context;
    const auto blocker = ctx.geometry.intersect(shadowRay);
    const PathEvent blocked{lpe::EventType::Reflection, lpe::Scatter::None, Subject::Object,
                            blocker ? blocker->object : 0};
    path.reject(lobes.event(0), lightEvent,
                "the shadow ray towards " + subjectName(ctx.scene, lightEvent) + " is blocked by " +
                    (blocker ? subjectName(ctx.scene, blocked) : std::string("an object")) +
                    formatted(" at t = %.3f (of %.3f)", blocker ? blocker->t : 0.0, distance));
}

// What `explain` needs of one light sample beside its per-lobe values.
struct LightTerms {
    const LightSample& sample;
    const Light& light;
    Rgb incident;
    Rgb transmittance;
    float lightPdf;
    DirectLightWeighting weighting;
    const Rgb& throughput;
};

[[gnu::cold, gnu::noinline]] void emitExplained(const ShadingPoint& p, const SmoothLobeEvents& lobes,
                                                const LightTerms& terms, const PathEvent& lightEvent,
                                                const Rgb* value, const float* weights,
                                                const lpe::OutputMask* accepted, unsigned wanted, PathState& path);

// One light sample through every smooth lobe, with one shadow ray from `origins` (p's). Inlined
// into addDirectLight's one loop over the lights (docs/performance.md, seventh pass).
[[gnu::always_inline]] inline void addLightSample(const ShadingPoint& p, const SmoothLobeEvents& lobes,
                                                  RayOrigins& origins, const Rgb& throughput, const LightSample& sample,
                                                  float choiceProbability, const Light& light,
                                                  DirectLightWeighting weighting, PathState& path,
                                                  const Medium* medium) {
    if (lobes.smooth().count == 0) return;
    const RenderContext& ctx = path.context;
    const bool skip = ctx.skipEnabled;
    RayCounters& counters = path.counters;
    // The lecture's own-primitive test: p is in the shadow of its own surface iff N.(b - p) <= 0,
    // unless a smooth lobe transmits: light from behind then passes through (its eval says how much).
    const float cosTheta = glm::dot(p.normal, sample.wi);
    const bool litSide = (cosTheta > 0.0f || p.terms.smoothTransmission) && sample.distance > 0.0f;
    // The light's event at the sample, for `explain`'s records only: made where they are.
    const auto lightEvent = [&] {
        PathEvent event = light.event();
        event.position = sample.point;
        return event;
    };
    if (!litSide && skip) {
        ++counters.shadowBehind;
        if (path.explaining()) [[unlikely]]
            rejectZero(p, lobes, sample, litSide, lightEvent(), path);
        return;
    }
    lpe::OutputMask stepped[kMaxLobes];
    const lpe::OutputMask* accepted = path.acceptsThrough(lobes.at, path.lightColumn(light.event()), stepped);
    // Bit l: lobe l's term reaches a requested output. A bit set, not a bool array: GCC made
    // the array a memset call per sample when `rest` keeps every path.
    const unsigned wanted = path.wantedLobes(accepted, lobes.smooth().count);
    const auto isWanted = [&](int l) { return (wanted >> l & 1u) != 0; };
    if (wanted == 0) {
        ++counters.shadowDead;
        return;
    }

    const Rgb incident = litSide ? sample.weight / choiceProbability : Rgb{0.0f};
    // Through index-matched boundaries the shadow ray crosses media: its transmittance is traced
    // segment by segment, and black means blocked.
    const bool throughInterfaces = ctx.scene.interfaces && ctx.shadows;
    const Rgb transmittance =
        throughInterfaces ? shadowTransmittance(spawnShadowRay(origins, sample.point, sample.normal), sample.point,
                                                sample.normal, ctx.scene.indexOf(medium), ctx)
        : medium != nullptr ? medium->transmittance(Ray{p.hit.point, sample.wi}, 0.0f, sample.distance)
                            : Rgb{1.0f};
    const Rgb seen = incident * transmittance;  // x * 1 is x: no cost to bit-identity without media
    const float lightPdf = sample.pdf * choiceProbability;
    Rgb value[kMaxLobes];
    float weights[kMaxLobes];
    bool anyValue = false;
    for (int l = 0; l < lobes.smooth().count; ++l) {
        const int lobe = lobes.smooth().lobe[l];
        value[l] = Rgb{0.0f};
        weights[l] = 1.0f;
        const bool present = p.terms.lobes[lobe];
        const bool glossy = lobes.smooth().glossy[l];
        if (!isWanted(l) || !(present || !skip)) {
            if (glossy && !present) ++counters.glossyAbsent;
            continue;
        }
        if (glossy) ++counters.glossyEvaluated;
        if (weighting == DirectLightWeighting::MultipleImportance && lightPdf > 0.0f)
            weights[l] = powerHeuristic(lightPdf, p.bsdf.pdf(lobe, p.wo, sample.wi));
        value[l] = throughput * p.bsdf.eval(lobe, p.wo, sample.wi) * seen * weights[l];
        anyValue = anyValue || !isBlack(value[l]);
    }
    if (skip && !anyValue) {
        ++counters.shadowZero;
        if (path.explaining()) [[unlikely]]
            rejectZero(p, lobes, sample, litSide, lightEvent(), path);
        return;
    }

    if (ctx.shadows) {
        ++counters.shadow;
        if (medium != nullptr) ++counters.mediumShadow;
        const Ray shadowRay = spawnShadowRay(origins, sample.point, sample.normal);
        if (throughInterfaces ? isBlack(transmittance) : ctx.geometry.occluded(shadowRay)) {
            if (path.explaining()) [[unlikely]]
                rejectBlocked(lobes, shadowRay, lightEvent(), sample.distance, path);
            return;
        }
    }
    if (path.explaining()) [[unlikely]] {
        const LightTerms terms{sample, light, incident, transmittance, lightPdf, weighting, throughput};
        emitExplained(p, lobes, terms, lightEvent(), value, weights, accepted, wanted, path);
        return;
    }
    for (int l = 0; l < lobes.smooth().count; ++l) {
        if (!isWanted(l) || (skip && isBlack(value[l]))) continue;
        path.addAccepted(value[l], accepted[l]);
    }
}

// `explain`'s part of addLightSample, out of line and cold (GCC places it apart from the hot
// code): every term with its factors, then the absent lobes beside present ones. Inline, this and
// the rejections below made addLightSample 9.3 KB, its hot lines spread among the cold ones.
[[gnu::cold, gnu::noinline]] void emitExplained(const ShadingPoint& p, const SmoothLobeEvents& lobes,
                                                const LightTerms& terms, const PathEvent& lightEvent,
                                                const Rgb* value, const float* weights,
                                                const lpe::OutputMask* accepted, unsigned wanted, PathState& path) {
    const bool skip = path.context.skipEnabled;
    const auto isWanted = [&](int l) { return (wanted >> l & 1u) != 0; };
    for (int l = 0; l < lobes.smooth().count; ++l) {
        if (!isWanted(l) || (skip && isBlack(value[l]))) continue;
        std::array<TermFactor, kMaxTermFactors> factors;
        const std::size_t count =
            termFactors(p, lobes.smooth().lobe[l], terms.sample, terms.light, terms.incident, terms.transmittance,
                        terms.lightPdf, weights[l], terms.weighting, terms.throughput, factors);
        path.emitAccepted(lobes.event(l), lightEvent, value[l], accepted[l], std::span(factors.data(), count));
    }
    // A lobe that is absent beside one that scatters, in the lecture's order (ks = 0 beside kd):
    // say so, as its term is part of the formula.
    bool earlierPresent = false;
    for (int l = 0; l < lobes.smooth().count; ++l) {
        const int lobe = lobes.smooth().lobe[l];
        if (isWanted(l) && !p.terms.lobes[lobe] && earlierPresent) {
            const LobeInfo& info = p.bsdf.lobe(lobe);
            path.reject(lobes.event(l), lightEvent,
                        std::string("the ") + info.name + " term is zero: " + info.coefficient + " = 0");
        }
        earlierPresent = earlierPresent || p.terms.lobes[lobe];
    }
}

LIGHTPATH_HOT_PATH
void addDirectLight(const ShadingPoint& point, const SmoothLobeEvents& lobes, RayOrigins& origins, const Rgb& throughput,
                    const LightChoiceSample& u, DirectLightWeighting weighting, PathState& path,
                    const Medium* medium = nullptr) {
    const LightSet& lights = path.context.lights;
    // Every delta light, then the chosen area light, through one call site: the sample's code is
    // inlined here once, the shading point's values kept in registers across the lights.
    const std::span<const Light* const> delta = lights.deltaLights();
    const ChosenLight chosen = lights.chooseAreaLight(u.uChoice);
    const std::size_t count = delta.size() + (chosen.light != nullptr ? 1 : 0);
    for (std::size_t i = 0; i < count; ++i) {
        const bool isDelta = i < delta.size();
        const Light& light = isDelta ? *delta[i] : *chosen.light;
        addLightSample(point, lobes, origins, throughput, light.sample(point.hit.point, u.uPoint),
                       isDelta ? 1.0f : chosen.probability, light, weighting, path, medium);
    }
}

// One light sample scattered at a medium point: one shadow ray, attenuated by the medium.
void addMediumLightSample(const MediumPoint& m, const Rgb& throughput, const LightSample& sample,
                          float choiceProbability, const Light& light, DirectLightWeighting weighting, PathState& path) {
    const RenderContext& ctx = path.context;
    RayCounters& counters = path.counters;
    PathEvent lightEvent = light.event();
    lightEvent.position = sample.point;
    const PathEvent scatter = m.event();
    const lpe::OutputMask accepted = path.acceptsAfter(path.stateAfter(scatter), lightEvent);
    if (!path.wanted(accepted)) {
        ++counters.shadowDead;
        return;
    }
    if (!(sample.distance > 0.0f) || (isBlack(sample.weight) && ctx.skipEnabled)) {
        ++counters.shadowZero;
        if (path.explaining()) path.reject(scatter, lightEvent, "the light sends nothing to the medium point");
        return;
    }
    const HenyeyGreensteinPhase phase = m.medium.phase(m.point);
    const float phaseValue = phase.eval(m.wo, sample.wi);
    const float lightPdf = sample.pdf * choiceProbability;
    const float weight = weighting == DirectLightWeighting::MultipleImportance && lightPdf > 0.0f
                             ? powerHeuristic(lightPdf, phase.pdf(m.wo, sample.wi))
                             : 1.0f;
    const Ray shadowRay = spawnShadowRay(m.point, sample.point, sample.normal, ctx.geometry.numerics());
    if (ctx.shadows) {
        ++counters.shadow;
        ++counters.mediumShadow;
        const bool blocked = ctx.scene.interfaces ? isBlack(shadowTransmittance(shadowRay, sample.point, sample.normal, m.index, ctx))
                                                  : ctx.geometry.occluded(shadowRay);
        if (blocked) {
            if (path.explaining()) path.reject(scatter, lightEvent, "the shadow ray from the medium point is blocked");
            return;
        }
    }
    // Through interfaces, the media beyond them attenuate too (pbrt-v4's SampleLd crosses them).
    const Rgb transmittance = ctx.scene.interfaces && ctx.shadows
                                  ? shadowTransmittance(shadowRay, sample.point, sample.normal, m.index, ctx)
                                  : m.medium.transmittance(shadowRay, 0.0f, sample.distance);
    const Rgb incident = sample.weight / choiceProbability;
    const Rgb value = throughput * phaseValue * incident * transmittance * weight;
    if (!path.explaining()) {
        path.emitAccepted(scatter, lightEvent, value, accepted);
        return;
    }
    const TermFactor factors[] = {{"phase", Rgb{phaseValue}},
                                  {"Li/pdf", incident},
                                  {"transmittance", transmittance},
                                  {"mis weight", Rgb{weight}},
                                  {"throughput", throughput}};
    path.emitAccepted(scatter, lightEvent, value, accepted, std::span(factors, 5));
}

LIGHTPATH_HOT_PATH
void addAmbient(const ShadingPoint& point, const SmoothLobeEvents& lobes, const Rgb& throughput, PathState& path) {
    const RenderContext& ctx = path.context;
    if (!point.terms.ambient && ctx.skipEnabled) return;
    const PathEvent ambient{lpe::EventType::Emitter, lpe::Scatter::None, Subject::Ambient, 0, point.hit.point};
    if (lobes.smooth().ambient < 0) return;  // no diffuse reflection to carry it
    lpe::OutputMask stepped[kMaxLobes];
    const lpe::OutputMask accepted = path.acceptsThrough(lobes.at, path.ambientColumn(), stepped)[lobes.smooth().ambient];
    if (!path.wanted(accepted)) return;
    const Rgb ka = point.bsdf.ambientReflectance();
    const Rgb value = throughput * ka * ctx.scene.ambient;
    if (!path.explaining()) {
        path.addAccepted(value, accepted);
        return;
    }
    const TermFactor factors[] = {{"ka", ka}, {"Ia", ctx.scene.ambient}, {"throughput", throughput}};
    path.emitAccepted(lobes.event(lobes.smooth().ambient), ambient, value, accepted, std::span(factors, throughput == Rgb{1.0f} ? 2 : 3));
}

}  // namespace

LIGHTPATH_HOT_PATH
float powerHeuristic(float pdf, float otherPdf) {
    // Squared in double: a pdf above 1.8e19 (a small light seen edge-on) squares to infinity in
    // float, and inf / inf is NaN.
    const double a = double(pdf) * pdf, b = double(otherPdf) * otherPdf;
    return a + b > 0.0 ? static_cast<float>(a / (a + b)) : 0.0f;
}

LIGHTPATH_HOT_PATH
void addDirectLight(const ShadingPoint& point, const Rgb& throughput, const LightChoiceSample& u,
                    DirectLightWeighting weighting, PathState& path, const Medium* medium) {
    RayOrigins origins(point.hit, path.context.geometry.numerics());  // shared by the shadow rays of every light
    addDirectLight(point, SmoothLobeEvents(point, path), origins, throughput, u, weighting, path, medium);
}

LIGHTPATH_HOT_PATH
void addDirectLight(const ShadingPoint& point, RayOrigins& origins, const Rgb& throughput, const LightChoiceSample& u,
                    DirectLightWeighting weighting, PathState& path, const Medium* medium) {
    addDirectLight(point, SmoothLobeEvents(point, path), origins, throughput, u, weighting, path, medium);
}

void addMediumDirectLight(const MediumPoint& point, const Rgb& throughput, const LightChoiceSample& u,
                          DirectLightWeighting weighting, PathState& path) {
    const LightSet& lights = path.context.lights;
    for (const Light* light : lights.deltaLights())
        addMediumLightSample(point, throughput, light->sample(point.point, u.uPoint), 1.0f, *light, weighting, path);
    const ChosenLight chosen = lights.chooseAreaLight(u.uChoice);
    if (chosen.light == nullptr) return;
    addMediumLightSample(point, throughput, chosen.light->sample(point.point, u.uPoint), chosen.probability,
                         *chosen.light, weighting, path);
}

LIGHTPATH_HOT_PATH
void addAmbient(const ShadingPoint& point, const Rgb& throughput, PathState& path) {
    if (!point.terms.ambient && path.context.skipEnabled) return;
    addAmbient(point, SmoothLobeEvents(point, path), throughput, path);
}

void addSingleScattering(const Ray& ray, float tMax, const Medium& medium, std::uint32_t index, const Rgb& throughput,
                         PathState& path) {
    // Enough strata that a shaft's edge is smooth at one sample per pixel.
    constexpr int kSingleScatteringSteps = 32;
    const LightSet& lights = path.context.lights;
    if (lights.deltaLights().empty() || path.sampler == nullptr) return;
    Sampler vertex = path.sampler->forVertex(path.key());
    const float jitter = vertex.next1D();
    const float uChannel = vertex.next1D();
    for (int k = 0; k < kSingleScatteringSteps; ++k) {
        const float u = (float(k) + jitter) / kSingleScatteringSteps;
        const MediumSample flight = medium.sampleDistance(ray, tMax, uChannel, u);
        if (!flight.scattered || isBlack(flight.weight)) continue;
        const MediumPoint point{ray.at(flight.t), -ray.direction, medium, index};
        const Rgb weight = throughput * flight.weight / float(kSingleScatteringSteps);
        ++path.counters.singleScattering;
        for (const Light* light : lights.deltaLights())
            addMediumLightSample(point, weight, light->sample(point.point, Vec2{0.0f}), 1.0f, *light,
                                 DirectLightWeighting::Alone, path);
    }
}

LIGHTPATH_HOT_PATH
Rgb throughMedium(const std::optional<SurfaceHit>& hit, const Ray& ray, std::uint32_t mediumIndex,
                  const Rgb& throughput, PathState& path) {
    const Medium* medium = path.context.scene.medium(mediumIndex);
    if (medium == nullptr) return throughput;
    const float tMax = hit ? hit->t : std::numeric_limits<float>::infinity();
    ++path.counters.mediumSegments;
    addSingleScattering(ray, tMax, *medium, mediumIndex, throughput, path);
    return throughput * medium->transmittance(ray, 0.0f, tMax);
}

BeyondInterfaces crossInterfaces(std::optional<SurfaceHit> hit, Ray ray, std::uint32_t mediumIndex,
                                 Rgb throughput, PathState& path) {
    const RenderContext& ctx = path.context;
    for (int crossing = 0; crossing < kMaxInterfaceCrossings && hit && ctx.scene.crossedWithoutEvent(hit->object);
         ++crossing) {
        throughput = throughMedium(hit, ray, mediumIndex, throughput, path);
        const bool entering = glm::dot(hit->normal, ray.direction) < 0.0f;
        mediumIndex = ctx.scene.mediumBeyond(hit->object, entering, mediumIndex);
        ray = spawnRay(*hit, ray.direction, ctx.geometry.numerics());
        hit = ctx.geometry.intersect(ray);
    }
    return {hit, ray, mediumIndex, throughput};
}

Rgb shadowTransmittance(Ray ray, const Vec3& target, const Vec3& targetNormal, std::uint32_t mediumIndex,
                        const RenderContext& ctx) {
    Rgb transmittance{1.0f};
    Vec3 from = ray.origin;
    for (int crossing = 0; crossing <= kMaxInterfaceCrossings; ++crossing) {
        const auto hit = ctx.geometry.intersect(ray);
        const Vec3 to = hit ? hit->point : target;
        const float distance = glm::length(to - from);
        if (const Medium* medium = ctx.scene.medium(mediumIndex); medium != nullptr && distance > 0.0f)
            transmittance *= medium->transmittance(Ray{from, (to - from) / distance}, 0.0f, distance);
        if (!hit) return transmittance;
        if (!ctx.scene.crossedWithoutEvent(hit->object)) return Rgb{0.0f};
        const bool entering = glm::dot(hit->normal, ray.direction) < 0.0f;
        mediumIndex = ctx.scene.mediumBeyond(hit->object, entering, mediumIndex);
        from = hit->point;
        ray = spawnShadowRay(*hit, target, targetNormal, ctx.geometry.numerics());
    }
    return Rgb{0.0f};
}

std::uint32_t cameraMedium(const RenderContext& ctx) {
    const Scene& scene = ctx.scene;
    if (scene.media.empty()) return scene.worldMedium;
    Ray ray{ctx.camera.eye(), glm::normalize(Vec3{0.2897f, 0.8231f, 0.4883f})};
    for (int crossing = 0; crossing < kMaxInterfaceCrossings; ++crossing) {
        const auto hit = ctx.geometry.intersect(ray);
        if (!hit) break;
        // Only a boundary of a medium decides: a closed room without one around the eye leaves it in
        // [world]'s fog, as before there were interfaces.
        const SceneObject& object = scene.objects[hit->object];
        if (object.enclosesVolume && object.interior != kNoMedium) {
            const bool leaving = glm::dot(hit->normal, ray.direction) > 0.0f;
            return leaving ? object.interior : scene.worldMedium;
        }
        ray = spawnRay(*hit, ray.direction, ctx.geometry.numerics());
    }
    return scene.worldMedium;
}

LIGHTPATH_HOT_PATH
void addLocalIllumination(const ShadingPoint& point, const Rgb& throughput, PathState& path, const Medium* medium) {
    const SmoothLobeEvents lobes(point, path);
    addAmbient(point, lobes, throughput, path);
    if (path.sampler == nullptr) return;
    // Only area lights read these numbers (the one delta light, PointLightSource, is one point and
    // ignores them; a delta light that sampled would have to be counted here): without any area
    // light the vertex's sampler is not made. It is keyed by the path, so no other sample depends on it.
    LightChoiceSample u{0.0f, Vec2{0.0f}};
    if (path.context.lights.hasAreaLights()) {
        Sampler vertex = path.sampler->forVertex(path.key());
        u = drawLightChoice(vertex, path.context.lights);
    }
    RayOrigins origins(point.hit, path.context.geometry.numerics());  // shared by the shadow rays of every light
    addDirectLight(point, lobes, origins, throughput, u, DirectLightWeighting::Alone, path, medium);
}

LIGHTPATH_HOT_PATH
void addEmission(const SurfaceHit& hit, const Ray& ray, const Rgb& throughput, float weight, PathState& path) {
    const Light* light = path.context.lights.lightOfObject(hit.object);
    if (light == nullptr) return;
    const Rgb emitted = light->radiance(hit, -ray.direction);
    if (isBlack(emitted)) return;
    PathEvent event = light->event();
    event.position = hit.point;
    if (!path.explaining()) {
        path.emit(event, throughput * emitted * weight);
        return;
    }
    const TermFactor factors[] = {{"Le", emitted}, {"mis weight", Rgb{weight}}, {"throughput", throughput}};
    path.emit(event, throughput * emitted * weight, std::span(factors, 3));
}

LIGHTPATH_HOT_PATH
void addBackground(const Ray& ray, const Rgb& throughput, PathState& path) {
    const Rgb& background = path.context.scene.background;
    if (isBlack(background) && path.context.skipEnabled) return;
    const PathEvent event{lpe::EventType::Background, lpe::Scatter::None, Subject::None, 0, ray.at(kBackgroundDistance)};
    if (!path.explaining()) {
        path.emit(event, throughput * background);
        return;
    }
    // The background seen in a mirror is kr times it: `throughput` is the kr/kt product (and, for
    // the path tracer, the sampled bounces' f cos / pdf).
    const TermFactor factors[] = {{"Lb", background}, {"throughput", throughput}};
    path.emit(event, throughput * background, std::span(factors, throughput == Rgb{1.0f} ? 1 : 2));
}

}  // namespace lightpath
