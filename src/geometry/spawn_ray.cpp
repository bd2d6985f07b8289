#include "geometry/spawn_ray.h"

#include <algorithm>
#include <cmath>

#include "geometry/ray_offset.h"
#include "util/hot_path.h"

namespace lightpath {
namespace {

// Shadow segments end this fraction short of the light, so a light placed on a surface does not
// shadow itself (pbrt-v4's ShadowEpsilon plays the same role).
constexpr float kShadowShortening = 1e-5f;

bool isUsable(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && glm::dot(v, v) > 0.0f;
}

// The point a ray leaving `point` along unit `side` starts from, by the chosen method.
Vec3 offsetOrigin(const SurfaceHit& hit, const Vec3& side, const NumericsOptions& numerics) {
    switch (numerics.offset) {
        case RayOffset::Robust: return offsetRayOrigin(hit.point, side, hit.t);
        case RayOffset::WachterBinder: return offsetRayOriginWachterBinder(hit.point, side);
        case RayOffset::FixedEpsilon:
        case RayOffset::None:
        case RayOffset::OwnPrimitive: break;
    }
    return hit.point;
}

// Points `ray` from its origin at `target`, stopping just short of it. When `target` lies on a
// surface (unit `normal`; zero: none), the segment also ends off that surface by the bound that
// moves ray origins off theirs (pbrt-v4's SpawnRayTo offsets both ends): the surface as the shadow
// ray's own intersection computes it then lies beyond the segment's end at any angle. The fixed
// shortening alone fails along grazing chords, where an ulp across the surface is many along the
// ray (a closed emissive sphere lost 0.03% of its self-light). The robust bound is applied along
// the ray, `across / |cos|`: the clearance of moving the target, for less work per shadow ray.
LIGHTPATH_HOT_PATH
void aimShadowRay(Ray& ray, Vec3 target, const Vec3& normal, const NumericsOptions& numerics) {
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

}  // namespace

LIGHTPATH_HOT_PATH
RayOrigins::RayOrigins(const SurfaceHit& hit, const NumericsOptions& numerics)
    : hit_(hit), numerics_(numerics), normalUsable_(isUsable(hit.normal)) {}

LIGHTPATH_HOT_PATH
Ray RayOrigins::leave(const Vec3& direction) {
    Ray ray;
    ray.origin = hit_.point;
    switch (numerics_.offset) {
        case RayOffset::Robust:
        case RayOffset::WachterBinder: {
            if (!normalUsable_) {
                // No side to name: the ray is pushed along its own direction instead.
                const Vec3 along = isUsable(direction) ? glm::normalize(direction) : Vec3{0.0f};
                ray.origin = offsetOrigin(hit_, along, numerics_);
                break;
            }
            const bool normalSide = glm::dot(direction, hit_.normal) >= 0.0f;
            std::optional<Vec3>& origin = origins_[normalSide ? 0 : 1];
            if (!origin) origin = offsetOrigin(hit_, normalSide ? hit_.normal : -hit_.normal, numerics_);
            ray.origin = *origin;
            break;
        }
        case RayOffset::FixedEpsilon:
            ray.tMin = numerics_.epsilon;
            break;
        case RayOffset::None:
            break;
        case RayOffset::OwnPrimitive:
            ray.ignoredPrimitive = hit_.primitive;
            break;
    }
    return ray;
}

LIGHTPATH_HOT_PATH
Ray spawnRay(const SurfaceHit& hit, const Vec3& direction, const NumericsOptions& numerics) {
    RayOrigins origins(hit, numerics);
    return spawnRay(origins, direction);
}

LIGHTPATH_HOT_PATH
Ray spawnRay(RayOrigins& origins, const Vec3& direction) {
    Ray ray = origins.leave(direction);
    ray.direction = direction;
    return ray;
}

LIGHTPATH_HOT_PATH
Ray spawnShadowRay(const SurfaceHit& hit, const Vec3& target, const Vec3& targetNormal,
                   const NumericsOptions& numerics) {
    RayOrigins origins(hit, numerics);
    return spawnShadowRay(origins, target, targetNormal);
}

LIGHTPATH_HOT_PATH
Ray spawnShadowRay(const Vec3& origin, const Vec3& target, const Vec3& targetNormal,
                   const NumericsOptions& numerics) {
    Ray ray;
    ray.origin = origin;
    aimShadowRay(ray, target, targetNormal, numerics);
    return ray;
}

LIGHTPATH_HOT_PATH
Ray spawnShadowRay(RayOrigins& origins, const Vec3& target, const Vec3& targetNormal) {
    Ray ray = origins.leave(target - origins.hit().point);
    aimShadowRay(ray, target, targetNormal, origins.numerics());
    return ray;
}

}  // namespace lightpath
