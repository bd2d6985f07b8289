// Degenerate but legal geometry renders without NaN, infinity or a crash: triangles without
// area, lights inside and on objects, coincident surfaces, a camera inside a sphere. Each scene
// is rendered by every integrator. No contribution may have been non-finite (the tracer drops
// and counts those, so the count is checked, not only the image), every layer of every pixel
// must be finite and non-negative, and the layers must still sum to the beauty.
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "film/aov_set.h"
#include "render/renderer.h"
#include "scene/scene_loader.h"
#include "film/aov_presets.h"
#include "../support/film_checks.h"

namespace lightpath {
namespace {

// A camera looking down -z at the origin, a grey floor at y = -1 and the materials the scenes use.
const std::string kStage = R"(
[camera]
eye = [0, 0, 4]
look_at = [0, 0, 0]
fov = 50
resolution = [32, 24]

[world]
ambient = 0.1
background = [0.05, 0.05, 0.1]

[materials.grey]
kd = 0.6
ks = 0.3
n = 20
[materials.mirror]
kd = 0.1
kr = 0.8
[materials.glass]
kt = 0.9
kr = 0.1
ior = 1.5
[materials.lamp]
emission = 5

[[planes]]
point = [0, -1, 0]
normal = [0, 1, 0]
material = "grey"
)";

const std::string kLamp = R"(
[[lights]]
name = "lamp"
position = [2, 3, 3]
intensity = 20
attenuation = [1, 0, 0.1]
)";

struct Verdict {
    bool finite = true, nonNegative = true;
    double worstSumError = 0.0;  // |layers - beauty| / tolerance; at most 1 passes
};

Verdict inspect(const Film& film) {
    Verdict verdict;
    for (const Rgb& v : film.interleaved()) {
        for (int c = 0; c < 3; ++c) {
            verdict.finite = verdict.finite && std::isfinite(v[c]);
            verdict.nonNegative = verdict.nonNegative && v[c] >= 0.0f;
        }
    }
    verdict.worstSumError = test::worstSumError(film);
    return verdict;
}

void checkRendersCleanly(const std::string& sceneText) {
    const Scene scene = loadSceneFromText(kStage + sceneText, "degenerate.toml");
    const AovSet aovs(classesSet());
    for (const char* integrator : {"raycast", "whitted", "path"}) {
        CAPTURE(integrator);
        RenderOptions options;
        options.integrator = integrator;
        options.samplesPerPixel = 4;
        options.threads = 1;
        const RenderResult result = Renderer(scene, aovs, options).render();
        CHECK(result.stats.rays.nonFinite == 0);
        const Verdict verdict = inspect(result.film);
        CHECK(verdict.finite);
        CHECK(verdict.nonNegative);
        CHECK(verdict.worstSumError <= 1.0);
    }
}

TEST_CASE("triangles without area are legal, never hit, and never a NaN") {
    checkRendersCleanly(kLamp + R"(
[[triangles]]
vertices = [[-1, 0, 0], [0, 0, 0], [1, 0, 0]]
material = "grey"
[[triangles]]
vertices = [[0, 0.5, 0], [0, 0.5, 0], [1, 1, 0]]
material = "mirror"
[[triangles]]
vertices = [[0.2, 0.2, 0], [0.2, 0.2, 0], [0.2, 0.2, 0]]
material = "glass"
[[triangles]]
vertices = [[-0.5, -0.5, 0], [-0.5, -0.5, 1e-30], [-0.5, -0.5, 2e-30]]
material = "grey"
[[triangles]]
name = "flat-lamp"
vertices = [[-1, 1, 0], [0, 1, 0], [1, 1, 0]]
material = "lamp"
)");
    const Scene scene = loadSceneFromText(kStage + R"(
[[triangles]]
vertices = [[-1, 0, 0], [0, 0, 0], [1, 0, 0]]
material = "grey"
)", "degenerate.toml");
    CHECK(scene.triangles.size() == 1);
    CHECK(scene.warnings.size() == 1);
}

TEST_CASE("a light inside an object: point and area lights enclosed, and a lamp on a surface") {
    SUBCASE("a point light inside an opaque ball and inside a glass ball") {
        checkRendersCleanly(R"(
[[lights]]
name = "caged"
position = [-1, 0, 0]
[[lights]]
name = "bulb"
position = [1, 0, 0]
[[spheres]]
center = [-1, 0, 0]
radius = 0.5
material = "grey"
[[spheres]]
center = [1, 0, 0]
radius = 0.5
material = "glass"
)");
    }
    SUBCASE("a sphere light inside a mirror ball, a quad light inside a glass ball") {
        checkRendersCleanly(R"(
[[lights]]
type = "sphere"
center = [-1, 0, 0]
radius = 0.2
radiance = 10
[[spheres]]
center = [-1, 0, 0]
radius = 0.6
material = "mirror"
[[lights]]
type = "quad"
corner = [0.9, -0.1, 0]
edge1 = [0.2, 0, 0]
edge2 = [0, 0.2, 0]
radiance = 10
[[spheres]]
center = [1, 0, 0]
radius = 0.6
material = "glass"
)");
    }
    SUBCASE("a point light exactly on a surface, with inverse-square attenuation") {
        checkRendersCleanly(R"(
[[lights]]
position = [0, -1, 0]
attenuation = [0, 0, 1]
[[lights]]
position = [0.5, 0, 0]
attenuation = [0, 1, 0]
[[spheres]]
center = [0, 0, 0]
radius = 0.5
material = "grey"
)");
    }
    SUBCASE("a quad light flush with the floor and coincident with a sphere light's centre") {
        checkRendersCleanly(R"(
[[lights]]
type = "quad"
corner = [-0.5, -1, -0.5]
edge1 = [0, 0, 1]
edge2 = [1, 0, 0]
radiance = 4
[[lights]]
type = "sphere"
center = [0, -1, 0]
radius = 0.3
radiance = 4
)");
    }
}

TEST_CASE("coincident surfaces: the same sphere twice, a triangle in a plane, back-to-back planes") {
    checkRendersCleanly(kLamp + R"(
[[spheres]]
center = [-1, 0, 0]
radius = 0.6
material = "mirror"
[[spheres]]
center = [-1, 0, 0]
radius = 0.6
material = "glass"
[[triangles]]
vertices = [[0, -1, -1], [2, -1, -1], [1, -1, 1]]
material = "mirror"
[[triangles]]
vertices = [[0, -1, -1], [2, -1, -1], [1, -1, 1]]
material = "glass"
[[planes]]
point = [0, 0, -3]
normal = [0, 0, 1]
material = "grey"
[[planes]]
point = [0, 0, -3]
normal = [0, 0, -1]
material = "mirror"
)");
}

TEST_CASE("a camera inside a glass ball and inside a mirror ball") {
    checkRendersCleanly(kLamp + R"(
[[spheres]]
center = [0, 0, 4]
radius = 1
material = "glass"
)");
    checkRendersCleanly(kLamp + R"(
[[spheres]]
center = [0, 0, 4]
radius = 0.5
material = "mirror"
)");
}

}  // namespace
}  // namespace lightpath
