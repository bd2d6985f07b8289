// The path tracer against references that do not come from it: the inverse-square law, Lambert's
// closed-form irradiance of a polygon, and the furnace closed forms, judged per AOV by Student's
// t-test on independent pixels (and shown to reject a reference 5% off).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "film/aov_set.h"
#include "render/renderer.h"
#include "scene_builder.h"
#include "../support/paired_agreement.h"
#include "../support/pinhole_reference.h"
#include "../support/statistics.h"
#include "film/aov_presets.h"

namespace lightpath {
namespace {

using test::studentTTest;

constexpr double kPValue = 0.001;  // rejection threshold of one test

// The point of the floor y = 0 that pixel (i, j) sees.
glm::dvec3 floorPoint(const CameraDescription& c, int i, int j) {
    const glm::dvec3 d = test::pixelDirection(c, i, j);
    return glm::dvec3(c.eye) + (-double(c.eye.y) / d.y) * d;
}

Film renderPath(const Scene& scene, const std::vector<lpe::NamedExpression>& set, int spp, int maxDepth = 64) {
    const AovSet aovs(set);
    RenderOptions options;
    options.integrator = "path";
    options.samplesPerPixel = spp;
    options.maxDepth = maxDepth;
    options.seed = 7;
    return Renderer(scene, aovs, options).render().film;
}

// The camera looks down on the floor from below any light, so nothing hides the floor.
Scene floorScene(float albedo) {
    Scene scene;
    scene.camera = test::centredCamera({0.3f, 1.0f, 0.2f}, {0.3f, 0, 0.2f}, {0, 0, -1}, 31);
    scene.camera.verticalFovDegrees = 60.0f;
    PhongMaterial floor;
    floor.name = "floor";
    floor.kd = Rgb{albedo};
    test::addPlane(scene, "floor", test::addMaterial(scene, floor), {0, 0, 0}, {0, 1, 0});
    return scene;
}

// A point light of intensity I has radiant intensity pi I, so Lambert's (rho/pi) pi I cos(theta)
// falloff(d) is the lecture's kd (N.L) I / (c0 + c1 d + c2 d^2) exactly: the physical inverse-square
// law for [0, 0, 1] and the lecture's attenuation for anything else.
double litFloor(const Scene& scene, const glm::dvec3& light, const glm::dvec3& attenuation) {
    const Film film = renderPath(scene, {}, 1);
    double worst = 0.0;
    for (int j = 0; j < film.height(); ++j) {
        for (int i = 0; i < film.width(); ++i) {
            const glm::dvec3 p = floorPoint(scene.camera, i, j);
            const glm::dvec3 toLight = light - p;
            const double d = glm::length(toLight);
            const double falloff = 1.0 / (attenuation.x + attenuation.y * d + attenuation.z * d * d);
            const double expected = 0.6 * 3.0 * (toLight.y / d) * falloff;
            worst = std::max(worst, std::fabs(film.at(0, i, j).g - expected) / expected);
        }
    }
    return worst;
}

TEST_CASE("path: a Lambertian plane under a point light is kd I cos(theta) / (c0 + c1 d + c2 d^2) at every pixel") {
    const glm::dvec3 light{0.7, 2.5, -0.4};
    for (const glm::dvec3 attenuation : {glm::dvec3{0, 0, 1}, glm::dvec3{1, 0.1, 0.01}, glm::dvec3{1, 0, 0}}) {
        CAPTURE(attenuation.y);
        Scene scene = floorScene(0.6f);
        scene.lights.push_back(PointLight{"key", Vec3(light), Rgb{3.0f}, Vec3(attenuation)});
        CHECK(litFloor(scene, light, attenuation) < 1e-4);
    }
}

// Lambert's formula for the irradiance at p (normal n) from a uniform polygon of radiance Le:
// E = Le/2 * sum over edges of angle(v_i, v_i+1) * n . normalize(v_i x v_i+1).
double polygonIrradiance(const glm::dvec3& p, const glm::dvec3& n, const std::vector<glm::dvec3>& polygon, double le) {
    double sum = 0.0;
    for (std::size_t k = 0; k < polygon.size(); ++k) {
        const glm::dvec3 a = glm::normalize(polygon[k] - p);
        const glm::dvec3 b = glm::normalize(polygon[(k + 1) % polygon.size()] - p);
        sum += std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0)) * glm::dot(n, glm::normalize(glm::cross(a, b)));
    }
    return le / 2.0 * std::fabs(sum);
}

