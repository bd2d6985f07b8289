// The spot and directional lights (src/lights/spot_light.cpp, directional_light.cpp) against closed
// forms, and through light tracing: bdpt and photon mapping reach the path tracer's image only if
// sampleEmission(), its densities and bdpt's weights of a light at infinity are right.
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "accel/scene_geometry.h"
#include "film/aov_presets.h"
#include "film/aov_set.h"
#include "render/renderer.h"
#include "scene/scene_loader.h"
#include "schema/parameter_values.h"
#include "integrators/bdpt_vertex.h"
#include "integrators/registry.h"
#include "lights/light_set.h"
#include "../support/film_checks.h"

namespace lightpath {
namespace {

// A Lambertian floor (kd alone: albedo kd) seen from straight above, 6 m up, through a 0.2° field
// of view: every pixel sees the floor within 1 cm of the origin, where a spot's cone varies by
// under a part in a thousand (through 2°, 10 cm, the mean over the pixels was 5.6% above the
// value at the origin on the cone's ramp).
constexpr const char* kFloor = R"(
[camera]
eye = [0, 6, 0.001]
look_at = [0, 0, 0]
fov = 0.2
resolution = [8, 8]

[materials.matte]
kd = 0.5

[[planes]]
point = [0, 0, 0]
normal = [0, 1, 0]
material = "matte"
)";

double meanGreen(const Film& film) {
    double sum = 0.0;
    for (int y = 0; y < film.height(); ++y)
        for (int x = 0; x < film.width(); ++x) sum += film.at(0, x, y).g;
    return sum / (film.width() * film.height());
}

double renderFloor(const std::string& light, const char* integrator, float fov = 0.2f, int spp = 1) {
    Scene scene = loadSceneFromText(std::string(kFloor) + light, "punctual-floor.toml");
    scene.camera.verticalFovDegrees = fov;
    RenderOptions options;
    options.integrator = integrator;
    options.samplesPerPixel = spp;
    return meanGreen(Renderer(scene, AovSet(classesSet()), options).render().film);
}

constexpr double kDegree = M_PI / 180.0;

// glTF's cone (KHR_lights_punctual appendix): t = (cos th - cos outer) / (cos inner - cos outer)
// clamped to [0, 1], squared. Evaluated here by hand, apart from the light's code.
double gltfCone(double theta, double inner, double outer) {
    const double t = (std::cos(theta) - std::cos(outer)) / (std::cos(inner) - std::cos(outer));
    const double clamped = t < 0.0 ? 0.0 : t > 1.0 ? 1.0 : t;
    return clamped * clamped;
}

TEST_CASE("a spot light at angle theta to its axis lights a Lambertian floor as kd I cone(theta) cos(theta) / d^2") {
    // The spot 2 m above the floor, pointing straight down, moved sideways by 2 tan(theta): the
    // origin sees it at theta off its axis, at d = 2 / cos(theta), its rays at theta to the normal.
    // Radiance kd / pi * pi I cone(theta) / d^2 * cos(theta) (radiant intensity pi I).
    const double intensity = 3.0, inner = 20.0 * kDegree, outer = 40.0 * kDegree;
    for (const double degrees : {10.0, 25.0, 30.0, 35.0, 50.0}) {
        const double theta = degrees * kDegree, d = 2.0 / std::cos(theta);
        const std::string light = "[[lights]]\ntype = \"spot\"\nposition = [" + std::to_string(2.0 * std::tan(theta)) +
                                  ", 2, 0]\ndirection = [0, -1, 0]\nintensity = 3\ncone_angle = 40\nfalloff_start = 20\n";
        const double expected = 0.5 * intensity * gltfCone(theta, inner, outer) * std::cos(theta) / (d * d);
        for (const char* integrator : {"raycast", "path"}) {
            CAPTURE(degrees);
            CAPTURE(integrator);
            const double value = renderFloor(light, integrator);
            if (degrees > 40.0) CHECK(value == 0.0);
            else CHECK(value == doctest::Approx(expected).epsilon(0.005).scale(0));
        }
    }
}

// `explain` under ray casting: Szymczak's factors with the spot's cone apart, so I is the scene
// file's intensity and the product is the term.
TEST_CASE("explain: a spot's term is kd, N.L, I, its cone and attenuation, multiplying to the value") {
    const double theta = 30.0 * kDegree;
    Scene scene = loadSceneFromText(std::string(kFloor) + "[[lights]]\ntype = \"spot\"\nposition = [" +
                                        std::to_string(2.0 * std::tan(theta)) +
                                        ", 2, 0]\nintensity = 3\ncone_angle = 40\nfalloff_start = 20\n",
                                    "punctual-explain.toml");
    RenderOptions options;
    options.integrator = "raycast";
    const auto log = Renderer(scene, AovSet(std::vector<lpe::NamedExpression>{}), options).explainPixel(4, 4);
    int checked = 0;
    for (const LoggedContribution& c : log) {
        if (!(c.value.g > 0.0f)) continue;
        REQUIRE(c.factorCount == 5);
        const char* names[] = {"kd", "N.L", "I", "cone", "attenuation"};
        Rgb product{1.0f};
        for (std::size_t f = 0; f < 5; ++f) {
            CHECK(std::string(c.factors[f].name) == names[f]);
            product *= c.factors[f].value;
        }
        CHECK(c.factors[2].value.g == doctest::Approx(3.0).epsilon(1e-4));
        // The axis is vertical, so the angle off it is the angle of incidence, whose cosine is N.L.
        const double offAxis = std::acos(double(c.factors[1].value.g));
        CHECK(c.factors[3].value.g == doctest::Approx(gltfCone(offAxis, 20.0 * kDegree, 40.0 * kDegree)).epsilon(1e-3));
        CHECK(c.factors[3].value.g < 0.5f);  // between the cones: the ramp
        CHECK(product.g == doctest::Approx(c.value.g).epsilon(1e-5));
        ++checked;
    }
    CHECK(checked == 1);
}

TEST_CASE("a directional light of irradiance E at theta to a Lambertian floor: radiance kd / pi E cos(theta)") {
    for (const double degrees : {0.0, 30.0, 60.0}) {
        const double theta = degrees * kDegree;
        const std::string light = "[[lights]]\ntype = \"directional\"\nirradiance = 2\ndirection = [" +
                                  std::to_string(std::sin(theta)) + ", " + std::to_string(-std::cos(theta)) + ", 0]\n";
        const double expected = 0.5 / M_PI * 2.0 * std::cos(theta);
        for (const char* integrator : {"raycast", "path"}) {
            CAPTURE(degrees);
            CAPTURE(integrator);
            CHECK(renderFloor(light, integrator) == doctest::Approx(expected).epsilon(1e-4).scale(0));
        }
        // The floor is a plane, unbounded: the emission disk covers the eye's neighbourhood only
        // (the scene has no bounded shape), so the floor seen through 60° gets its light by light
        // sampling alone, and bdpt must give that strategy the whole weight there. 64 samples a
        // pixel: its other strategies' noise is 3.7% of the mean at 1 (0.007% at 256).
        CAPTURE(degrees);
        CHECK(renderFloor(light, "bdpt", 60.0f, 64) == doctest::Approx(expected).epsilon(0.02).scale(0));
    }
}

// A closed box open to the camera, bounded (triangles): light bounces between floor, back wall and
// side wall, so light walks (bdpt's s >= 2, photons) carry a share of every pixel.
constexpr const char* kRoom = R"(
[camera]
eye = [0, 1, 3.5]
look_at = [0, 0.8, 0]
fov = 50
resolution = [16, 16]

[materials.matte]
kd = 0.6

[[triangles]]
material = "matte"
vertices = [[-1.5, 0, -1.5], [1.5, 0, 1.5], [1.5, 0, -1.5]]
[[triangles]]
material = "matte"
vertices = [[-1.5, 0, -1.5], [-1.5, 0, 1.5], [1.5, 0, 1.5]]
[[triangles]]
material = "matte"
vertices = [[-1.5, 0, -1.5], [1.5, 0, -1.5], [1.5, 3, -1.5]]
[[triangles]]
material = "matte"
vertices = [[-1.5, 0, -1.5], [1.5, 3, -1.5], [-1.5, 3, -1.5]]
[[triangles]]
material = "matte"
vertices = [[-1.5, 0, -1.5], [-1.5, 3, -1.5], [-1.5, 3, 1.5]]
[[triangles]]
material = "matte"
vertices = [[-1.5, 0, -1.5], [-1.5, 3, 1.5], [-1.5, 0, 1.5]]
)";

