#include "integrators/raycast.h"

#include "integrators/direct_light.h"

namespace lightpath {

void RaycastIntegrator::traceCameraRay(const Ray& ray, PathState& path) const {
    const RenderContext& ctx = path.context;
    const auto hit = ctx.geometry.intersect(ray);
    if (!hit) {
        addBackground(ray, Rgb{1.0f}, path);
        return;
    }
    addEmission(*hit, ray, Rgb{1.0f}, 1.0f, path);
    if (ctx.maxDepth < 1) return;
    addLocalIllumination(makeShadingPoint(*hit, ray, ctx), Rgb{1.0f}, path);
}

}  // namespace lightpath
