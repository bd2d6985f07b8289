#include "integrators/shading_point.h"

#include "integrators/integrator.h"

namespace lightpath {

ShadingPoint makeShadingPoint(const SurfaceHit& hit, const Ray& ray, const RenderContext& context, TransportMode mode) {
    const bool entering = glm::dot(hit.normal, ray.direction) < 0.0f;
    const Vec3 normal = entering ? hit.shadingNormal : -hit.shadingNormal;
    const std::uint32_t material = context.scene.objects[hit.object].material;
    const Material& m = *context.scene.materials[material];
    return {hit, -ray.direction, normal, entering, m, context.analysis.materials[material], Bsdf(m, normal, entering, mode)};
}

}  // namespace lightpath
