#include "integrators/raycast.h"

#include "integrators/direct_light.h"

namespace lightpath {

void RaycastIntegrator::traceCameraRay(const Ray& ray, PathState& path) const {
    shadeFirstHit(path.context.geometry.intersect(ray), ray, path);
}

void shadeFirstHit(const std::optional<SurfaceHit>& hit, const Ray& ray, PathState& path) {
    const RenderContext& ctx = path.context;
    if (!hit) {
        addBackground(ray, Rgb{1.0f}, path);
        return;
    }
    addEmission(*hit, ray, Rgb{1.0f}, 1.0f, path);
    if (ctx.maxDepth < 1) return;
    addLocalIllumination(makeShadingPoint(*hit, ray, ctx), Rgb{1.0f}, path);
}

}  // namespace lightpath
