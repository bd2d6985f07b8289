#include "integrators/raycast.h"

#include "integrators/registry.h"
#include "integrators/direct_light.h"

namespace lightpath {

void RaycastIntegrator::traceCameraRay(const Ray& ray, PathState& path) const {
    shadeFirstHit(path.context.geometry.intersect(ray), ray, path);
}

void shadeFirstHit(const std::optional<SurfaceHit>& hit, const Ray& ray, PathState& path) {
    const RenderContext& ctx = path.context;
    // Every term is seen through the media from the camera's on, across index-matched boundaries.
    const BeyondInterfaces beyond = crossInterfaces(hit, ray, ctx.eyeMedium, Rgb{1.0f}, path);
    const Rgb seen = throughMedium(beyond.hit, beyond.ray, beyond.medium, beyond.throughput, path);
    if (!beyond.hit) {
        addBackground(beyond.ray, seen, path);
        return;
    }
    addEmission(*beyond.hit, beyond.ray, seen, 1.0f, path);
    if (ctx.maxDepth < 1) return;
    addLocalIllumination(makeShadingPoint(*beyond.hit, beyond.ray, ctx), seen, path, ctx.scene.medium(beyond.medium));
}

}  // namespace lightpath

// raycast.cpp shades the first hit with local_illumination.cpp's diffuse and highlight terms towards
// each light and the ambient light (E(D|G)L), and adds emission and the background seen directly (EL).
LIGHTPATH_REGISTER_INTEGRATOR(lightpath::rendersMedia(lightpath::integratorRow(
    "raycast", "first hit only: Szymczak's formula, emitters and the background seen directly",
    "E(D|G)L|EL|E<Vx>L", "ray casting follows no specular bounce and no second bounce: it shades the first hit only",
    [] { return std::unique_ptr<lightpath::Integrator>(std::make_unique<lightpath::RaycastIntegrator>()); },
    lightpath::ShadowRays::Optional, 0)))
