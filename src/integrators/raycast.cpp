#include "integrators/raycast.h"

#include "integrators/registry.h"
#include "integrators/direct_light.h"

namespace lightpath {

void RaycastIntegrator::traceCameraRay(const Ray& ray, PathState& path) const {
    shadeFirstHit(path.context.geometry.intersect(ray), ray, path);
}

void shadeFirstHit(const std::optional<SurfaceHit>& hit, const Ray& ray, PathState& path) {
    const RenderContext& ctx = path.context;
    // The camera is in the world's medium (media do not nest): every term is seen through it.
    const Rgb seen = throughMedium(hit, ray, ctx.scene.worldMedium, Rgb{1.0f}, path);
    if (!hit) {
        addBackground(ray, seen, path);
        return;
    }
    addEmission(*hit, ray, seen, 1.0f, path);
    if (ctx.maxDepth < 1) return;
    addLocalIllumination(makeShadingPoint(*hit, ray, ctx), seen, path, ctx.scene.medium(ctx.scene.worldMedium));
}

}  // namespace lightpath

// raycast.cpp shades the first hit with local_illumination.cpp's diffuse and highlight terms towards
// each light and the ambient light (E(D|G)L), and adds emission and the background seen directly (EL).
LIGHTPATH_REGISTER_INTEGRATOR(lightpath::rendersMedia(lightpath::integratorRow(
    "raycast", "first hit only: Szymczak's formula, emitters and the background seen directly",
    "E(D|G)L|EL|E<Vx>L", "ray casting follows no specular bounce and no second bounce: it shades the first hit only",
    [] { return std::unique_ptr<lightpath::Integrator>(std::make_unique<lightpath::RaycastIntegrator>()); },
    lightpath::ShadowRays::Optional, 0)))
