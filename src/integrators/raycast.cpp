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

namespace {

// The first surface the camera sees along `ray` in `medium` (none: the ray escapes), `throughput`
// being what reaches the eye from the ray's origin.
void shadeSeenHit(const std::optional<SurfaceHit>& hit, const Ray& ray, std::uint32_t medium, const Rgb& throughput,
                  PathState& path) {
    const RenderContext& ctx = path.context;
    const Rgb seen = throughMedium(hit, ray, medium, throughput, path);
    if (!hit) {
        addBackground(ray, seen, path);
        return;
    }
    addEmission(*hit, ray, seen, 1.0f, path);
    // Unlikely, so that GCC does not take the shading below for a cold call and leave
    // makeShadingPoint out of line (which the unity batch's inlining budget then decides).
    if (ctx.maxDepth < 1) [[unlikely]] return;
    addLocalIllumination(makeShadingPoint(*hit, ray, ctx), seen, path, ctx.scene.medium(medium));
}

}  // namespace

LIGHTPATH_HOT_PATH
void shadeFirstHit(const std::optional<SurfaceHit>& hit, const Ray& ray, PathState& path) {
    const RenderContext& ctx = path.context;
    // Every term is seen through the media from the camera's on, across index-matched boundaries.
    // A scene without them crosses none: its hit is shaded as found, neither copied through
    // crossInterfaces nor an empty optional of the crossing made (GCC zeroed its 136 bytes a point).
    if (!ctx.scene.interfaces) {
        shadeSeenHit(hit, ray, ctx.eyeMedium, Rgb{1.0f}, path);
        return;
    }
    const BeyondInterfaces beyond = crossInterfaces(hit, ray, ctx.eyeMedium, Rgb{1.0f}, path);
    shadeSeenHit(beyond.hit, beyond.ray, beyond.medium, beyond.throughput, path);
}

}  // namespace lightpath

// raycast.cpp shades the first hit with local_illumination.cpp's diffuse and highlight terms towards
// each light and the ambient light (E(D|G)L), and adds emission and the background seen directly (EL).
LIGHTPATH_REGISTER_INTEGRATOR(lightpath::rendersMedia(lightpath::integratorRow(
    "raycast", "first hit only: Szymczak's formula, emitters and the background seen directly",
    "E(D|G)L|EL|E<Vx>L", "ray casting follows no specular bounce and no second bounce: it shades the first hit only",
    [] { return std::unique_ptr<lightpath::Integrator>(std::make_unique<lightpath::RaycastIntegrator>()); },
    lightpath::ShadowRays::Optional, 0)))
