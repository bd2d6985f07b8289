#pragma once
// Light that reaches a shading point straight from the lights, shared by every integrator: Szymczak's
// sum over point lights (each with one shadow ray) plus one sampled point on an area light, through
// each smooth lobe of the BSDF. For ray casting this is the illumination formula itself; the path
// tracer calls it as next-event estimation and weighs it against BSDF sampling (MIS, Veach 1997 ch. 9).
#include "integrators/path_state.h"
#include "integrators/shading_point.h"
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

void addDirectLight(const ShadingPoint& point, const Rgb& throughput, const LightChoiceSample& u,
                    DirectLightWeighting weighting, PathState& path);

// The ambient term ka Ia, the one fake of the classic methods (an `<L'ambient'>` event after D).
void addAmbient(const ShadingPoint& point, const Rgb& throughput, PathState& path);

// Ray casting's local illumination at a hit: ambient plus direct light, with random numbers keyed
// by the path so that skipping a branch never changes another branch's samples.
void addLocalIllumination(const ShadingPoint& point, const Rgb& throughput, PathState& path);

// Light an emitter sends back along `ray`, which hit it at `hit`, weighted by `weight`.
void addEmission(const SurfaceHit& hit, const Ray& ray, const Rgb& throughput, float weight, PathState& path);

// The background, for a ray that escaped (a `B` event).
void addBackground(const Ray& ray, const Rgb& throughput, PathState& path);

// Veach's power heuristic (beta = 2) for a sample of density `pdf` against one of `otherPdf`.
float powerHeuristic(float pdf, float otherPdf);

}  // namespace lightpath
