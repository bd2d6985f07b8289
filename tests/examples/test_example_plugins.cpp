// The example plugins (examples/plugins/, docs/extending.md) work as a user meets them: a scene
// that names the example material and light loads, renders under the example integrator, and its
// AOVs sum to the beauty. The conformance kit (conformance_tests, which links them too) holds each
// to the contract of its family.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "accel/scene_geometry.h"
#include "film/aov_presets.h"
#include "film/aov_set.h"
#include "geometry/shape.h"
#include "../support/film_checks.h"
#include "render/renderer.h"
#include "scene/scene_loader.h"

namespace lightpath {
namespace {

// A rough floor under Warn's spotlight pointing straight down: its intensity pi I cos^n(theta)
// (n = 20) is a twentieth of the axis' at theta = 57° (2 m below the light: 3.1 m off centre).
constexpr const char* kScene = R"(
[camera]
eye = [0, 6, 0.001]
look_at = [0, 0, 0]
fov = 40
resolution = [32, 32]

[materials.rough]
type = "oren-nayar"
kd = 0.8
sigma = 30

[[planes]]
point = [0, 0, 0]
normal = [0, 1, 0]
material = "rough"

[[lights]]
type = "warn"
name = "warn"
position = [0, 2, 0]
direction = [0, -1, 0]
intensity = 3
exponent = 20
)";

// `fov` narrows the view (degrees): the scene's 40° makes a pixel 13 cm of floor.
Film renderExample(const AovSet& aovs, float fov = 40.0f) {
    Scene scene = loadSceneFromText(kScene, "example-plugins.toml");
    scene.camera.verticalFovDegrees = fov;
    RenderOptions options;
    options.integrator = "direct";
    options.samplesPerPixel = 2;
    return Renderer(scene, aovs, options).render().film;
}

TEST_CASE("the example material and light render under the example integrator, the AOVs sum to the beauty") {
    const Film film = renderExample(AovSet(classesSet()));
    CHECK(test::finiteNonNegative(film));
    CHECK(test::worstSumError(film) <= 1.0);
    // Under the light (the image's centre) the floor is lit; off its axis (a corner) the cos^n lobe
    // leaves it far darker.
    const Rgb centre = film.at(0, 16, 16), corner = film.at(0, 0, 0);
    CHECK(centre.g > 0.0f);
    CHECK(corner.g < 0.05f * centre.g);
}

// Straight below the light, wo = wi = the normal: Oren-Nayar's B term vanishes (theta = 0), so the
// floor reflects kd A / pi times the irradiance pi I / d^2 (lights/point_light.h's radiant intensity
// pi I): radiance kd A I / d^2, A = 1 - s / (2 (s + 0.33)), s = sigma^2 in radians.
// Seen through 0.2°, every pixel is within 1 cm of that point (through 40°, pixel (16, 16) spans
// 13 cm beside it, 3% darker).
TEST_CASE("straight below Warn's spotlight, the rough floor's radiance is kd A I / d^2") {
    const Film film = renderExample(AovSet(classesSet()), 0.2f);
    const double sigma = 30.0 * M_PI / 180.0, s = sigma * sigma;
    const double a = 1.0 - s / (2.0 * (s + 0.33));
    const double expected = 0.8 * a * 3.0 / (2.0 * 2.0);
    CHECK(film.at(0, 16, 16).g == doctest::Approx(expected).epsilon(1e-3).scale(0));
}

// The translucent sheet (examples/plugins/translucent_material.cpp) declares a diffuse transmission
// lobe <TD>, a kind no shipped material has. A point light 1 m behind the sheet, the camera 3 m
// in front, both on the sheet's axis: the centre pixel sees only light that passed through, in the
// AOV E<TD>L, none in E<RD>L. Its value by hand: the irradiance on the back, pi I / d^2 (radiant
// intensity pi I), times the transmission kt / pi: kt I / d^2 = 0.6 * 2 / 1 = 1.2.
constexpr const char* kSheetScene = R"(
[camera]
eye = [0, 0, 3]
look_at = [0, 0, 0]
fov = 40
resolution = [33, 33]

[materials.paper]
type = "translucent"
kd = 0.3
kt = 0.6

[[planes]]
point = [0, 0, 0]
normal = [0, 0, 1]
material = "paper"

[[lights]]
name = "behind"
position = [0, 0, -1]
intensity = 2
)";

