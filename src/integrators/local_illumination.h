#pragma once
#include "geometry/surface_hit.h"
#include "integrators/integrator.h"

namespace lightpath {

// Szymczak's illumination formula at a visible point, one contribution per term so each lands in
// the AOVs its light path selects:
//   ambient   ka Ia                                  E ... D <L'ambient'>
//   diffuse   I_l / (c0 + c1 d + c2 d^2) kd (N.L_l)   E ... D L
//   highlight I_l / (c0 + c1 d + c2 d^2) ks (H.N)^n   E ... G L
// `normal` faces the incoming ray; `throughput` is the product of kr/kt weights so far.
void addLocalIllumination(const SurfaceHit& hit, const Vec3& normal, const Vec3& towardViewer,
                          lpe::Automaton::State state, const Rgb& throughput, Tracer& tracer);

}  // namespace lightpath
