#include "geometry/spawn_ray.h"

#include <cmath>

#include "geometry/ray_offset.h"

namespace lightpath {
namespace {

// Shadow segments end this fraction short of the light, so a light placed on a surface does not
// shadow itself (pbrt-v4's ShadowEpsilon plays the same role).
constexpr float kShadowShortening = 1e-5f;

bool isUsable(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && glm::dot(v, v) > 0.0f;
}

// The side of the surface `direction` leaves into. A degenerate normal (zero or not finite, e.g.
// from a zero-area triangle) cannot say, so the ray is pushed along its own direction instead.
Vec3 leavingSide(const SurfaceHit& hit, const Vec3& direction) {
    if (!isUsable(hit.normal)) return isUsable(direction) ? glm::normalize(direction) : Vec3{0.0f};
    return glm::dot(direction, hit.normal) >= 0.0f ? hit.normal : -hit.normal;
}

// The origin and the rules of a ray leaving `hit` towards the side of `direction`.
Ray leave(const SurfaceHit& hit, const Vec3& direction, const NumericsOptions& numerics) {
    Ray ray;
    ray.origin = hit.point;
    switch (numerics.offset) {
        case RayOffset::Robust:
            ray.origin = offsetRayOrigin(hit.point, leavingSide(hit, direction), hit.t);
            break;
        case RayOffset::WachterBinder:
            ray.origin = offsetRayOriginWachterBinder(hit.point, leavingSide(hit, direction));
            break;
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
    if (!(distance > 0.0f) || !std::isfinite(distance)) {
        // The light sits on the origin (or something is not finite): nothing can lie between.
        ray.tMax = 0.0f;
        return ray;
    }
    ray.direction = toTarget / distance;
    ray.tMax = distance * (1.0f - kShadowShortening);
    return ray;
}

}  // namespace lightpath
