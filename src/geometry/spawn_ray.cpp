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

}  // namespace

LIGHTPATH_HOT_PATH
Ray RayOrigins::leaveFirst(const Vec3& direction) {
    Ray ray;
    ray.origin = hit_.point;
    switch (numerics_.offset) {
        case RayOffset::Robust:
        case RayOffset::WachterBinder: {
            if (!isUsable(hit_.normal)) {
                // A zero or non-finite normal names no side: the ray is pushed along its own
                // direction instead, and nothing is kept.
                const Vec3 along = isUsable(direction) ? glm::normalize(direction) : Vec3{0.0f};
                ray.origin = offsetOrigin(hit_, along, numerics_);
                break;
            }
            const bool normalSide = glm::dot(direction, hit_.normal) >= 0.0f;
            const int side = normalSide ? 0 : 1;
            origins_[side] = offsetOrigin(hit_, normalSide ? hit_.normal : -hit_.normal, numerics_);
            made_ |= 1u << side;
            ray.origin = origins_[side];
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

}  // namespace lightpath
