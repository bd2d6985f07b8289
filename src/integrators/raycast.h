#pragma once
#include "integrators/integrator.h"

namespace lightpath {

// Ray casting (Appel 1968; the lecture's "stop at the first intersection"): Szymczak's
// illumination formula at the first visible surface, with shadow rays, plus the ambient term.
// Produces E(D|G)L, E D <L'ambient'> and the emitters and background seen directly.
class RaycastIntegrator final : public Integrator {
public:
    void traceCameraRay(const Ray& ray, PathState& path) const override;
};

}  // namespace lightpath
