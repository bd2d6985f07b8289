#include "stress/non_finite_row.h"

#include <cmath>
#include <limits>

#include "film/aov_set.h"
#include "accel/scene_geometry.h"
#include "geometry/spawn_ray.h"
#include "lights/point_light.h"
#include "materials/phong_material.h"
#include "render/renderer.h"
#include "stress/sampling.h"
#include "stress/scene_objects.h"
#include "film/aov_presets.h"

namespace lightpath {
namespace {

bool finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }


// A floor, a glass ball seen from straight above (rays with zero x and z components, total
// internal reflection inside the ball), a mirror ball, and triangles of zero area: repeated
// vertices, collinear vertices, one point, and one so small its edge products underflow.
Scene hostileScene(int size) {
    Scene scene;
    scene.camera.eye = {0.0f, 6.0f, 0.0f};
    scene.camera.lookAt = {0.0f, 0.0f, 0.0f};
    scene.camera.up = {0.0f, 0.0f, -1.0f};
    scene.camera.width = scene.camera.height = size;
    scene.background = {0.2f, 0.3f, 0.5f};
    scene.ambient = {0.1f, 0.1f, 0.1f};
    PhongMaterial matte;
    matte.ka = matte.kd = {0.6f, 0.6f, 0.6f};
    matte.ks = {0.3f, 0.3f, 0.3f};
    PhongMaterial glass;
    glass.kt = {0.9f, 0.9f, 0.9f};
    glass.kr = {0.1f, 0.1f, 0.1f};
    glass.ior = 2.4f;  // diamond: a wide range of internal angles reflect totally
    PhongMaterial mirror;
    mirror.kr = {0.9f, 0.9f, 0.9f};
    scene.planes.push_back({{0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, stress::addObject(scene, "floor", matte)});
    scene.spheres.push_back({{0.0f, 1.0f, 0.0f}, 1.0f, stress::addObject(scene, "glass", glass)});
    scene.spheres.push_back({{1.8f, 0.7f, 0.9f}, 0.7f, stress::addObject(scene, "mirror", mirror)});
    const std::uint32_t flat = stress::addObject(scene, "degenerate", matte);
    const Vec3 a{-1.5f, 0.5f, 1.0f}, b{-0.5f, 0.5f, 2.0f};
    scene.triangles.push_back({a, a, b, flat});
    scene.triangles.push_back({a, b, 0.5f * (a + b), flat});
    scene.triangles.push_back({b, b, b, flat});
    scene.triangles.push_back({Vec3{1e-30f}, Vec3{2e-30f, 1e-30f, 1e-30f}, Vec3{1e-30f, 2e-30f, 1e-30f}, flat});
    scene.lights.push_back(PointLight{"key", {2.0f, 5.0f, 1.0f}, Rgb{1.0f}, Vec3{1.0f, 0.0f, 0.0f}});
    scene.lights.push_back(PointLight{"on-floor", {-2.0f, 0.0f, -2.0f}, Rgb{0.5f}, Vec3{1.0f, 0.0f, 0.0f}});
    return scene;
}

// Queries that must answer "no hit" or a finite hit, and spawned rays that must stay finite.
double hostileQueries(const Scene& scene, const NumericsOptions& numerics) {
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    const TriangleNormals zero{};
    const SceneGeometry geometry(scene.spheres, scene.planes, scene.triangles, numerics, Accelerator::BruteForce,
                                 std::vector<TriangleNormals>(scene.triangles.size(), zero));
    const std::vector<Ray> rays = {
        {{nan, 1.0f, 0.0f}, {0.0f, -1.0f, 0.0f}},  {{0.0f, 3.0f, 0.0f}, {nan, nan, nan}},
        {{0.0f, 3.0f, 0.0f}, {0.0f, 0.0f, 0.0f}},  {{0.0f, 3.0f, 0.0f}, {0.0f, -inf, 0.0f}},
        {{inf, 3.0f, 0.0f}, {-1.0f, 0.0f, 0.0f}},  {{0.0f, 3.0f, 0.0f}, {0.0f, -1.0f, 0.0f}},
        {{-1.0f, 0.5f, 1.5f}, {1.0f, 0.0f, 0.0f}}, {{-3.0f, 0.5f, 1.0f}, {1.0f, 0.0f, 0.0f}},
    };
    double bad = 0;
    for (const Ray& ray : rays) {
        geometry.occluded(ray);
        const auto hit = geometry.intersect(ray);
        if (!hit) continue;
        bad += !std::isfinite(hit->t) || !finite(hit->point) || !finite(hit->shadingNormal);
        // Secondary rays from it, including one along a zero-length normal.
        SurfaceHit degenerate = *hit;
        degenerate.normal = Vec3{0.0f};
        for (const SurfaceHit& from : {*hit, degenerate}) {
            bad += !finite(spawnRay(from, {0.0f, 1.0f, 0.0f}, numerics).origin);
            const Ray shadow = spawnShadowRay(from, from.point, kNoSurfaceNormal, numerics);  // a light on the point itself
            bad += !finite(shadow.origin) || std::isnan(shadow.tMax);
        }
    }
    return bad;
}

}  // namespace

void runNonFiniteRow(const StressConfig& config, std::vector<ScoreRow>& rows) {
    const Scene scene = hostileScene(config.quick ? 63 : 161);  // odd: centre rays have zero components
    const AovSet aovs(classesSet());
    for (const bool robust : {true, false}) {
        RenderOptions options;
        options.numerics = robust ? NumericsOptions{} : NumericsOptions::naive();
        options.threads = 1;
        options.samplesPerPixel = 2;
        options.maxDepth = 8;
        const RenderResult result = Renderer(scene, aovs, options).render();
        double nonFinitePixels = 0;
        for (const Rgb& v : result.film.interleaved()) nonFinitePixels += !finite(v);
        const double badQueries = hostileQueries(scene, options.numerics);
        const double dropped = static_cast<double>(result.stats.rays.nonFinite);
        char detail[160];
        std::snprintf(detail, sizeof detail,
                      "%.0f non-finite pixel values, %.0f contributions dropped by the guard, %.0f bad hits/spawns "
                      "of NaN/Inf/zero rays",
                      nonFinitePixels, dropped, badQueries);
        rows.push_back({"non-finite", robust ? "robust" : "naive", "float", "NaN/Inf samples, bad hits",
                        nonFinitePixels + dropped + badQueries, 0.0, detail});
    }
}

}  // namespace lightpath
