#pragma once
#include <optional>

#include "integrators/integrator.h"

namespace lightpath {

// Ray casting (Appel 1968; the lecture's "stop at the first intersection"): Szymczak's
// illumination formula at the first visible surface, with shadow rays, plus the ambient term.
// Produces E(D|G)L, E D <L'ambient'> and the emitters and background seen directly.
class RaycastIntegrator final : public Integrator {
public:
    void traceCameraRay(const Ray& ray, PathState& path) const override;
};

// What ray casting adds for a camera ray whose first visible surface is `hit` (none: the ray
// escapes): the emitter or background seen, and the local illumination there. The one shading of
// the first hit, whichever visibility method found it (ray casting or the rasteriser, raster.h),
// seen through the world's medium, whose single scattering it adds (E V L).
void shadeFirstHit(const std::optional<SurfaceHit>& hit, const Ray& ray, PathState& path);

}  // namespace lightpath
