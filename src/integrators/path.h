#pragma once
#include "integrators/integrator.h"

namespace lightpath {

// Unidirectional path tracing (Kajiya 1986) of the shared material reading (materials/bsdf.h),
// with next-event estimation at every diffuse or glossy vertex, multiple importance sampling of
// area lights by the power heuristic (Veach and Guibas 1995) and Russian roulette. Every
// contribution, from a light sampled by NEE or an emitter hit by a sampled direction, ends its
// path with the same events, so both MIS-weighted halves of one light path land in the same AOVs.
// Produces E (D|G|S)* L: `indirect` is its share beyond Whitted.
class PathIntegrator final : public Integrator {
public:
    void traceCameraRay(const Ray& ray, PathState& path) const override;
};

}  // namespace lightpath
