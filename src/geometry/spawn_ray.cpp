#include "geometry/spawn_ray.h"

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

// Points `ray` from its origin at `target`, stopping just short of it.
void aimShadowRay(Ray& ray, const Vec3& target) {
    const Vec3 toTarget = target - ray.origin;
    const float distance = glm::length(toTarget);
    if (!(distance > 0.0f) || !std::isfinite(distance)) {
        // The light sits on the origin (or something is not finite): nothing can lie between.
        ray.tMax = 0.0f;
        return;
    }
    ray.direction = toTarget / distance;
    ray.tMax = distance * (1.0f - kShadowShortening);
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
    Ray ray = RayOrigins(hit, numerics).leave(direction);
    ray.direction = direction;
    return ray;
}

LIGHTPATH_HOT_PATH
Ray spawnShadowRay(const SurfaceHit& hit, const Vec3& target, const NumericsOptions& numerics) {
    RayOrigins origins(hit, numerics);
    return spawnShadowRay(origins, target);
}

LIGHTPATH_HOT_PATH
Ray spawnShadowRay(const Vec3& origin, const Vec3& target) {
    Ray ray;
    ray.origin = origin;
    aimShadowRay(ray, target);
    return ray;
}

LIGHTPATH_HOT_PATH
Ray spawnShadowRay(RayOrigins& origins, const Vec3& target) {
    Ray ray = origins.leave(target - origins.hit().point);
    aimShadowRay(ray, target);
    return ray;
}

}  // namespace lightpath
