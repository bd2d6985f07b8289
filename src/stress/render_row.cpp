#include "stress/render_row.h"

#include <algorithm>
#include <cmath>

#include "film/aov_set.h"
#include "accel/scene_geometry.h"
#include "geometry/spawn_ray.h"
#include "lights/point_light.h"
#include "materials/phong_material.h"
#include "render/renderer.h"
#include "stress/sampling.h"
#include "stress/scene_objects.h"

namespace lightpath {
namespace {


void addQuad(Scene& scene, std::uint32_t object, Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
    scene.triangles.push_back({a, b, c, object});
    scene.triangles.push_back({a, c, d, object});
}

// The Cornell box's arrangement: a room 2 units wide with a red and a green wall, a matte ball
// resting on the floor, a mirror ball, and a point light under the ceiling with no attenuation,
// so radiance does not depend on the scale. Every length is multiplied by `scale`. The floor is
// the plane y = 0: its hit points have a coordinate that is zero but carries the error of
// o + t d, the case that defeats an offset proportional to the point's own coordinates.
// The camera is off the room's axis of symmetry: on it, the room's corner edges pass exactly
// through pixel centres, where which wall is seen is a coin toss at any scale.
Scene cornellRoom(float scale, int size) {
    Scene scene;
    scene.camera.eye = scale * Vec3{0.0123f, 0.9629f, 3.4f};
    scene.camera.lookAt = scale * Vec3{0.0123f, 0.9629f, 0.0f};
    scene.camera.up = {0.0f, 1.0f, 0.0f};
    scene.camera.verticalFovDegrees = 40.0f;
    scene.camera.width = scene.camera.height = size;
    scene.ambient = {0.05f, 0.05f, 0.05f};
    const auto matte = [](Rgb kd) {
        PhongMaterial m;
        m.ka = m.kd = kd;
        return m;
    };
    const auto p = [scale](float x, float y, float z) { return scale * Vec3{x, y + 1.0f, z}; };
    scene.planes.push_back({Vec3{0.0f}, {0.0f, 1.0f, 0.0f}, stress::addObject(scene, "floor", matte({0.7f, 0.7f, 0.7f}))});
    addQuad(scene, stress::addObject(scene, "ceiling", matte({0.7f, 0.7f, 0.7f})), p(-1, 1, -1), p(1, 1, -1), p(1, 1, 1), p(-1, 1, 1));
    addQuad(scene, stress::addObject(scene, "back", matte({0.7f, 0.7f, 0.7f})), p(-1, -1, -1), p(1, -1, -1), p(1, 1, -1), p(-1, 1, -1));
    addQuad(scene, stress::addObject(scene, "red", matte({0.7f, 0.1f, 0.1f})), p(-1, -1, 1), p(-1, -1, -1), p(-1, 1, -1), p(-1, 1, 1));
    addQuad(scene, stress::addObject(scene, "green", matte({0.1f, 0.7f, 0.1f})), p(1, -1, -1), p(1, -1, 1), p(1, 1, 1), p(1, 1, -1));
    PhongMaterial ball = matte({0.5f, 0.5f, 0.8f});
    ball.ks = {0.4f, 0.4f, 0.4f};
    ball.n = 30.0f;
    scene.spheres.push_back({p(-0.4f, -0.6f, -0.3f), 0.4f * scale, stress::addObject(scene, "ball", ball)});
    PhongMaterial mirror;
    mirror.kr = {0.8f, 0.8f, 0.8f};
    scene.spheres.push_back({p(0.45f, -0.7f, 0.3f), 0.3f * scale, stress::addObject(scene, "mirror", mirror)});
    scene.lights.push_back(PointLight{"key", p(0.1f, 0.9f, 0.2f), Rgb{1.2f}, Vec3{1.0f, 0.0f, 0.0f}});
    return scene;
}

std::vector<Rgb> renderBeauty(const Scene& scene, const NumericsOptions& numerics) {
    const AovSet aovs({});
    RenderOptions options;
    options.numerics = numerics;
    options.threads = 2;
    return Renderer(scene, aovs, options).render().film.layer(0);
}

// Pixels whose centre and 8 neighbours see the same flat (plane or triangle) object at points
// the light reaches: there a renderer at any scale must give the same colour.
std::vector<bool> litFlatMask(const Scene& scene) {
    const SceneGeometry geometry(scene.spheres, scene.planes, scene.triangles);
    const Camera camera(scene.camera);
    const int w = scene.camera.width, h = scene.camera.height;
    std::vector<int> object(static_cast<std::size_t>(w * h), -1);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const auto hit = geometry.intersect(camera.generateRay(x + 0.5f, y + 0.5f));
            if (!hit || (hit->shape != nullptr && hit->shape->closed)) continue;  // flat surfaces only
            const Vec3 toLight = scene.lights[0]->position() - hit->point;
            if (glm::dot(toLight, hit->normal) * glm::dot(-camera.generateRay(x + 0.5f, y + 0.5f).direction, hit->normal) <= 0.0f)
                continue;  // the light is on the other side of the wall
            if (geometry.occluded(spawnShadowRay(*hit, scene.lights[0]->position(), kNoSurfaceNormal, geometry.numerics()))) continue;
            object[static_cast<std::size_t>(y * w + x)] = static_cast<int>(hit->object);
        }
    }
    std::vector<bool> mask(object.size(), false);
    for (int y = 1; y + 1 < h; ++y) {
        for (int x = 1; x + 1 < w; ++x) {
            const int o = object[static_cast<std::size_t>(y * w + x)];
            bool flat = o >= 0;
            for (int dy = -1; dy <= 1 && flat; ++dy)
                for (int dx = -1; dx <= 1 && flat; ++dx) flat = object[static_cast<std::size_t>((y + dy) * w + x + dx)] == o;
            mask[static_cast<std::size_t>(y * w + x)] = flat;
        }
    }
    return mask;
}