std::size_t layerNamed(const Film& film, const std::string& name) {
    const auto& names = film.layerNames();
    const auto it = std::find(names.begin(), names.end(), name);
    REQUIRE(it != names.end());
    return std::size_t(it - names.begin());
}

TEST_CASE("a light behind the translucent sheet reaches the camera through <TD> under every integrator") {
    const Scene scene = loadSceneFromText(kSheetScene, "translucent-sheet.toml");
    const AovSet aovs(std::vector<lpe::NamedExpression>{parseNamedExpression("through=E<TD>L", 0),
                                                        parseNamedExpression("front=E<RD>L", 1)});
    for (const char* integrator : {"raycast", "whitted", "path", "bdpt"}) {
        INFO(integrator);
        RenderOptions options;
        options.integrator = integrator;
        options.samplesPerPixel = 1;
        const Film film = Renderer(scene, aovs, options).render().film;
        CHECK(test::finiteNonNegative(film));
        CHECK(test::worstSumError(film) <= 1.0);
        const Rgb through = film.at(layerNamed(film, "through"), 16, 16);
        CHECK(film.at(layerNamed(film, "front"), 16, 16) == Rgb{0.0f});
        if (std::string(integrator) == "bdpt") {
            // Light tracing adds its share by chance (splats): the estimate is only near the value.
            CHECK(through.g > 0.0f);
        } else {
            CHECK(through.g == doctest::Approx(0.6 * 2.0 / 1.0).epsilon(1e-4));
        }
    }
}

// The example shape (examples/plugins/cylinder_shape.cpp) against closed forms. Its record as the
// renderer holds it, from a scene that declares it alone.
ShapeRecord cylinderRecord(const std::string& declaration) {
    const Scene scene = loadSceneFromText("[materials.grey]\nkd = 0.5\n[[cylinders]]\nmaterial = \"grey\"\n" + declaration,
                                          "cylinder.toml");
    const SceneGeometry geometry(scene.spheres, scene.planes, {}, {}, Accelerator::BruteForce, {}, 0, scene.shapes);
    REQUIRE(geometry.shapes().size() == 1);
    return geometry.shapes().front();
}

float hitAlong(const ShapeRecord& record, const Vec3& origin, const Vec3& direction, float tMin = 0.0f) {
    Ray ray;
    ray.origin = origin;
    ray.direction = direction;
    return record.ops->intersect(ray, record, tMin, NumericsOptions{});
}

TEST_CASE("a ray through the cylinder's axis meets its wall at the distance minus and plus the radius, its area is 2 pi r h") {
    // Upright: base at the origin, 2 m high, radius 0.5; a ray 3 m from the axis, at mid-height.
    const ShapeRecord upright = cylinderRecord("base = [0, 0, 0]\ntop = [0, 2, 0]\nradius = 0.5\n");
    CHECK(hitAlong(upright, {3, 1, 0}, {-1, 0, 0}) == doctest::Approx(2.5));
    CHECK(hitAlong(upright, {3, 1, 0}, {-1, 0, 0}, 2.6f) == doctest::Approx(3.5));  // the far wall
    CHECK(hitAlong(upright, {0, 1, 0}, {0, 0, 1}) == doctest::Approx(0.5));          // from inside
    CHECK(hitAlong(upright, {3, 2.5f, 0}, {-1, 0, 0}) < 0.0f);                         // above the top
    CHECK(hitAlong(upright, {0, 3, 0}, {0, -1, 0}) < 0.0f);  // along the axis, through both open ends
    CHECK(upright.ops->area(upright) == doctest::Approx(2.0 * M_PI * 0.5 * 2.0).epsilon(1e-12));
    // Oblique: the axis (1, 1, 1) / sqrt 3, height sqrt 3; from 3 m off the axis's midpoint across it.
    const ShapeRecord oblique = cylinderRecord("base = [0, 0, 0]\ntop = [1, 1, 1]\nradius = 0.5\n");
    const Vec3 across = glm::normalize(Vec3(1, -1, 0));
    CHECK(hitAlong(oblique, Vec3(0.5f) + 3.0f * across, -across) == doctest::Approx(2.5).epsilon(1e-6));
    CHECK(oblique.ops->area(oblique) == doctest::Approx(2.0 * M_PI * 0.5 * std::sqrt(3.0)).epsilon(1e-6));
}

