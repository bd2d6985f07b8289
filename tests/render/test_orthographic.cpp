// The orthographic camera (scene/camera.h) against references that do not come from it: a film
// laid out by hand (eye + u right + v up, the ray along the view) with a Lambertian ball's shading
// worked out per point, the pinhole-free inverse of the film map, and the integrators against each
// other, bdpt with its light-tracing strategies out (an orthographic camera cannot be joined to).
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "film/aov_presets.h"
#include "film/aov_set.h"
#include "integrators/registry.h"
#include "render/renderer.h"
#include "scene/camera.h"
#include "scene/scene_loader.h"
#include "../support/material_harness.h"
#include "../support/paired_agreement.h"

namespace lightpath {
namespace orthographic_test {

// A ball of radius 1 at the origin, kd 0.8, under parallel light along the view with E = pi: a
// point whose normal is at theta to the view reflects 0.8 cos theta, and cos theta = sqrt(1 - rho^2)
// at distance rho from the ball's axis on the film.
const char* const kBall = R"(
[camera]
projection = "orthographic"
eye = [0, 0, 5]
look_at = [0, 0, 0]
height = 3
resolution = [48, 36]
[materials.matte]
kd = 0.8
[[spheres]]
center = [0, 0, 0]
radius = 1
material = "matte"
[[lights]]
type = "directional"
direction = [0, 0, -1]
irradiance = 3.141592653589793
)";

Scene ballScene() { return loadSceneFromText(kBall, LIGHTPATH_SOURCE_DIR "/tests/render/data/orthographic.toml"); }

TEST_CASE("orthographic camera: parallel rays from a film of the given height, centred on the eye") {
    CameraDescription description;
    description.eye = {1, 2, 3};
    description.lookAt = {1, 2, -7};
    description.projection = Projection::Orthographic;
    description.orthographicHeight = 4.0f;
    description.width = 200;
    description.height = 100;
    const Camera camera(description);
    CHECK(camera.orthographic());
    CHECK(!camera.connectible());
    // By hand: the film spans x in [1 - 4, 1 + 4] (aspect 2) and y in [2 - 2, 2 + 2] at z = 3.
    const Ray corner = camera.generateRay(0.0f, 0.0f), centre = camera.generateRay(100.0f, 50.0f),
              last = camera.generateRay(200.0f, 100.0f);
    CHECK(corner.origin.x == doctest::Approx(-3.0));
    CHECK(corner.origin.y == doctest::Approx(4.0));
    CHECK(last.origin.x == doctest::Approx(5.0));
    CHECK(last.origin.y == doctest::Approx(0.0));
    CHECK(centre.origin.x == doctest::Approx(1.0));
    CHECK(centre.origin.y == doctest::Approx(2.0));
    for (const Ray& ray : {corner, centre, last}) {
        CHECK(ray.origin.z == doctest::Approx(3.0));
        CHECK(ray.direction == Vec3(0, 0, -1));
    }
    // A point anywhere along a ray projects to the film position the ray came from; behind the
    // film it is not seen.
    const Vec3 far = camera.generateRay(37.5f, 81.25f).origin + Vec3(0, 0, -50);
    const auto film = camera.project(far);
    REQUIRE(film);
    CHECK(film->x == doctest::Approx(37.5));
    CHECK(film->y == doctest::Approx(81.25));
    CHECK(!camera.project(Vec3(1, 2, 4)));
    CHECK(camera.importance(Vec3(0, 0, -1)) == 0.0f);
}

TEST_CASE("orthographic camera: a Lambertian ball under light along the view shows 0.8 cos theta, pixel by pixel") {
    const Scene scene = ballScene();
    RenderOptions options;
    options.integrator = "raycast";
    options.samplesPerPixel = 64;
    const Film film = Renderer(scene, AovSet(classesSet()), options).render().film;
    REQUIRE(film.width() == 48);
    REQUIRE(film.height() == 36);
    // The film by hand: pixel (x, y) covers u in [-2, 2] (aspect 4/3 of height 3), v in [1.5, -1.5].
    constexpr int kGrid = 16;
    double worst = 0.0, sum = 0.0, expectedSum = 0.0;
    int compared = 0;
    for (int y = 0; y < 36; ++y)
        for (int x = 0; x < 48; ++x) {
            double expected = 0.0;
            int inside = 0;
            for (int j = 0; j < kGrid; ++j)
                for (int i = 0; i < kGrid; ++i) {
                    const double u = (2.0 * (x + (i + 0.5) / kGrid) / 48.0 - 1.0) * 2.0;
                    const double v = (1.0 - 2.0 * (y + (j + 0.5) / kGrid) / 36.0) * 1.5;
                    const double rho2 = u * u + v * v;
                    inside += rho2 < 1.0;
                    expected += rho2 < 1.0 ? 0.8 * std::sqrt(1.0 - rho2) : 0.0;
                }
            expected /= kGrid * kGrid;
            const double value = film.at(0, x, y).g;
            sum += value;
            expectedSum += expected;
            if (inside != 0 && inside != kGrid * kGrid) continue;  // the silhouette: sampled differently
            worst = std::max(worst, std::abs(value - expected));
            ++compared;
        }
    CAPTURE(worst);
    CHECK(compared > 1500);
    // Inside, the pixel's own sample positions against the grid: the shading's curvature only.
    CHECK(worst < 4e-3);
    // The whole image, silhouette included: the ball's projected area is pi r^2 at every distance.
    CHECK(sum / expectedSum == doctest::Approx(1.0).epsilon(0.005).scale(0));
}

TEST_CASE("orthographic camera: the path tracer and bdpt, without light tracing, agree on a box (t-test)" *
          doctest::test_suite("statistical")) {
    Scene scene = loadScene(LIGHTPATH_SOURCE_DIR "/tests/render/data/cornell-orthographic.toml");
    scene.camera.width = scene.camera.height = 32;
    // Every camera sample walks from a light too (the pilot might choose none here, leaving the
    // joins untested), so bdpt's joins s, t >= 2 carry light and weigh out its light tracing.
    RenderOptions options;
    options.integrator = "bdpt";
    options.samplesPerPixel = 256;
    options.maxDepth = 5;
    options.seed = 17;
    ParameterValues values(findIntegrator("bdpt")->schema);
    values.set("light-walk-fraction", 1.0);
    options.integratorParameters = values;
    const Film bdpt = Renderer(scene, AovSet(classesSet()), options).render().film;
    // The same seed: common random numbers make the paired differences small (test_bdpt.cpp).
    test::checkPairedAgreement(bdpt, test::renderClassesFilm(scene, "path", 256, 17), 0.001);
}

TEST_CASE("orthographic camera: bdpt's light walks beyond one per camera sample, which only splat, are not taken") {
    Scene scene = loadScene(LIGHTPATH_SOURCE_DIR "/tests/render/data/cornell-orthographic.toml");
    scene.camera.width = scene.camera.height = 12;
    const auto render = [&](double fraction) {
        RenderOptions options;
        options.integrator = "bdpt";
        options.samplesPerPixel = 4;
        options.seed = 3;
        ParameterValues values(findIntegrator("bdpt")->schema);
        values.set("light-walk-fraction", fraction);
        options.integratorParameters = values;
        return Renderer(scene, AovSet(classesSet()), options).render();
    };
    const RenderResult one = render(1.0), four = render(4.0);
    for (int y = 0; y < 12; ++y)
        for (int x = 0; x < 12; ++x) CHECK(four.film.at(0, x, y) == one.film.at(0, x, y));
    CHECK(four.stats.rays.total() == one.stats.rays.total());
}

}  // namespace orthographic_test
}  // namespace lightpath