bool differs(const Rgb& a, const Rgb& b) {
    for (int c = 0; c < 3; ++c) {
        const float x = std::clamp(a[c], 0.0f, 1.0f), y = std::clamp(b[c], 0.0f, 1.0f);
        if (!(std::fabs(x - y) <= 1.0f / 255.0f)) return true;
    }
    return false;
}

}  // namespace

void runRenderRow(const StressConfig& config, std::vector<ScoreRow>& rows) {
    const int size = config.quick ? 96 : 256;
    const Scene reference = cornellRoom(1.0f, size);
    const std::vector<bool> litFlat = litFlatMask(reference);
    const auto litFlatCount = static_cast<double>(std::count(litFlat.begin(), litFlat.end(), true));
    for (const bool robust : {true, false}) {
        const NumericsOptions numerics = robust ? NumericsOptions{} : NumericsOptions::naive();
        const std::vector<Rgb> base = renderBeauty(reference, numerics);
        double worstPercent = 0, inLitFlat = 0;
        std::string detail;
        for (const float scale : {1e-3f, 1e3f, 1e5f}) {
            const std::vector<Rgb> image = renderBeauty(cornellRoom(scale, size), numerics);
            double different = 0, differentLitFlat = 0;
            for (std::size_t i = 0; i < image.size(); ++i) {
                if (!differs(image[i], base[i])) continue;
                ++different;
                differentLitFlat += litFlat[i];
            }
            worstPercent = std::max(worstPercent, 100.0 * different / static_cast<double>(image.size()));
            inLitFlat += differentLitFlat;
            char buffer[96];
            std::snprintf(buffer, sizeof buffer, "%s: %.0f px (%.0f lit flat); ", stress::powerLabel(scale).c_str(),
                          different, differentLitFlat);
            detail += buffer;
        }
        const std::string setup = std::to_string(size) + "x" + std::to_string(size) + ", " +
                                  std::to_string(static_cast<long long>(litFlatCount)) + " lit flat px; ";
        rows.push_back({"render-level acne", robust ? "robust" : "naive", "float", "pixels off by >1/255, % (worst scale)",
                        worstPercent, 0.1, setup + detail});
        rows.push_back({"render-level acne", robust ? "robust" : "naive", "float", "of those in lit flat regions, pixels",
                        inLitFlat, 0.0, "scales 1e-3, 1e3, 1e5 against 1"});
    }
}

}  // namespace lightpath
