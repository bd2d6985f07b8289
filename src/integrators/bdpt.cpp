#include "integrators/bdpt.h"

#include "integrators/registry.h"
#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

#include "geometry/spawn_ray.h"
#include "integrators/light_ray.h"
#include "integrators/bdpt_allocation.h"
#include "integrators/bdpt_vertex.h"
#include "integrators/direct_light.h"
#include "sampling/russian_roulette.h"

namespace lightpath {
namespace {

// Names the light walk's own random numbers within a pixel sample (Sampler::forVertex), so the
// eye's walk draws the same numbers whether or not a light walk was traced.
constexpr std::uint64_t kLightWalkKey = 0x6c69676874ull;  // "light"
// Names the number that decides whether a camera sample takes one more light walk (a fraction
// q - floor(q) of them do): its own dimension, stratified over the pixel's samples like the others.
constexpr std::uint64_t kLightWalkChoiceKey = 0x63686f696365ull;  // "choice"

// How one camera sample weighs the light walk's strategies. Under q light walks per camera sample
// on average, light tracing counts q samples in the power heuristic and its splats are divided by
// q, the joins (of the first walk) count min(q, 1) and are divided by it (bdpt_allocation.h); the
// pilot tallies them instead.
struct Weights {
    double lightWalks = 1.0;  // light walks per camera sample, q (0: none)
    float splatScale = 1.0f;  // 1 / q
    float joinScale = 1.0f;   // 1 / min(q, 1)
    PilotSample* pilot = nullptr;
    const Rgb* pilotBeauty = nullptr;  // the pilot's sink's beauty, read around s = 0's emission
};

using Vertices = std::array<BdptVertex, kMaxSubpathVertices>;

// Both subpaths' vertices, and the light walks' beyond the first (splatted, never joined), kept
// per thread: constructing 2 x kMaxSubpathVertices vertices per sample (about 30 KB, most never
// used at the usual depths) cost more than a bounce. A walk writes each vertex before anything
// reads it, so nothing carries over between samples.
struct Subpaths {
    Vertices light, eye, moreLight;
};
Subpaths& threadSubpaths() {
    thread_local Subpaths subpaths;
    return subpaths;
}

// The light walk: x0 on a light chosen by power, then the light's ray and BSDF samples in
// importance mode, up to `maxDepth` scattering vertices. Returns how many vertices it made.
int walkFromLight(Sampler& sampler, Vertices& v, PathState& path) {
    const RenderContext& ctx = path.context;
    const ChosenLight chosen = ctx.lights.chooseEmitter(sampler.next1D());
    const Vec2 uPoint = sampler.next2D(), uDirection = sampler.next2D();
    if (chosen.light == nullptr || !(chosen.probability > 0.0f)) return 0;
    const Light& light = *chosen.light;
    const EmittedRay e = ctx.lights.emissionGuide().sample(light, uPoint, uDirection);
    if (!(e.pdfPosition > 0.0f) || !(e.pdfDirection > 0.0f) || isBlack(e.radiance)) return 0;
    v[0] = lightVertex(light, e.ray.origin, e.normal, e.pdfPosition, e.pdfPosition);
    v[0].pdfFwd = chosen.probability * e.pdfPosition;
    v[0].beta = e.radiance / (chosen.probability * e.pdfPosition);

    const LightRay leaving = leaveLight(light, e, ctx.geometry);
    Ray ray = leaving.ray;
    const float cosine = leaving.cosine;
    Rgb beta = e.radiance * (cosine / (chosen.probability * e.pdfPosition * e.pdfDirection));
    float pdf = e.pdfDirection;
    bool delta = false;
    int count = 1;
    while (count <= ctx.maxDepth) {
        const auto hit = ctx.geometry.intersect(ray);
        if (!hit) break;
        if (count == 1) {
            // The light's first segment falls off as the light says (the lecture's attenuation
            // for a point light) instead of the 1/d^2 the area density conversion assumes.
            const float d = glm::length(hit->point - v[0].point);
            beta *= light.falloff(d) * d * d;
            // Light sampling from x1 would have picked x0 by another density than emission did.
            if (!light.samplesByArea(hit->point))
                v[0].pdfPosition = lightSamplingAreaDensity(light, hit->point, v[0].point, v[0].normal);
            // An area light's ray left from an offset origin: x1's density from x0 -> x1, as the
            // other strategies' views compute it (linkThrough says why).
            if (!light.isDelta())
                pdf = ctx.lights.emissionGuide().pdfDirection(light, v[0].point, v[0].normal,
                                                              glm::normalize(hit->point - v[0].point));
        }
        BdptVertex& here = v[count];
        setSurfaceVertex(here, *hit, ray, beta, v[count - 1], pdf, delta, ctx, TransportMode::Importance);
        if (count >= 2) linkThrough(v[count - 2], v[count - 1], here);
        ++count;
        if (count > ctx.maxDepth) break;  // a vertex deeper could not be joined within maxDepth
        const float uLobe = sampler.next1D();
        const Vec2 u = sampler.next2D();
        const auto step = sampledStep(*here.surface, uLobe, u);
        if (!step) break;
        here.lobe = step->lobe;
        here.delta = step->delta;
        beta *= step->weight;
        if (!survivesRussianRoulette(beta, count - 1, sampler)) break;
        ++(here.surface->bsdf.lobe(step->lobe).transmits() ? path.counters.refraction : path.counters.reflection);
        pdf = step->pdf;
        delta = step->delta;
        ray = spawnRay(here.surface->hit, step->wi, ctx.geometry.numerics());
    }
    return count;
}

// Pushes the events of light vertices y(last) ... y1 (nearest the eye first): the light walk
// reversed. False, with nothing left pushed, when the automaton dies on the way.
bool pushLightEvents(PathState& path, const Vertices& light, int last) {
    const std::size_t before = path.size();
    for (int i = last; i >= 1; --i) {
        if (!path.push(light[i].surface->eventOf(light[i].lobe))) {
            while (path.size() > before) path.pop();
            return false;
        }
    }
    return true;
}

void popTo(PathState& path, std::size_t size) {
    while (path.size() > size) path.pop();
}

PathEvent eventOfLight(const BdptVertex& origin) {
    PathEvent event = origin.light->event();
    event.position = origin.point;
    return event;
}

// A shadow ray's answer, cast at most once per join and only when a contribution needs it.
class Visibility {
public:
    // `from`: the offset origins of the vertex the ray leaves, shared by all its joins and its
    // bounce. `toNormal`: the unit normal of the surface `to` lies on; zero for the camera and a
    // point light.
    Visibility(RayOrigins& from, const Vec3& to, const Vec3& toNormal) : from_(from), to_(to), toNormal_(toNormal) {}
    bool operator()(PathState& path) {
        if (!known_) {
            ++path.counters.shadow;
            visible_ = !path.context.geometry.occluded(spawnShadowRay(from_, to_, toNormal_));
            known_ = true;
        }
        return visible_;
    }

private:
    RayOrigins& from_;
    Vec3 to_, toNormal_;
    bool known_ = false, visible_ = false;
};

// Calls add(x, y, weight) for every pixel whose filter covers film position p, weight the filter's
// density at p (PixelFilter::density). A pixel's own samples are spread by that density (filter
// importance sampling), so a splat must be too, or light tracing and the eye's strategies would
// estimate different integrals and their MIS sum neither (pbrt-v4's RGBFilm::AddSplat weighs splats
// by the filter likewise). The box: the pixel that contains p, weight 1.
template <class Add>
void forPixelsCovering(const PixelFilter* filter, const Vec2& p, const Camera& camera, const Add& add) {
    if (filter == nullptr || filter->kind() == PixelFilterKind::Box) {
        add(std::min(static_cast<int>(p.x), camera.width() - 1), std::min(static_cast<int>(p.y), camera.height() - 1), 1.0f);
        return;
    }
    // Pixel i's centre is i + 0.5: the pixels within the filter's radius of p.
    const float r = filter->radius();
    const int x0 = std::max(0, static_cast<int>(std::ceil(p.x - 0.5f - r)));
    const int x1 = std::min(camera.width() - 1, static_cast<int>(std::floor(p.x - 0.5f + r)));
    const int y0 = std::max(0, static_cast<int>(std::ceil(p.y - 0.5f - r)));
    const int y1 = std::min(camera.height() - 1, static_cast<int>(std::floor(p.y - 0.5f + r)));
    for (int y = y0; y <= y1; ++y) {
        const float wy = filter->density(p.y - (static_cast<float>(y) + 0.5f));
        if (wy == 0.0f) continue;
        for (int x = x0; x <= x1; ++x) {
            const float w = wy * filter->density(p.x - (static_cast<float>(x) + 0.5f));
            if (w > 0.0f) add(x, y, w);
        }
    }
}

// t = 1: light vertex y_i joined to the pinhole, splatted into the pixels whose filter covers it.
void joinToCamera(const Vertices& light, int i, PathState& path, const Weights& weights, bool weighted) {
    const RenderContext& ctx = path.context;
    const BdptVertex& y = light[i];
    const ShadingPoint& sp = *y.surface;
    if (y.smoothLobes == 0 || !ctx.camera.connectible()) return;
    const auto raster = ctx.camera.project(y.point);
    if (!raster) return;
    const Vec3 toEye = ctx.camera.eye() - y.point;
    const float distance2 = glm::dot(toEye, toEye);
    const Vec3 w = toEye / std::sqrt(distance2);
    const float importance = ctx.camera.importance(-w);
    if (!(importance > 0.0f)) return;
    // We cos(theta_eye) / d^2: the pinhole's importance through the solid angle it subtends.
    const float cameraTerm = importance * glm::dot(-w, ctx.camera.forward()) / distance2;
    const PathEvent lightEvent = eventOfLight(light[0]);
    const BdptVertex eye[1] = {cameraVertex(ctx.camera.eye())};
    RayOrigins origins(sp.hit, ctx.geometry.numerics());
    Visibility visible(origins, ctx.camera.eye(), kNoSurfaceNormal);
    const std::size_t before = path.size();
    for (int lobe = 0; lobe < int(sp.bsdf.lobes().size()); ++lobe) {
        if (!y.scattersSmoothly(lobe)) continue;
        if (!path.push(sp.eventOf(lobe))) continue;
        if (pushLightEvents(path, light, i - 1) && path.wants(lightEvent)) {
            const Rgb f = sp.bsdf.eval(lobe, sp.wo, w);
            if (!isBlack(f)) {
                if (weights.pilot != nullptr) {
                    weights.pilot->countJoin(PilotTerm::Splat);
                    if (visible(path)) {
                        double shareSquares = 0.0;
                        forPixelsCovering(ctx.filter, *raster, ctx.camera, [&](int, int, float share) { shareSquares += share * share; });
                        weights.pilot->add(PilotTerm::Splat, luminance(y.beta * f) * cameraTerm,
                                           joinedDensities({light.data(), std::size_t(i + 1)}, lobe, eye, lobe, ctx), i + 1,
                                           shareSquares);
                    }
                    popTo(path, before);
                    continue;
                }
                const float weight =
                    weighted ? misWeight(joinedDensities({light.data(), std::size_t(i + 1)}, lobe, eye, lobe, ctx), i + 1,
                                         weights.lightWalks) * weights.splatScale
                             : 1.0f;
                path.setStrategy(i + 1, 1);
                if (weight > 0.0f && visible(path)) {
                    const Rgb value = y.beta * f * (cameraTerm * weight);
                    forPixelsCovering(ctx.filter, *raster, ctx.camera, [&](int x, int yPixel, float share) {
                        path.splat(x, yPixel, lightEvent, value * share);
                    });
                }
            }
        }
        popTo(path, before);
    }
}

// s = 1: light sampling at eye vertex z_t-1, through every delta light and one area light chosen
// by power, as the path tracer's next-event estimation does.
void joinToLightSample(const Vertices& eye, int t, RayOrigins& origins, const Light& light, float choice, Vec2 uPoint,
                       PathState& path, const Weights& weights) {
    const RenderContext& ctx = path.context;
    const BdptVertex& z = eye[t - 1];
    const ShadingPoint& sp = *z.surface;
    const LightSample sample = light.sample(z.point, uPoint);
    if (!(sample.distance > 0.0f) || isBlack(sample.weight)) return;
    if (!light.isDelta() && !(sample.pdf > 0.0f)) return;
    const float pdfPosition =
        light.isDelta() ? 1.0f : sample.pdf * std::fabs(glm::dot(sample.normal, sample.wi)) / (sample.distance * sample.distance);
    const float pdfEmission = light.samplesByArea(z.point) ? pdfPosition : light.pdfEmissionPosition();
    BdptVertex y[1] = {lightVertex(light, sample.point, sample.normal, pdfPosition, pdfEmission)};
    y[0].pdfFwd = choice * pdfPosition;
    const PathEvent lightEvent = eventOfLight(y[0]);
    Visibility visible(origins, sample.point, sample.normal);
    for (int lobe = 0; lobe < int(sp.bsdf.lobes().size()); ++lobe) {
        if (!z.scattersSmoothly(lobe) || !path.wants(sp.eventOf(lobe), lightEvent)) continue;
        const Rgb f = sp.bsdf.eval(lobe, sp.wo, sample.wi);
        if (isBlack(f)) continue;
        if (weights.pilot != nullptr) {
            weights.pilot->countJoin(PilotTerm::Eye);
            if (visible(path))
                weights.pilot->add(PilotTerm::Eye, luminance(z.beta * f * sample.weight) / choice,
                                   joinedDensities(y, lobe, {eye.data(), std::size_t(t)}, lobe, ctx), 1);
            continue;
        }
        const float weight = misWeight(joinedDensities(y, lobe, {eye.data(), std::size_t(t)}, lobe, ctx), 1, weights.lightWalks);
        path.setStrategy(1, t);
        if (weight > 0.0f && visible(path)) path.emit(sp.eventOf(lobe), lightEvent, z.beta * f * sample.weight * (weight / choice));
    }
}

// s, t >= 2: light vertex y_s-1 joined to eye vertex z_t-1, one contribution per pair of their
// smooth lobes (each pair is a different path: E..D D..L and E..G D..L land in different AOVs).
void joinVertices(const Vertices& light, int s, const Vertices& eye, int t, RayOrigins& origins, PathState& path,
                  const Weights& weights) {
    const RenderContext& ctx = path.context;
    const BdptVertex& y = light[s - 1];
    const BdptVertex& z = eye[t - 1];
    const ShadingPoint& ly = *y.surface;
    const ShadingPoint& ez = *z.surface;
    if (y.smoothLobes == 0) return;
    const Vec3 d = y.point - z.point;
    const float distance2 = glm::dot(d, d);
    if (!(distance2 > 0.0f)) return;
    const Vec3 w = d / std::sqrt(distance2);  // from z to y
    const PathEvent lightEvent = eventOfLight(light[0]);
    Visibility visible(origins, y.point, y.normal);
    const std::size_t before = path.size();
    for (int eyeLobe = 0; eyeLobe < int(ez.bsdf.lobes().size()); ++eyeLobe) {
        if (!z.scattersSmoothly(eyeLobe)) continue;
        const Rgb fz = ez.bsdf.eval(eyeLobe, ez.wo, w);
        if (isBlack(fz) || !path.push(ez.eventOf(eyeLobe))) continue;
        const std::size_t withEye = path.size();
        for (int lightLobe = 0; lightLobe < int(ly.bsdf.lobes().size()); ++lightLobe) {
            if (!y.scattersSmoothly(lightLobe) || !path.push(ly.eventOf(lightLobe))) continue;
            if (pushLightEvents(path, light, s - 2) && path.wants(lightEvent)) {
                const Rgb fy = ly.bsdf.eval(lightLobe, ly.wo, -w);
                if (!isBlack(fy) && weights.pilot != nullptr) {
                    weights.pilot->countJoin(PilotTerm::Join);
                    if (visible(path))
                        weights.pilot->add(PilotTerm::Join, luminance(z.beta * fz * fy * y.beta) / distance2,
                                           joinedDensities({light.data(), std::size_t(s)}, lightLobe,
                                                           {eye.data(), std::size_t(t)}, eyeLobe, ctx),
                                           s);
                } else if (!isBlack(fy)) {
                    const float weight = misWeight(joinedDensities({light.data(), std::size_t(s)}, lightLobe,
                                                                   {eye.data(), std::size_t(t)}, eyeLobe, ctx),
                                                   s, weights.lightWalks) *
                                         weights.joinScale;
                    path.setStrategy(s, t);
                    if (weight > 0.0f && visible(path))
                        path.emit(lightEvent, z.beta * fz * fy * y.beta * (weight / distance2));
                }
            }
            popTo(path, withEye);
        }
        popTo(path, before);
    }
}

// One camera sample's strategies: `lightWalks` light walks, each splatted, the first also joined
// to the eye's walk, then the eye's.
void traceStrategies(const Ray& cameraRay, PathState& path, int lightWalks, BdptIntegrator::Strategies strategies,
                     const Weights& weights) {
    const RenderContext& ctx = path.context;
    Sampler& sampler = *path.sampler;
    const std::uint64_t raysBefore = path.counters.total();
    std::uint64_t lightWalkRays = 0, joinRays = 0;  // the pilot's: rays cast for the light walk's strategies

    Subpaths& subpaths = threadSubpaths();
    Vertices& light = subpaths.light;
    int lightCount = 0;
    const bool weighted = strategies == BdptIntegrator::Strategies::All;
    for (int walk = 0; walk < lightWalks; ++walk) {
        // The first walk draws the numbers it drew before there were more (its key alone).
        Sampler lightSampler = sampler.forVertex(kLightWalkKey + std::uint64_t(walk));
        Vertices& vertices = walk == 0 ? light : subpaths.moreLight;
        const int count = walkFromLight(lightSampler, vertices, path);
        for (int i = 1; i < count; ++i) joinToCamera(vertices, i, path, weights, weighted);
        if (walk == 0) lightCount = count;
    }
    lightWalkRays = path.counters.total() - raysBefore;
    if (strategies == BdptIntegrator::Strategies::LightTracingOnly) return;

    Vertices& eye = subpaths.eye;
    // An orthographic camera's ray is a Dirac in direction: its first step counts as a delta's.
    const bool orthographic = !ctx.camera.connectible();
    eye[0] = cameraVertex(cameraRay.origin, orthographic);
    const std::size_t pathStart = path.size();
    Ray ray = cameraRay;
    Rgb beta{1.0f};
    float pdf = orthographic ? 1.0f : ctx.camera.pdfDirection(cameraRay.direction);
    bool delta = orthographic;
    for (int t = 2; t <= ctx.maxDepth + 2; ++t) {
        const auto hit = ctx.geometry.intersect(ray);
        if (!hit) {
            path.setStrategy(0, t);
            const Rgb before = weights.pilotBeauty != nullptr ? *weights.pilotBeauty : Rgb{0.0f};
            addBackground(ray, beta, path);  // s = 0 only: nothing else samples the background
            if (weights.pilot != nullptr) weights.pilot->addUnweighted(luminance(*weights.pilotBeauty - before));
            break;
        }
        BdptVertex& z = eye[t - 1];
        setSurfaceVertex(z, *hit, ray, beta, eye[t - 2], pdf, delta, ctx, TransportMode::Radiance);
        if (t >= 3) linkThrough(eye[t - 3], eye[t - 2], z);

        // s = 0: an emitter found by the eye's walk.
        if (const Light* emitter = ctx.lights.lightOfObject(hit->object)) {
            PathEvent event = emitter->event();
            event.position = hit->point;
            if (path.wants(event) && !isBlack(emitter->radiance(*hit, -ray.direction))) {
                markEmitter(z, *emitter, eye[t - 2]);
                const PathDensities densities = joinedDensities({}, 0, {eye.data(), std::size_t(t)}, 0, ctx);
                z.light = nullptr;
                path.setStrategy(0, t);
                if (weights.pilot != nullptr) {
                    // The emission before its weight, as the pilot's sink adds it.
                    const Rgb before = *weights.pilotBeauty;
                    addEmission(*hit, ray, beta, 1.0f, path);
                    weights.pilot->add(PilotTerm::Eye, luminance(*weights.pilotBeauty - before), densities, 0);
                } else {
                    addEmission(*hit, ray, beta, misWeight(densities, 0, weights.lightWalks), path);
                }
            }
        }
        // Joins at z scatter once more; the path may have at most maxDepth scattering events.
        if (t - 1 > ctx.maxDepth) break;
        const ShadingPoint& sp = *z.surface;
        // One set of offset origins for z's shadow rays and its bounce (as the path tracer's).
        RayOrigins origins(sp.hit, ctx.geometry.numerics());
        if (z.smoothLobes != 0) {
            const LightChoiceSample u = drawLightChoice(sampler, ctx.lights);
            for (const Light* l : ctx.lights.deltaLights())
                joinToLightSample(eye, t, origins, *l, 1.0f, u.uPoint, path, weights);
            const ChosenLight chosen = ctx.lights.chooseAreaLight(u.uChoice);
            if (chosen.light != nullptr)
                joinToLightSample(eye, t, origins, *chosen.light, chosen.probability, u.uPoint, path, weights);
            const int longestLight = std::min(lightCount, ctx.maxDepth + 2 - t);
            const std::uint64_t shadowBefore = path.counters.shadow;
            for (int s = 2; s <= longestLight; ++s) joinVertices(light, s, eye, t, origins, path, weights);
            joinRays += path.counters.shadow - shadowBefore;
        }

        const float uLobe = sampler.next1D();
        const Vec2 u = sampler.next2D();
        const auto step = sampledStep(sp, uLobe, u);
        if (!step) break;
        const bool transmitted = sp.bsdf.lobe(step->lobe).transmits();
        if (!path.push(sp.eventOf(step->lobe))) {
            ++(transmitted ? path.counters.refractionDead : path.counters.reflectionDead);
            break;
        }
        z.lobe = step->lobe;
        z.delta = step->delta;
        beta *= step->weight;
        if (!survivesRussianRoulette(beta, t - 1, sampler)) break;
        ++(transmitted ? path.counters.refraction : path.counters.reflection);
        pdf = step->pdf;
        delta = step->delta;
        ray = spawnRay(origins, step->wi);
    }
    popTo(path, pathStart);
    if (weights.pilot != nullptr) {
        // + 1 each: the ray leaving the light and the camera ray, which the counters leave out.
        weights.pilot->lightWalkWork += double(lightWalkRays) + double(lightWalks);
        weights.pilot->joinWork += double(joinRays);
        weights.pilot->eyeWork += double(path.counters.total() - raysBefore - lightWalkRays - joinRays) + 1.0;
    }
}

// The pilot's camera samples: this many per pixel (at least 2, for each pixel's variance; more
// pixels rather than more samples, so that the lamp's edges, which dominate the Cornell box's
// noise, are among them), on a lattice of pixels over the image, about 1/128 of the render's
// samples within bounds (callgrind: 256 samples of the Cornell box, 20.7 M instructions, 3% of a
// 32 x 32 render at 32 spp).
constexpr int kPilotSamplesPerPixel = 2;
constexpr int kPilotMinSamples = 256, kPilotMaxSamples = 4096;
constexpr std::uint64_t kPilotKey = 0x70696c6f74ull;  // "pilot"
// Light walks per pilot sample for light tracing's splats, beside its own: a caustic reached by one
// light walk in hundreds (the glass ball's) is then seen by the pilot.
constexpr int kPilotExtraLightWalks = 2;

// Traces the pilot (one thread, independent numbers from the render's seed: the same choice on
// any number of threads) and tallies every strategy at every candidate fraction.
LightWalkPilot runPilot(const RenderContext& ctx, BdptIntegrator::Strategies strategies) {
    const int width = ctx.camera.width(), height = ctx.camera.height();
    const std::int64_t renderSamples = std::int64_t(width) * height * ctx.samplesPerPixel;
    const int samples = static_cast<int>(std::clamp<std::int64_t>(renderSamples / 128, kPilotMinSamples, kPilotMaxSamples));
    const int pixels = samples / kPilotSamplesPerPixel;
    const int columns = std::clamp(static_cast<int>(std::lround(std::sqrt(double(pixels) * width / height))), 1, width);
    const int rows = std::clamp(pixels / columns, 1, height);
    std::vector<Rgb> layers(lpe::kMaxOutputs + 2, Rgb{0.0f});
    ContributionSink sink(layers);
    RayCounters counters;
    // Every path, whatever the request: the fraction chosen, and so every output's image, must not
    // depend on which outputs are written (an AOV alone is the same AOV of the full render).
    RenderContext everyPath = ctx;
    everyPath.keepAllPaths = true;
    PathState path(everyPath, sink, counters);
    LightWalkPilot pilot(kPilotSamplesPerPixel);
    const std::uint64_t seed = mixBits(ctx.seed ^ kPilotKey);
    for (int row = 0; row < rows; ++row) {
        for (int column = 0; column < columns; ++column) {
            const int x = (2 * column + 1) * width / (2 * columns), y = (2 * row + 1) * height / (2 * rows);
            for (int k = 0; k < kPilotSamplesPerPixel; ++k) {
                Sampler sampler = Sampler::forPixel(SamplerKind::Independent, x, y, k, kPilotSamplesPerPixel, seed);
                path.sampler = &sampler;
                path.sampleIndex = k;
                const Vec2 u = sampler.next2D();
                const Vec2 offset = Vec2{0.5f} + (ctx.filter != nullptr ? ctx.filter->sample(u) : u - Vec2{0.5f});
                PilotSample sample;
                const Ray ray = ctx.camera.generateRay(float(x) + offset.x, float(y) + offset.y);
                if (path.push({lpe::EventType::Camera, lpe::Scatter::None, Subject::None, 0, ray.origin})) {
                    traceStrategies(ray, path, 1, strategies, {1.0, 1.0f, 1.0f, &sample, &layers[0]});
                    // Light tracing's splats need no eye walk: more light walks, their splats'
                    // second moment averaged with the sample's own (their work is not the render's).
                    PilotSample more;
                    const Weights moreWeights{1.0, 1.0f, 1.0f, &more, &layers[0]};
                    Vertices& light = threadSubpaths().light;
                    for (int m = 1; m <= kPilotExtraLightWalks; ++m) {
                        Sampler lightSampler = sampler.forVertex(kLightWalkKey + std::uint64_t(m));
                        const int count = walkFromLight(lightSampler, light, path);
                        for (int i = 1; i < count; ++i) joinToCamera(light, i, path, moreWeights, true);
                    }
                    for (std::size_t f = 0; f < kLightWalkFractions.size(); ++f)
                        sample.splatSquares[f] = (sample.splatSquares[f] + more.splatSquares[f]) / (1 + kPilotExtraLightWalks);
                    path.pop();
                }
                pilot.add(sample);
            }
        }
    }
    return pilot;
}

}  // namespace

void BdptIntegrator::preprocess(const RenderContext& ctx) {
    lightWalks_ = true;
    if (ctx.keepAllPaths) return chooseLightWalkFraction(ctx);
    // Does any requested output accept E, one or more scattering events, then a light? Search the
    // automaton over this scene's own events (every object through every lobe, every light).
    std::vector<PathEvent> scattering, lights;
    for (std::uint32_t object = 0; object < ctx.scene.objects.size(); ++object) {
        for (const LobeInfo& lobe : ctx.scene.materials[ctx.scene.objects[object].material]->lobes())
            scattering.push_back({lobe.event.type, lobe.event.scatter, Subject::Object, object});
    }
    for (const auto& light : ctx.lights.all()) lights.push_back(light->event());
    const lpe::Automaton& automaton = ctx.automaton;
    std::vector<bool> seen(automaton.stateCount(), false);
    const lpe::Automaton::State afterEye =
        automaton.step(automaton.start(), ctx.symbols({lpe::EventType::Camera, lpe::Scatter::None, Subject::None, 0}));
    std::vector<lpe::Automaton::State> frontier;
    for (const PathEvent& e : scattering) {
        const auto next = automaton.step(afterEye, ctx.symbols(e));
        if (!seen[next]) seen[next] = true, frontier.push_back(next);
    }
    bool useful = false;
    while (!frontier.empty() && !useful) {
        const auto state = frontier.back();
        frontier.pop_back();
        for (const PathEvent& light : lights)
            useful = useful || (automaton.accepts(automaton.step(state, ctx.symbols(light))) & ctx.requested) != 0;
        for (const PathEvent& e : scattering) {
            const auto next = automaton.step(state, ctx.symbols(e));
            if (!seen[next]) seen[next] = true, frontier.push_back(next);
        }
    }
    lightWalks_ = useful;
    chooseLightWalkFraction(ctx);
}

void BdptIntegrator::chooseLightWalkFraction(const RenderContext& ctx) {
    const auto started = std::chrono::steady_clock::now();
    stats_ = {};
    fraction_ = 1.0;
    if (!lightWalks_) {
        stats_.lightWalkFraction = 0.0;
        stats_.reason = "none: no requested output accepts a path that scatters before its light";
        return;
    }
    if (strategies_ != Strategies::All) {
        stats_.reason = "light tracing alone";
        return;
    }
    if (ctx.parameters != nullptr && ctx.parameters->has("light-walk-fraction")) {
        fraction_ = ctx.parameters->number("light-walk-fraction");
        stats_.reason = "given (--light-walk-fraction)";
        // Walks beyond one per camera sample only splat (t = 1), which no join reaches under an
        // orthographic camera: they would cost and add nothing.
        if (fraction_ > 1.0 && !ctx.camera.connectible()) {
            fraction_ = 1.0;
            stats_.reason = "given above 1, 1 used: the walks beyond only splat, which an orthographic camera cannot take";
        }
        stats_.lightWalkFraction = fraction_;
        return;
    }
    const LightWalkPilot pilot = runPilot(ctx, strategies_);
    const std::size_t best = pilot.choice();
    fraction_ = kLightWalkFractions[best];
    stats_.lightWalkFraction = fraction_;
    stats_.pilotSamples = pilot.samples();
    for (std::size_t k = 0; k < kLightWalkFractions.size(); ++k) {
        const LightWalkPilot::Estimate e = pilot.estimate(k);
        stats_.candidates.push_back({kLightWalkFractions[k], e.variance, e.work, pilot.differenceError(k)});
    }
    stats_.reason = best == pilot.best() ? "least variance x work in a pilot"
                                         : "the fewest within one standard error of the least variance x work in a pilot";
    stats_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
}

void BdptIntegrator::traceCameraRay(const Ray& cameraRay, PathState& path) const {
    // floor(q) light walks, and one more for a fraction q - floor(q) of the camera samples, chosen
    // by their own dimension.
    int walks = 0;
    if (lightWalks_) {
        const double whole = std::floor(fraction_);
        walks = static_cast<int>(whole);
        if (fraction_ > whole && path.sampler->forVertex(kLightWalkChoiceKey).next1D() < fraction_ - whole) ++walks;
    }
    traceStrategies(cameraRay, path, walks, strategies_,
                    {lightWalks_ ? fraction_ : 0.0, static_cast<float>(1.0 / fraction_),
                     static_cast<float>(1.0 / std::min(fraction_, 1.0)), nullptr, nullptr});
}

}  // namespace lightpath

// Every bounce, from the eye and from the lights.
// Under point lights a light walk's vertex is joined to the eye, to an eye vertex or to the light by a
// shadow ray, from a diffuse or glossy vertex on each side: never E S+ (D|G) S+ L.
LIGHTPATH_REGISTER_INTEGRATOR(lightpath::underPointLights(lightpath::integratorRow(
    "bdpt", "bidirectional path tracing: also light from the light's side, caustics under point lights",
    "E.*[<L.[^'ambient']>OB]",
    "bidirectional path tracing follows every bounce, from the eye and from the lights, but adds no ambient term (ka Ia)",
    [] { return std::unique_ptr<lightpath::Integrator>(std::make_unique<lightpath::BdptIntegrator>()); },
    lightpath::ShadowRays::Always, 5,
    {{.name = "light-walk-fraction", .type = lightpath::ParameterType::Number, .range = {0.0, 16.0, true, false},
      .doc = "light walks per camera sample: below 1 the fraction of camera samples that also walk from a light, "
             "above 1 more walks, splatted only (default: chosen per scene by a pilot; --stats prints it)"}}), "E.*(D|G)L|E(D|G).*L|E.*(D|G)(D|G).*L"))
