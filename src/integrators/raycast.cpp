#include "integrators/raycast.h"

#include <optional>

#include "integrators/registry.h"
#include "integrators/direct_light.h"
#include "util/hot_path.h"

namespace lightpath {

LIGHTPATH_HOT_PATH
void RaycastIntegrator::traceCameraRay(const Ray& ray, PathState& path) const {
    shadeFirstHit(path.context.geometry.intersect(ray), ray, path);
}

LIGHTPATH_HOT_PATH
void shadeFirstHit(const std::optional<SurfaceHit>& hit, const Ray& ray, PathState& path) {
    const RenderContext& ctx = path.context;
    // Every term is seen through the media from the camera's on, across index-matched boundaries
    // (a scene without them crosses none: the hit is not copied through crossInterfaces).
    std::optional<BeyondInterfaces> beyond;
    if (ctx.scene.interfaces) beyond = crossInterfaces(hit, ray, ctx.eyeMedium, Rgb{1.0f}, path);
    const std::optional<SurfaceHit>& seenHit = beyond ? beyond->hit : hit;
    const Ray& seenRay = beyond ? beyond->ray : ray;
    const std::uint32_t medium = beyond ? beyond->medium : ctx.eyeMedium;
    const Rgb seen = throughMedium(seenHit, seenRay, medium, beyond ? beyond->throughput : Rgb{1.0f}, path);
    if (!seenHit) {
        addBackground(seenRay, seen, path);
        return;
    }
    addEmission(*seenHit, seenRay, seen, 1.0f, path);
    if (ctx.maxDepth < 1) return;
    addLocalIllumination(makeShadingPoint(*seenHit, seenRay, ctx), seen, path, ctx.scene.medium(medium));
}

}  // namespace lightpath

// raycast.cpp shades the first hit with local_illumination.cpp's diffuse and highlight terms towards
// each light and the ambient light (E(D|G)L), and adds emission and the background seen directly (EL).
LIGHTPATH_REGISTER_INTEGRATOR(lightpath::rendersMedia(lightpath::integratorRow(
    "raycast", "first hit only: Szymczak's formula, emitters and the background seen directly",
    "E(D|G)L|EL|E<Vx>L", "ray casting follows no specular bounce and no second bounce: it shades the first hit only",
    [] { return std::unique_ptr<lightpath::Integrator>(std::make_unique<lightpath::RaycastIntegrator>()); },
    lightpath::ShadowRays::Optional, 0)))
