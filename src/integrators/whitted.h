#pragma once
#include "integrators/integrator.h"

namespace lightpath {

// Whitted ray tracing (Whitted 1980): ray casting plus recursive mirror rays weighted by kr and
// refracted rays weighted by kt (Fresnel's split where the material asks for it), every branch
// traced: I = local + kr I_reflected + kt I_refracted. Produces E S* (D|G) L and E S* L.
class WhittedIntegrator final : public Integrator {
public:
    void traceCameraRay(const Ray& ray, PathState& path) const override;

private:
    // `depth`: scattering events on the path so far.
    // `mediumIndex`: the medium the ray travels in (Scene::media), kNoMedium in vacuum.
    void trace(const Ray& ray, const Rgb& throughput, int depth, std::uint32_t mediumIndex, PathState& path) const;
};

}  // namespace lightpath
