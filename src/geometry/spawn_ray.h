#pragma once
// The one place where secondary rays (shadow, reflection, refraction) are born, so every ray
// leaves its surface by the same numerical method (NumericsOptions::offset).
#include <algorithm>
#include <cmath>

#include "geometry/numerics.h"
#include "geometry/ray_offset.h"
#include "geometry/surface_hit.h"
#include "math/ray.h"

namespace lightpath {

// Where rays leaving one surface hit start: a point on each side of the surface, each computed
// on first use and then shared, so a shading point's shadow rays (one per light) pay for the
// robust offset once per side, not once per ray. `leave` is inline for the shadow rays after a
// side's first: a side test and a copy of the stored origin, no call (docs/performance.md,
// Shading share, eighth pass).
class RayOrigins {
public:
    RayOrigins(const SurfaceHit& hit, const NumericsOptions& numerics) : hit_(hit), numerics_(numerics) {}

    // A ray (origin, tMin, ignored primitive; no direction) leaving on the side `direction` points to.
    Ray leave(const Vec3& direction) {
        if (numerics_.offset != RayOffset::Robust && numerics_.offset != RayOffset::WachterBinder)
            return leaveWithoutOffset();
        const int side = glm::dot(direction, hit_.normal) >= 0.0f ? 0 : 1;  // [0] on the normal's side
        Ray ray;
        ray.origin = made_ >> side & 1u ? origins_[side] : firstOrigin(side, direction);
        return ray;
    }
    const SurfaceHit& hit() const { return hit_; }
    const NumericsOptions& numerics() const { return numerics_; }

private:
    // The origin of the first ray on `side` (Robust or WachterBinder offsets), kept for the next
    // ones; or, when the normal names no side (zero or not finite), the ray's own origin pushed
    // along `direction`, not kept.
    Vec3 firstOrigin(int side, const Vec3& direction);
    // A ray from the hit point itself, by the methods that move no origin (FixedEpsilon, None,
    // OwnPrimitive).
    Ray leaveWithoutOffset() const;

    const SurfaceHit& hit_;
    const NumericsOptions& numerics_;
    unsigned made_ = 0;  // bit s: origins_[s] is computed
    Vec3 origins_[2];    // [0] on the normal's side, [1] on the other
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
// The segment from a point inside a medium, on no surface (so with no offset at its start).
Ray spawnShadowRay(const Vec3& origin, const Vec3& target, const Vec3& targetNormal,
                   const NumericsOptions& numerics);

// Shadow segments end this fraction short of the light, so a light placed on a surface does not
// shadow itself (pbrt-v4's ShadowEpsilon plays the same role).
inline constexpr float kShadowShortening = 1e-5f;

// Points `ray` from its origin at `target`, stopping just short of it. When `target` lies on a
// surface (unit `normal`; zero: none), the segment also ends off that surface by the bound that
// moves ray origins off theirs (pbrt-v4's SpawnRayTo offsets both ends): the surface as the shadow
// ray's own intersection computes it then lies beyond the segment's end at any angle. The fixed
// shortening alone fails along grazing chords, where an ulp across the surface is many along the
// ray (a closed emissive sphere lost 0.03% of its self-light). The robust bound is applied along
// the ray, `across / |cos|`: the clearance of moving the target, for less work per shadow ray.
// Inline, as spawnShadowRay from shared origins is: both run once per light of a shading point.
inline void aimShadowRay(Ray& ray, Vec3 target, const Vec3& normal, const NumericsOptions& numerics) {
    if (numerics.offset == RayOffset::WachterBinder && glm::dot(normal, normal) > 0.0f)
        target = offsetRayOriginWachterBinder(target, glm::dot(ray.origin - target, normal) >= 0.0f ? normal : -normal);
    const Vec3 toTarget = target - ray.origin;
    const float distance = glm::length(toTarget);
    if (!(distance > 0.0f) || !std::isfinite(distance)) {
        // The light sits on the origin (or something is not finite): nothing can lie between.
        ray.tMax = 0.0f;
        return;
    }
    ray.direction = toTarget / distance;
    ray.tMax = distance * (1.0f - kShadowShortening);
    // Zero for no surface (and for a segment along one, which carries no light).
    const float cosine = std::fabs(glm::dot(ray.direction, normal));
    if (numerics.offset == RayOffset::Robust && cosine > 0.0f) {
        // offsetRayOrigin's error per coordinate, times sqrt(3) >= |n_x| + |n_y| + |n_z|.
        const float largest = std::max(std::max(std::fabs(target.x), std::fabs(target.y)), std::fabs(target.z));
        const float across = kPointErrorScale * 1.7320508f * (largest + 2.0f * distance);
        ray.tMax = std::max(std::min(ray.tMax, distance - across / cosine), 0.0f);
    }
}

// The same as spawnShadowRay(hit, ...), from origins shared by several shadow rays of one hit.
inline Ray spawnShadowRay(RayOrigins& origins, const Vec3& target, const Vec3& targetNormal) {
    Ray ray = origins.leave(target - origins.hit().point);
    aimShadowRay(ray, target, targetNormal, origins.numerics());
    return ray;
}

}  // namespace lightpath
