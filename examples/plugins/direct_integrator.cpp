// Example plugin (docs/extending.md): direct lighting only (pbrt's DirectLightingIntegrator): the
// emitters and background a camera ray sees, and at its first hit the light that arrives straight
// from the lights (one shadow ray per point light, one sampled point on an area light), with no
// ambient term and no second bounce. Ray casting without Szymczak's ambient fake: what a lecturer
// shows before the path tracer adds the indirect light. One file: the method and its registry row.
#include "integrators/direct_light.h"
#include "integrators/registry.h"

namespace lightpath::examples {
namespace {

class DirectIntegrator final : public Integrator {
public:
    void traceCameraRay(const Ray& ray, PathState& path) const override {
        const RenderContext& ctx = path.context;
        const std::optional<SurfaceHit> hit = ctx.geometry.intersect(ray);
        if (!hit) {
            addBackground(ray, Rgb{1.0f}, path);
            return;
        }
        addEmission(*hit, ray, Rgb{1.0f}, 1.0f, path);
        if (ctx.maxDepth < 1 || path.sampler == nullptr) return;
        // Keyed by the path, as ray casting's, so that skipping another branch never moves these numbers.
        LightChoiceSample u{0.0f, Vec2{0.0f}};
        if (ctx.lights.hasAreaLights()) {
            Sampler vertex = path.sampler->forVertex(path.key());
            u.uChoice = vertex.next1D();
            u.uPoint = vertex.next2D();
        }
        addDirectLight(makeShadingPoint(*hit, ray, ctx), Rgb{1.0f}, u, DirectLightWeighting::Alone, path);
    }
};

}  // namespace
}  // namespace lightpath::examples

LIGHTPATH_REGISTER_INTEGRATOR(lightpath::integratorRow(
    "direct", "example plugin: direct light only, emitters seen and the lights at the first hit, no ambient term",
    "E(D|G)([OB]|<L[^'ambient']>)|EL", "direct lighting follows no bounce after the first hit and adds no ambient term",
    [] { return std::unique_ptr<lightpath::Integrator>(std::make_unique<lightpath::examples::DirectIntegrator>()); },
    lightpath::ShadowRays::Optional, 100))
