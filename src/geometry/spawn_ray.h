#pragma once
// The one place where secondary rays (shadow, reflection, refraction) are born, so every ray
// leaves its surface by the same numerical method (NumericsOptions::offset).
#include <optional>

#include "geometry/numerics.h"
#include "geometry/surface_hit.h"
#include "math/ray.h"

namespace lightpath {

// Where rays leaving one surface hit start: a point on each side of the surface, each computed
// on first use and then shared, so a shading point's shadow rays (one per light) pay for the
// robust offset once per side, not once per ray.
class RayOrigins {
public:
    RayOrigins(const SurfaceHit& hit, const NumericsOptions& numerics);

    // A ray (origin, tMin, ignored primitive; no direction) leaving on the side `direction` points to.
    Ray leave(const Vec3& direction);
    const SurfaceHit& hit() const { return hit_; }
    const NumericsOptions& numerics() const { return numerics_; }

private:
    const SurfaceHit& hit_;
    const NumericsOptions& numerics_;
    bool normalUsable_;  // a zero or non-finite normal names no side: each ray then leaves along itself
    std::optional<Vec3> origins_[2];  // [0] on the normal's side, [1] on the other
};

// A ray leaving `hit` in unit `direction`; it leaves on the side of the surface `direction` points to.
Ray spawnRay(const SurfaceHit& hit, const Vec3& direction, const NumericsOptions& numerics);
// The same from origins the hit's shadow rays already used: a bounce on the side they left from
// reuses their offset origin instead of computing it again (the path tracer's next-event
// estimation and its sampled bounce; docs/performance.md, Shading share, sixth pass).
Ray spawnRay(RayOrigins& origins, const Vec3& direction);

// The `targetNormal` of a target on no surface: a point light, the camera.
inline const Vec3 kNoSurfaceNormal{0.0f};

// The segment from `hit` towards `target`, stopping just short of it so a light placed on a
// surface does not shadow itself. When `target` lies on a surface (an area light's sample, a bdpt
// vertex), `targetNormal` is that surface's unit normal and the segment also ends off that surface
// by its rounding error; kNoSurfaceNormal means no surface.
Ray spawnShadowRay(const SurfaceHit& hit, const Vec3& target, const Vec3& targetNormal,
                   const NumericsOptions& numerics);
// The same from origins shared by several shadow rays of one hit.
Ray spawnShadowRay(RayOrigins& origins, const Vec3& target, const Vec3& targetNormal);
// The segment from a point inside a medium, on no surface (so with no offset at its start).
Ray spawnShadowRay(const Vec3& origin, const Vec3& target, const Vec3& targetNormal,
                   const NumericsOptions& numerics);

}  // namespace lightpath
