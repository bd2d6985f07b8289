#pragma once
// The one place where secondary rays (shadow, reflection, refraction) are born, so every ray
// leaves its surface by the same numerical method (NumericsOptions::offset).
#include "geometry/numerics.h"
#include "geometry/surface_hit.h"
#include "math/ray.h"

namespace lightpath {

// A ray leaving `hit` in unit `direction`; it leaves on the side of the surface `direction` points to.
Ray spawnRay(const SurfaceHit& hit, const Vec3& direction, const NumericsOptions& numerics);

// The segment from `hit` towards a point light at `target`, stopping just short of it so a light
// placed on a surface does not shadow itself.
Ray spawnShadowRay(const SurfaceHit& hit, const Vec3& target, const NumericsOptions& numerics);

}  // namespace lightpath
