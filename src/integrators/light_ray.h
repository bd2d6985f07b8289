#pragma once
// The first ray of a walk from a light (bdpt's light subpath, a photon): its start and the cosine
// at the light, shared so that both walks leave a light alike.
#include <cmath>

#include "accel/scene_geometry.h"
#include "geometry/spawn_ray.h"
#include "lights/light.h"

namespace lightpath {

struct LightRay {
    Ray ray;
    float cosine = 1.0f;  // |n . w| at an area light's point; 1 for a delta light
};

// An area light's ray leaves its surface like any surface's (offset by the numerics' rule), so it
// does not find its own start; a delta light's ray starts at the light itself.
inline LightRay leaveLight(const Light& light, const EmittedRay& e, const SceneGeometry& geometry) {
    if (light.isDelta()) return {e.ray, 1.0f};
    SurfaceHit origin;
    origin.point = e.ray.origin;
    origin.normal = origin.shadingNormal = e.normal;
    origin.object = light.event().index;
    origin.primitive = kNoPrimitive;
    return {spawnRay(origin, e.ray.direction, geometry.numerics()), std::fabs(glm::dot(e.normal, e.ray.direction))};
}

}  // namespace lightpath