TEST_CASE("a cylinder whose top is its base is refused where the scene file says so") {
    std::string message;
    try {
        cylinderRecord("base = [0, 1, 0]\ntop = [0, 1, 0]\nradius = 1\n");
    } catch (const SceneError& e) {
        message = e.what();
    }
    CHECK(message.find("cylinders[0].top: expected a point other than base") != std::string::npos);
}

TEST_CASE("the cylinder's tessellation: triangles wound with the outward normal, edges at most edgeLength") {
    const ShapeRecord upright = cylinderRecord("base = [0, 0, 0]\ntop = [0, 2, 0]\nradius = 0.5\n");
    constexpr float kEdge = 0.3f;
    std::vector<Triangle> triangles;
    upright.ops->tessellate(upright, kEdge, triangles);
    REQUIRE(!triangles.empty());
    int inward = 0, long_ = 0;
    for (const Triangle& t : triangles) {
        const Vec3 centroid = (t.a + t.b + t.c) / 3.0f;
        const Vec3 outward(centroid.x, 0.0f, centroid.z);  // from the axis, the y axis
        if (!(glm::dot(glm::cross(t.b - t.a, t.c - t.a), outward) > 0.0f)) ++inward;
        for (const float edge : {glm::distance(t.a, t.b), glm::distance(t.b, t.c), glm::distance(t.c, t.a)})
            if (edge > kEdge * (1.0f + 1e-6f)) ++long_;
    }
    CHECK(inward == 0);
    CHECK(long_ == 0);
}

// A point light on the axis of a Lambertian cylinder (radius 1, from y = -2 to 2), 0.5 m above the
// camera's height, both inside it; the centre pixel sees the wall at (0, 0, -1), from the inside,
// where the light is d^2 = 1.25 away at cos theta = 1 / sqrt 1.25. Its radiance in E<RD>L under
// raycast by hand: kd/pi times the irradiance pi I cos theta / d^2 (the point light's radiant
// intensity is pi I, as above, and its attenuation 1/d^2 as declared): kd I cos theta / d^2
// = 0.5 * 2 / 1.25^1.5.
constexpr const char* kCylinderScene = R"(
[camera]
eye = [0, 0, 0.5]
look_at = [0, 0, -1]
fov = 40
resolution = [33, 33]

[materials.grey]
kd = 0.5

[[cylinders]]
base = [0, -2, 0]
top = [0, 2, 0]
radius = 1
material = "grey"

[[lights]]
name = "axis"
position = [0, 0.5, 0]
intensity = 2
attenuation = [0, 0, 1]
)";

TEST_CASE("a point light on the cylinder's axis: the wall's radiance is kd I cos theta / d^2") {
    const Scene scene = loadSceneFromText(kCylinderScene, "cylinder-light.toml");
    const AovSet aovs(std::vector<lpe::NamedExpression>{parseNamedExpression("direct=E<RD>L", 0)});
    RenderOptions options;
    options.integrator = "raycast";
    options.samplesPerPixel = 1;
    const Film film = Renderer(scene, aovs, options).render().film;
    CHECK(test::finiteNonNegative(film));
    CHECK(film.at(layerNamed(film, "direct"), 16, 16).g == doctest::Approx(0.5 * 2.0 / std::pow(1.25, 1.5)).epsilon(1e-4));
}

}  // namespace
}  // namespace lightpath