TEST_CASE("path: a plane under a quad light matches Lambert's polygon irradiance (t-test)") {
    Scene scene = floorScene(0.5f);
    PhongMaterial lamp;
    lamp.name = "lamp";
    lamp.emission = Rgb{4.0f};
    const std::uint32_t lampMaterial = test::addMaterial(scene, lamp);
    const std::uint32_t lampObject = test::addObject(scene, "quad", lampMaterial);
    // A 1 x 0.6 quad at height 1.5 facing down (clockwise seen from above: normal -y).
    const Vec3 q0{-0.5f, 1.5f, -0.3f}, q1{0.5f, 1.5f, -0.3f}, q2{0.5f, 1.5f, 0.3f}, q3{-0.5f, 1.5f, 0.3f};
    scene.triangles.push_back({q0, q1, q2, lampObject});
    scene.triangles.push_back({q0, q2, q3, lampObject});
    REQUIRE(glm::normalize(glm::cross(q1 - q0, q2 - q0)).y < 0.0f);

    const Film film = renderPath(scene, {{"direct", "E D <O.'quad'>"}}, 8, 3);
    std::vector<double> differences, differencesWrong;
    const std::vector<glm::dvec3> polygon{glm::dvec3(q0), glm::dvec3(q1), glm::dvec3(q2), glm::dvec3(q3)};
    for (int j = 0; j < film.height(); ++j) {
        for (int i = 0; i < film.width(); ++i) {
            const glm::dvec3 p = floorPoint(scene.camera, i, j);
            const double expected = 0.5 / M_PI * polygonIrradiance(p, {0, 1, 0}, polygon, 4.0);
            differences.push_back(film.at(1, i, j).r - expected);
            differencesWrong.push_back(film.at(1, i, j).r - 1.05 * expected);
        }
    }
    double meanDifference = 0.0;
    for (double d : differences) meanDifference += d / double(differences.size());
    CAPTURE(meanDifference);
    CHECK(studentTTest(differences, 0.0) > kPValue);
    CHECK(studentTTest(differencesWrong, 0.0) < kPValue);
}

