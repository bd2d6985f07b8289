#include "integrators/shading_point.h"

#include <cmath>

#include "integrators/integrator.h"
#include "util/hot_path.h"

namespace lightpath {
namespace {

// Where the offset ray from + s d meets the tangent plane through `point` with normal `normal`,
// minus `point`: the step on the surface that one pixel's step of the film makes (zero where the
// offset ray runs along the plane).
Vec3 stepOnTangentPlane(const Vec3& from, const Vec3& d, const Vec3& point, const Vec3& normal) {
    const float along = glm::dot(normal, d);
    const float s = glm::dot(normal, point - from) / along;
    if (!std::isfinite(s) || s <= 0.0f) return Vec3(0.0f);
    return from + s * d - point;
}

// The texture footprint of a hit: its uv and their change across one pixel. The pixel's steps on
// the surface are the camera's ray differentials (pbrt-v4 5.2.3, 10.1.1), found from the eye (an
// orthographic camera: from the film, one pixel over) through the hit's tangent plane; for a point the camera does not see directly (after a
// bounce) the same steps from the eye, pbrt-v4's Approximate_dp_dxy: the footprint of a camera
// ray to that point, narrower than a ray cone along the path would give (no blur added by
// mirrors or curvature), so it never blurs more than a camera ray would. Then dp = dpdu du + dpdv
// dv solved in the least-squares sense (pbrt-v4 10.1.1, SurfaceInteraction::ComputeDifferentials).
TextureFootprint footprintOf(const SurfaceHit& hit, const SurfaceParameters& surface, const RenderContext& context) {
    const Camera& camera = context.camera;
    const Vec3 toPoint = hit.point - camera.eye();
    const float depth = glm::dot(toPoint, camera.forward());
    TextureFootprint footprint;
    footprint.uv = surface.uv;
    if (!(depth > 0.0f)) return footprint;  // behind the eye's plane: no pixel sees it; point sampled
    Vec3 dpdx, dpdy;
    if (camera.orthographic()) {
        // Parallel rays: the neighbouring pixels' rays start one pixel's step along the film.
        const Vec3 film = hit.point - depth * camera.forward(), start = camera.filmOrigin(0.0f, 0.0f);
        const Vec3 dOdx = camera.filmOrigin(1.0f, 0.0f) - start, dOdy = camera.filmOrigin(0.0f, 1.0f) - start;
        dpdx = stepOnTangentPlane(film + dOdx, camera.forward(), hit.point, hit.normal);
        dpdy = stepOnTangentPlane(film + dOdy, camera.forward(), hit.point, hit.normal);
    } else {
        const Vec3 origin = camera.filmDirection(0.0f, 0.0f);
        const Vec3 dDdx = camera.filmDirection(1.0f, 0.0f) - origin, dDdy = camera.filmDirection(0.0f, 1.0f) - origin;
        const Vec3 d = toPoint / depth;  // on the film plane at distance 1, as filmDirection's
        dpdx = stepOnTangentPlane(camera.eye(), d + dDdx, hit.point, hit.normal);
        dpdy = stepOnTangentPlane(camera.eye(), d + dDdy, hit.point, hit.normal);
    }
    const float ata00 = glm::dot(surface.dpdu, surface.dpdu), ata01 = glm::dot(surface.dpdu, surface.dpdv),
                ata11 = glm::dot(surface.dpdv, surface.dpdv);
    float invDet = 1.0f / (ata00 * ata11 - ata01 * ata01);
    if (!std::isfinite(invDet)) invDet = 0.0f;
    const auto solve = [&](const Vec3& dp) {
        const float atb0 = glm::dot(surface.dpdu, dp), atb1 = glm::dot(surface.dpdv, dp);
        const Vec2 duv{(ata11 * atb0 - ata01 * atb1) * invDet, (ata00 * atb1 - ata01 * atb0) * invDet};
        // Clamped as pbrt-v4 does: a grazing step can be huge; the filter then takes the coarsest level.
        return glm::clamp(duv, Vec2(-1e8f), Vec2(1e8f));
    };
    footprint.dUVdx = solve(dpdx);
    footprint.dUVdy = solve(dpdy);
    return footprint;
}

// A textured material's footprint (into `texture`) and its shading normal, normal-mapped if it
// has a map. Out of line: inline, it made makeShadingPoint 3.4 KB, most of it never run by an
// untextured scene, whose hot lines it spread apart.
[[gnu::noinline]] Vec3 textured(const SurfaceHit& hit, const Material& m, const RenderContext& context,
                                TextureFootprint& texture) {
    const SurfaceParameters surface = context.geometry.surfaceParameters(hit);
    texture = footprintOf(hit, surface, context);
    if (!m.normalMap.texture) return hit.shadingNormal;
    // The mesh's tangent when it gives one (glTF 2.0, 3.7.2.1: bitangent = w cross(normal,
    // tangent)), else the uvs' dp/du and dp/dv.
    const Vec3 tangent(surface.tangent);
    const bool given = surface.tangent.w != 0.0f;
    return m.normalMap.perturb(hit.shadingNormal, given ? tangent : surface.dpdu,
                               given ? surface.tangent.w * glm::cross(hit.shadingNormal, tangent) : surface.dpdv,
                               texture);
}

}  // namespace

LIGHTPATH_HOT_PATH
ShadingPoint makeShadingPoint(const SurfaceHit& hit, const Ray& ray, const RenderContext& context, TransportMode mode) {
    const bool entering = glm::dot(hit.normal, ray.direction) < 0.0f;
    const std::uint32_t material = context.scene.objects[hit.object].material;
    const Material& m = *context.scene.materials[material];
    // Only a textured material pays for its texture coordinates.
    TextureFootprint texture;
    Vec3 shadingNormal = hit.shadingNormal;
    if (m.textured) shadingNormal = textured(hit, m, context, texture);
    const Vec3 normal = entering ? shadingNormal : -shadingNormal;
    const MaterialTerms& terms = context.analysis.materials[material];
    const Rgb vertexColor = m.vertexColored ? context.geometry.vertexColorAt(hit) : Rgb(1.0f);
    return {hit, -ray.direction, normal, entering, m, terms, Bsdf(m, normal, entering, mode, texture, &terms.lobes, vertexColor)};
}

}  // namespace lightpath