constexpr const char* kSunDeclaration = R"(
[[lights]]
type = "directional"
name = "sun"
direction = [-0.5, -1, -0.6]
irradiance = 2
)";

Film renderRoom(const std::string& light, const char* integrator, int spp) {
    const Scene scene = loadSceneFromText(std::string(kRoom) + light, "punctual-room.toml");
    RenderOptions options;
    options.integrator = integrator;
    options.samplesPerPixel = spp;
    if (std::string(integrator) == "photon") {
        ParameterValues values(findIntegrator("photon")->schema);
        values.set("photons", 50000);
        options.integratorParameters = values;
    }
    return Renderer(scene, AovSet(classesSet()), options).render().film;
}

// bdpt weighs strategies by each one's area density of a vertex: under parallel rays a receiver's
// is the emission disk's density times |cos| at the receiver, at any distance (no 1/d^2: the rays
// do not spread). A wrong density here biases nothing (the weights still sum to 1) but hands the
// light walks a weight they do not earn, so it is checked by itself.
TEST_CASE("under a directional light, a receiver's area density is the disk's density times |cos|, at any distance") {
    const Scene scene = loadSceneFromText(std::string(kRoom) + kSunDeclaration, "punctual-density.toml");
    const SceneGeometry geometry(scene.spheres, scene.planes, scene.triangles, {}, Accelerator::Bvh, {}, 0, scene.shapes);
    const LightSet lights(scene, geometry);
    REQUIRE(lights.all().size() == 1);
    const Light& sun = *lights.all()[0];
    REQUIRE(sun.atInfinity());
    const EmittedRay e = sun.sampleEmission({0.3f, 0.6f}, {0.5f, 0.5f});
    const BdptVertex y = lightVertex(sun, e.ray.origin, Vec3{0.0f}, e.pdfPosition, e.pdfPosition);
    const Vec3 normal = glm::normalize(Vec3{0.2f, 1.0f, 0.1f});
    for (const float distance : {0.5f, 3.0f, 10.0f}) {
        BdptVertex z;
        z.point = e.ray.at(distance);
        z.normal = normal;
        CAPTURE(distance);
        CHECK(toAreaDensity(e.pdfDirection, y, z) ==
              doctest::Approx(e.pdfDirection * std::fabs(glm::dot(normal, e.ray.direction))).epsilon(1e-5));
    }
}

constexpr const char* kSpot = R"(
[[lights]]
type = "spot"
name = "spot"
position = [0.5, 2.5, 0.5]
direction = [-0.3, -1, -0.4]
intensity = 4
cone_angle = 35
falloff_start = 15
)";

constexpr const char* kSun = kSunDeclaration;

TEST_CASE("spot and directional lights: bdpt and photon mapping (light walks from sampleEmission) agree with the path tracer" *
          doctest::test_suite("statistical")) {
    for (const char* light : {kSpot, kSun}) {
        CAPTURE(light);
        const Film path = renderRoom(light, "path", 256);
        const Film bdpt = renderRoom(light, "bdpt", 128);
        const Film photon = renderRoom(light, "photon", 64);
        CHECK(test::worstSumError(path) <= 1.0);
        CHECK(test::worstSumError(bdpt) <= 1.0);
        CHECK(test::worstSumError(photon) <= 1.0);
        const double reference = meanGreen(path);
        REQUIRE(reference > 0.0);
        CHECK(meanGreen(bdpt) == doctest::Approx(reference).epsilon(0.01));
        CHECK(meanGreen(photon) == doctest::Approx(reference).epsilon(0.03));
    }
}

}  // namespace
}  // namespace lightpath
