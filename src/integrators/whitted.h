#pragma once
#include "integrators/integrator.h"

namespace lightpath {

// Whitted ray tracing (Whitted 1980): ray casting plus recursive mirror rays weighted by kr and
// refracted rays weighted by kt, up to maxDepth bounces: I = local + kr I_reflected + kt I_refracted.
// Produces E S* (D|G) L, E S* L (background through mirrors and glass) and EL.
class WhittedIntegrator final : public Integrator {
public:
    void traceCameraRay(const Ray& ray, lpe::Automaton::State state, Tracer& tracer) const override;

private:
    void trace(const Ray& ray, lpe::Automaton::State state, const Rgb& throughput, int depth,
               Tracer& tracer) const;
    void traceSpecular(const Ray& ray, const PathEvent& event, lpe::Automaton::Symbol symbol,
                       lpe::Automaton::State state, const Rgb& throughput, int depth, Tracer& tracer) const;
};

}  // namespace lightpath
