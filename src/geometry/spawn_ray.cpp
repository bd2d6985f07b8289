#include "geometry/spawn_ray.h"

#include "geometry/ray_offset.h"

namespace lightpath {
namespace {

// Shadow segments end this fraction short of the light.
constexpr float kShadowShortening = 1e-5f;

// The origin and the rules of a ray leaving `hit` towards the side of `direction`.
Ray leave(const SurfaceHit& hit, const Vec3& direction, const NumericsOptions& numerics) {
    Ray ray;
    ray.origin = hit.point;
    switch (numerics.offset) {
        case RayOffset::Robust: {
            const Vec3 side = glm::dot(direction, hit.normal) >= 0.0f ? hit.normal : -hit.normal;
            ray.origin = offsetRayOrigin(hit.point, side);
            break;
        }
        case RayOffset::FixedEpsilon:
            ray.tMin = numerics.epsilon;
            break;
        case RayOffset::None:
            break;
        case RayOffset::OwnPrimitive:
            ray.ignoredPrimitive = hit.primitive;
            break;
    }
    return ray;
}

}  // namespace

Ray spawnRay(const SurfaceHit& hit, const Vec3& direction, const NumericsOptions& numerics) {
    Ray ray = leave(hit, direction, numerics);
    ray.direction = direction;
    return ray;
}

Ray spawnShadowRay(const SurfaceHit& hit, const Vec3& target, const NumericsOptions& numerics) {
    Ray ray = leave(hit, target - hit.point, numerics);
    const Vec3 toTarget = target - ray.origin;
    const float distance = glm::length(toTarget);
    ray.direction = toTarget / distance;
    ray.tMax = distance * (1.0f - kShadowShortening);
    return ray;
}

}  // namespace lightpath
