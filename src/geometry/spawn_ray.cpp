#include "geometry/spawn_ray.h"

#include <algorithm>
#include <cmath>

#include "geometry/ray_offset.h"
#include "util/hot_path.h"

namespace lightpath {
namespace {

bool isUsable(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && glm::dot(v, v) > 0.0f;
}

// The point a ray leaving `point` along unit `side` starts from, by the method that moves it.
[[gnu::always_inline]] inline Vec3 offsetOrigin(const SurfaceHit& hit, const Vec3& side, const NumericsOptions& numerics) {
    return numerics.offset == RayOffset::WachterBinder ? offsetRayOriginWachterBinder(hit.point, side)
                                                       : offsetRayOrigin(hit.point, side, hit.t);
}

}  // namespace

// Flattened: the offset's arithmetic inline, not a call with its arguments through memory.
LIGHTPATH_HOT_PATH
[[gnu::flatten]] Vec3 RayOrigins::firstOrigin(int side, const Vec3& direction) {
    if (!isUsable(hit_.normal)) {
        // No side to name: the ray is pushed along its own direction instead.
        const Vec3 along = isUsable(direction) ? glm::normalize(direction) : Vec3{0.0f};
        return offsetOrigin(hit_, along, numerics_);
    }
    origins_[side] = offsetOrigin(hit_, side == 0 ? hit_.normal : -hit_.normal, numerics_);
    made_ |= 1u << side;
    return origins_[side];
}

Ray RayOrigins::leaveWithoutOffset() const {
    Ray ray;
    ray.origin = hit_.point;
    if (numerics_.offset == RayOffset::FixedEpsilon) ray.tMin = numerics_.epsilon;
    if (numerics_.offset == RayOffset::OwnPrimitive) ray.ignoredPrimitive = hit_.primitive;
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

}  // namespace lightpath