// A closed sphere seen from its centre, split by the classes AOVs.
Scene furnace(float albedo, Rgb emission) {
    Scene scene;
    scene.camera = test::centredCamera({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 33);
    scene.camera.verticalFovDegrees = 90.0f;
    PhongMaterial wall;
    wall.name = "wall";
    wall.kd = Rgb{albedo};
    wall.emission = emission;
    test::addSphere(scene, "furnace", test::addMaterial(scene, wall), {0, 0, 0}, 1.0f);
    return scene;
}

void checkLayer(const Film& film, const std::string& name, double expected) {
    const auto& names = film.layerNames();
    const std::size_t layer = static_cast<std::size_t>(std::find(names.begin(), names.end(), name) - names.begin());
    REQUIRE(layer < names.size());
    CAPTURE(name);
    CAPTURE(expected);
    const std::vector<double> values = test::channelValues(film, layer, 0);
    double mean = 0.0;
    for (double v : values) mean += v / double(values.size());
    const double bias = mean - expected;
    CAPTURE(bias);
    CHECK(studentTTest(values, expected) > kPValue);
    CHECK(studentTTest(values, expected * 1.05) < kPValue);
}

TEST_CASE("path: furnace, a closed emissive diffuse sphere has radiance Le / (1 - rho)") {
    const double rho = 0.5, le = 1.0;
    const Film film = renderPath(furnace(float(rho), Rgb{float(le)}), classesSet(), 16);
    checkLayer(film, "beauty", le / (1.0 - rho));
    // E D L, one bounce of the emission: every sample, by light or by BSDF, is rho Le exactly (cos
    // cos / d^2 is the same everywhere on a sphere), so no noise is left for a t-test, only the MIS
    // weights' rounding along short chords (up to 3e-4 of a pixel). One sample lost, or counted
    // twice, moves its pixel by rho Le / 16.
    const std::vector<double> direct = test::channelValues(film, 1, 0);
    REQUIRE(film.layerNames()[1] == "raycast");
    double worst = 0.0;
    for (double v : direct) worst = std::max(worst, std::fabs(v - rho * le));
    CAPTURE(worst);
    CHECK(worst < 0.25 * rho * le / 16);
    checkLayer(film, "indirect", le * rho * rho / (1.0 - rho));
    CHECK(film.at(4, 3, 3).r == doctest::Approx(le));      // emission EL: seen directly, exactly Le
}

TEST_CASE("path: furnace, a point light of radiant intensity pi at the centre of a unit sphere with kd 0.5") {
    Scene scene = furnace(0.5f, Rgb{0.0f});
    scene.lights.push_back(PointLight{"centre", {0, 0, 0}, Rgb{1.0f}, {0, 0, 1}});
    const Film film = renderPath(scene, classesSet(), 16);
    checkLayer(film, "beauty", 1.0);
    checkLayer(film, "raycast", 0.5);   // E D L: exactly 0.5 everywhere
    checkLayer(film, "indirect", 0.5);
}

TEST_CASE("path: the classes AOVs sum to the beauty and indirect is non-zero in the lecture room") {
    // A room with walls, so light bounces: indirect must carry it and the sum must hold.
    const AovSet aovs(classesSet());
    Scene scene = furnace(0.5f, Rgb{0.0f});
    scene.lights.push_back(PointLight{"centre", {0, 0.5f, 0}, Rgb{1.0f}, {1, 0, 0}});
    RenderOptions options;
    options.integrator = "path";
    options.samplesPerPixel = 2;
    const Film film = Renderer(scene, aovs, options).render().film;
    double indirect = 0.0;
    for (int y = 0; y < film.height(); ++y) {
        for (int x = 0; x < film.width(); ++x) {
            Rgb sum{0.0f};
            for (std::size_t l = 1; l < film.layerCount(); ++l) sum += film.at(l, x, y);
            for (int c = 0; c < 3; ++c) CHECK(sum[c] == doctest::Approx(film.at(0, x, y)[c]).epsilon(1e-5));
            indirect += film.at(5, x, y).r;
        }
    }
    CHECK(indirect > 0.0);
}

// Found by tests/fuzz: a sphere light of radius 1e-6 seen from 1000 away has a solid-angle density
// above 1e19 near its silhouette; the MIS weight squared it to infinity in float and returned NaN.
TEST_CASE("path: a tiny, distant light's MIS weights stay finite") {
    Scene scene;
    scene.camera = test::centredCamera({0, 1, 5}, {0, 0, 0}, {0, 1, 0}, 33);
    PhongMaterial floor;
    floor.kd = Rgb{0.5f};
    floor.ks = Rgb{0.5f};
    test::addPlane(scene, "floor", test::addMaterial(scene, floor), {0, 0, 0}, {0, 1, 0});
    PhongMaterial light;
    light.emission = Rgb{1.0f};
    test::addSphere(scene, "light", test::addMaterial(scene, light), {1000, 1, 0}, 1e-6f);
    const AovSet aovs(classesSet());
    RenderOptions options;
    options.integrator = "path";
    CHECK(Renderer(scene, aovs, options).render().stats.rays.nonFinite == 0);
}

}  // namespace
}  // namespace lightpath
