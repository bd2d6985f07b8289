#pragma once
#include "integrators/integrator.h"

namespace lightpath {

// Ray casting (Appel 1968; the lecture's "stop at the first intersection"): the illumination
// formula at the first visible surface, with shadow rays. Produces E(D|G)L and EL (background).
class RaycastIntegrator final : public Integrator {
public:
    void traceCameraRay(const Ray& ray, lpe::Automaton::State state, Tracer& tracer) const override;
};

// Shared by the integrators: the background seen along an escaped ray, a `B` event.
void addBackground(lpe::Automaton::State state, const Rgb& throughput, Tracer& tracer);
// An emissive surface seen along a ray: an `L` event labelled with the surface's object.
void addSurfaceEmission(const SurfaceHit& hit, const Vec3& towardViewer, lpe::Automaton::State state,
                        const Rgb& throughput, Tracer& tracer);

}  // namespace lightpath
