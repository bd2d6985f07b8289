#pragma once
// Light that reaches a shading point straight from the lights, shared by every integrator: Szymczak's
// sum over point lights (each with one shadow ray) plus one sampled point on an area light, through
// each smooth lobe of the BSDF. For ray casting this is the illumination formula itself; the path
// tracer calls it as next-event estimation and weighs it against BSDF sampling (MIS, Veach 1997 ch. 9).
#include "geometry/spawn_ray.h"
#include "integrators/path_state.h"
#include "media/medium.h"
#include "integrators/shading_point.h"
#include "lights/light_set.h"
#include "math/ray.h"

namespace lightpath {

enum class DirectLightWeighting : std::uint8_t {
    Alone,               // the only technique that finds light from lights (raycast, Whitted)
    MultipleImportance,  // BSDF sampling can also hit area lights: the power heuristic (path)
};

// The random numbers of one area-light sample: which light, and where on it.
struct LightChoiceSample {
    float uChoice;
    Vec2 uPoint;
};

// The numbers of one next-event estimate, drawn from `sampler` in a fixed order (the choice of an
// area light, then the point on it), each only when something reads it: the choice when there are
// two or more area lights, the point when there is any (delta lights read neither). A number no
// one reads is skipped, not drawn, so the sampler's later numbers are the same either way
// (docs/performance.md, Shading share, ninth pass).
inline LightChoiceSample drawLightChoice(Sampler& sampler, const LightSet& lights) {
    LightChoiceSample u{0.0f, Vec2{0.0f}};
    if (lights.choosesAmongAreaLights()) u.uChoice = sampler.next1D();
    else sampler.skip1D();
    if (lights.hasAreaLights()) u.uPoint = sampler.next2D();
    else sampler.skip2D();
    return u;
}

// `medium`: what fills the space on the shading point's side (wo's), which attenuates every shadow
// ray by its transmittance; null in vacuum.
void addDirectLight(const ShadingPoint& point, const Rgb& throughput, const LightChoiceSample& u,
                    DirectLightWeighting weighting, PathState& path, const Medium* medium = nullptr);
// The same with the shadow rays leaving from `origins` (point.hit's), which the caller keeps to
// spawn its next ray from: the offset origin on a side is computed once per hit.
void addDirectLight(const ShadingPoint& point, RayOrigins& origins, const Rgb& throughput, const LightChoiceSample& u,
                    DirectLightWeighting weighting, PathState& path, const Medium* medium = nullptr);

// A scattering inside a medium (the event <V'NAME'>): where, the direction back along the path,
// and the medium (Scene::media[index]).
struct MediumPoint {
    Vec3 point;
    Vec3 wo;  // unit, towards the previous vertex
    const Medium& medium;
    std::uint32_t index;

    // Volume scattering has no surface scattering type: Scatter::None keeps D, G and S (and so the
    // `classes` AOVs) to surface events; `V`, `<V>` and `<V.'NAME'>` match it.
    PathEvent event() const { return {lpe::EventType::Volume, lpe::Scatter::None, Subject::Medium, index, point}; }
};

// Light that reaches a medium point straight from the lights and scatters towards wo by the phase
// function: the lights' terms of the volume rendering equation, each shadow ray attenuated by the
// medium's transmittance (pbrt-v4 14.2.2, SampleLd). `throughput` carries sigma_s and the free
// flight's weight.
void addMediumDirectLight(const MediumPoint& point, const Rgb& throughput, const LightChoiceSample& u,
                          DirectLightWeighting weighting, PathState& path);

// The ambient term ka Ia, the one fake of the classic methods (an `<L'ambient'>` event after D).
void addAmbient(const ShadingPoint& point, const Rgb& throughput, PathState& path);

// Ray casting's local illumination at a hit: ambient plus direct light, with random numbers keyed
// by the path so that skipping a branch never changes another branch's samples. `medium`: what
// fills the space on the viewer's side (shadow rays through it are attenuated); null in vacuum.
void addLocalIllumination(const ShadingPoint& point, const Rgb& throughput, PathState& path,
                          const Medium* medium = nullptr);

// The lecture's single scattering along a ray segment [0, tMax) inside `medium` (Scene::media[index]):
// light from the point lights scattered once towards the ray's origin, each term the path
// E ... V <L.>, with shadows in the fog. The integral over t is estimated by kSingleScatteringSteps
// stratified free flights (one jitter per ray, keyed by the path), so it is unbiased and smooth.
void addSingleScattering(const Ray& ray, float tMax, const Medium& medium, std::uint32_t index, const Rgb& throughput,
                         PathState& path);
// What the classic methods do along a ray in medium `mediumIndex` (kNoMedium: vacuum) up to its
// first hit (none: to infinity): add its single scattering, and return the throughput every term
// beyond is seen with, attenuated by the medium's transmittance.
Rgb throughMedium(const std::optional<SurfaceHit>& hit, const Ray& ray, std::uint32_t mediumIndex,
                  const Rgb& throughput, PathState& path);

// Index-matched boundaries (`interface` materials, pbrt-v4): a ray crosses them without an event,
// into the medium beyond. Crossings per ray are bounded so a degenerate mesh cannot loop forever.
inline constexpr int kMaxInterfaceCrossings = 64;

// The first hit that is not an interface, the ray segment that reaches it and its medium, and the
// throughput the segments before it leave (the classic methods' single scattering added along them).
struct BeyondInterfaces {
    std::optional<SurfaceHit> hit;
    Ray ray;
    std::uint32_t medium;
    Rgb throughput;
};
BeyondInterfaces crossInterfaces(std::optional<SurfaceHit> hit, Ray ray, std::uint32_t mediumIndex,
                                 Rgb throughput, PathState& path);

// A shadow ray's transmittance from its origin (in medium `mediumIndex`) to `target` (on a surface
// of unit normal `targetNormal`, or zero), through interfaces and the media between them; black
// when a scattering surface blocks it.
Rgb shadowTransmittance(Ray ray, const Vec3& target, const Vec3& targetNormal, std::uint32_t mediumIndex,
                        const RenderContext& ctx);

// The medium the camera is in: the interior of the closed object around the eye, else the world's.
// Found by the first closed boundary a ray from the eye meets (media do not nest): leaving it
// through its back face means the eye is inside. Costs nothing in a scene without media.
std::uint32_t cameraMedium(const RenderContext& ctx);

// Light an emitter sends back along `ray`, which hit it at `hit`, weighted by `weight`.
void addEmission(const SurfaceHit& hit, const Ray& ray, const Rgb& throughput, float weight, PathState& path);

// The background, for a ray that escaped (a `B` event).
void addBackground(const Ray& ray, const Rgb& throughput, PathState& path);

// Veach's power heuristic (beta = 2) for a sample of density `pdf` against one of `otherPdf`.
float powerHeuristic(float pdf, float otherPdf);

}  // namespace lightpath
