// The path tracer through participating media (src/media/) against references that do not come
// from it: Beer-Lambert's attenuation of a lit floor seen through fog (eye ray and shadow ray),
// the white furnace (a non-absorbing medium inside an emitting enclosure leaves its radiance
// unchanged: L = Le solves the radiative transfer equation there), the AOVs' sum with media, and
// Arnold's volume AOVs filling.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "film/aov_presets.h"
#include "film/aov_set.h"
#include "materials/interface_material.h"
#include "media/homogeneous_medium.h"
#include "render/renderer.h"
#include "scene_builder.h"
#include "../support/film_checks.h"
#include "../support/pinhole_reference.h"
#include "../support/statistics.h"

// Its own namespace: render_tests is a unity build, beside test_path_tracer.cpp's helpers.
namespace lightpath::media_transport_test {
namespace {

constexpr double kPValue = 0.001;  // rejection threshold of one test, as test_path_tracer.cpp

Film renderPath(const Scene& scene, const std::vector<lpe::NamedExpression>& set, int spp, int maxDepth = 64) {
    const AovSet aovs(set);
    RenderOptions options;
    options.integrator = "path";
    options.samplesPerPixel = spp;
    options.maxDepth = maxDepth;
    options.seed = 7;
    return Renderer(scene, aovs, options).render().film;
}

std::uint32_t addMedium(Scene& scene, const std::string& name, Rgb sigmaA, Rgb sigmaS, float g = 0.0f) {
    HomogeneousMedium medium;
    medium.name = name;
    medium.sigmaA = sigmaA;
    medium.sigmaS = sigmaS;
    medium.g = g;
    scene.media.push_back(medium);
    return static_cast<std::uint32_t>(scene.media.size() - 1);
}

const glm::dvec3 kLight{0.7, 2.5, -0.4};
constexpr double kAlbedo = 0.6, kIntensity = 3.0;

// A Lambertian floor under a point light, seen from above, all in the world's medium.
Scene fogFloor(Rgb sigmaA, Rgb sigmaS) {
    Scene scene;
    scene.camera = test::centredCamera({0.3f, 1.5f, 0.2f}, {0.3f, 0, 0.2f}, {0, 0, -1}, 31);
    scene.camera.verticalFovDegrees = 60.0f;
    PhongMaterial floor;
    floor.name = "floor";
    floor.kd = Rgb{float(kAlbedo)};
    test::addPlane(scene, "floor", test::addMaterial(scene, floor), {0, 0, 0}, {0, 1, 0});
    scene.lights.push_back(PointLight{"key", Vec3(kLight), Rgb{float(kIntensity)}, Vec3{0, 0, 1}});
    scene.worldMedium = addMedium(scene, "fog", sigmaA, sigmaS);
    return scene;
}

// Pixel (i, j)'s direct light from the floor point it sees (test::pixelDirection, the pinhole model
// written out): kd I cos / d² (test_path_tracer.cpp's closed form),
// dimmed by exp(-sigma_t d) along the shadow ray (d = the light's distance) and along the eye ray.
double floorThroughFog(const Scene& scene, int i, int j, double sigmaT) {
    const CameraDescription& c = scene.camera;
    const glm::dvec3 d = test::pixelDirection(c, i, j);
    const double eyeDistance = -double(c.eye.y) / d.y;
    const glm::dvec3 p = glm::dvec3(c.eye) + eyeDistance * d;
    const glm::dvec3 toLight = kLight - p;
    const double lightDistance = glm::length(toLight);
    const double unattenuated = kAlbedo * kIntensity * (toLight.y / lightDistance) / (lightDistance * lightDistance);
    return unattenuated * std::exp(-sigmaT * (lightDistance + eyeDistance));
}

// The beauty's largest relative error over every pixel and channel against expected(i, j, channel).
template <class Expected>
double worstRelativeError(const Film& film, const Expected& expected) {
    double worst = 0.0;
    for (int j = 0; j < film.height(); ++j)
        for (int i = 0; i < film.width(); ++i)
            for (int c = 0; c < 3; ++c) {
                const double e = expected(i, j, c);
                worst = std::max(worst, std::fabs(film.at(0, i, j)[c] - e) / e);
            }
    return worst;
}

TEST_CASE("path: a floor seen through absorbing fog is dimmed by exp(-sigma_t d) on the eye ray and the shadow ray") {
    const Rgb sigmaA{0.05f, 0.2f, 0.4f};
    const Scene scene = fogFloor(sigmaA, Rgb{0.0f});
    // A medium that only absorbs makes the estimate exact: one sample per pixel, every pixel within 0.5%.
    const Film film = renderPath(scene, {}, 1);
    CHECK(worstRelativeError(film, [&](int i, int j, int c) { return floorThroughFog(scene, i, j, sigmaA[c]); }) < 0.005);
}

// The same fog held by a large interface sphere around the camera, the light and the floor seen:
// the camera starts in the sphere's medium (cameraMedium), no surface event is added, and the
// closed form is the world-fog one. Its control: the same sphere with vacuum inside is undimmed.
TEST_CASE("path, raycast: the camera inside an interface sphere of fog sees the floor dimmed by exp(-sigma_t d)") {
    const Rgb sigmaA{0.05f, 0.2f, 0.4f};
    Scene scene = fogFloor(sigmaA, Rgb{0.0f});
    const std::uint32_t fog = scene.worldMedium;
    scene.worldMedium = kNoMedium;
    InterfaceMaterial boundary;
    boundary.name = "boundary";
    scene.materials.push_back(boundary);
    scene.interfaces = true;
    test::addSphere(scene, "box", static_cast<std::uint32_t>(scene.materials.size() - 1), {0.3f, 0.0f, 0.2f}, 20.0f);
    scene.objects.back().enclosesVolume = true;
    scene.objects.back().interior = fog;
    for (const char* integrator : {"path", "raycast"}) {
        CAPTURE(integrator);
        RenderOptions options;
        options.integrator = integrator;
        options.samplesPerPixel = 1;
        options.seed = 7;
        const Film film = Renderer(scene, AovSet({}), options).render().film;
        CHECK(worstRelativeError(film, [&](int i, int j, int c) { return floorThroughFog(scene, i, j, sigmaA[c]); }) < 0.005);
    }
}

// An axis-aligned box of triangles wound outwards (normal = (b - a) x (c - a)), as a closed mesh.
void addOutwardBox(Scene& scene, std::uint32_t object, Vec3 lo, Vec3 hi) {
    const Vec3 centre = 0.5f * (lo + hi);
    const auto corner = [&](int k) { return Vec3{k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z}; };
    const int faces[6][4] = {{0, 1, 3, 2}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 3, 7, 5}};
    for (const auto& f : faces) {
        Vec3 q[4] = {corner(f[0]), corner(f[1]), corner(f[2]), corner(f[3])};
        const Vec3 faceCentre = 0.25f * (q[0] + q[1] + q[2] + q[3]);
        if (glm::dot(glm::cross(q[1] - q[0], q[2] - q[0]), faceCentre - centre) < 0.0f) std::swap(q[1], q[3]);
        scene.triangles.push_back({q[0], q[1], q[2], object});
        scene.triangles.push_back({q[0], q[2], q[3], object});
    }
}

// A slab of fog between heights 0.5 and 1 held by an interface box, with the camera above it and
// the floor and the light on either side: the eye ray and the shadow ray each cross it without an
// event, so the floor is dimmed by exp(-sigma_t 0.5 (1/|d.y| + 1/cos theta_light)) (the slab's
// thickness along each ray). Its control: the same box as a glass-free vacuum boundary is undimmed.
TEST_CASE("path, raycast, whitted: a floor seen through an interface slab of fog is dimmed by exp(-sigma_t d) on the eye ray and the shadow ray") {
    const Rgb sigmaA{0.3f, 0.8f, 1.5f};
    Scene scene = fogFloor(sigmaA, Rgb{0.0f});
    const std::uint32_t fog = scene.worldMedium;
    scene.worldMedium = kNoMedium;
    InterfaceMaterial boundary;
    boundary.name = "boundary";
    scene.materials.push_back(boundary);
    scene.interfaces = true;
    const std::uint32_t slab = test::addObject(scene, "slab", static_cast<std::uint32_t>(scene.materials.size() - 1));
    addOutwardBox(scene, slab, {-40.0f, 0.5f, -40.0f}, {40.0f, 1.0f, 40.0f});
    scene.objects[slab].enclosesVolume = true;
    scene.objects[slab].interior = fog;
    for (const char* integrator : {"path", "raycast", "whitted"}) {
        CAPTURE(integrator);
        RenderOptions options;
        options.integrator = integrator;
        options.samplesPerPixel = 1;
        options.seed = 7;
        const Film film = Renderer(scene, AovSet({}), options).render().film;
        double worst = 0.0, worstUndimmed = 0.0;
        for (int j = 0; j < film.height(); ++j)
            for (int i = 0; i < film.width(); ++i) {
                const glm::dvec3 d = test::pixelDirection(scene.camera, i, j);
                const glm::dvec3 p = glm::dvec3(scene.camera.eye) - double(scene.camera.eye.y) / d.y * d;
                const glm::dvec3 toLight = kLight - p;
                const double thickness = 0.5 * (1.0 / std::fabs(d.y) + glm::length(toLight) / toLight.y);
                for (int c = 0; c < 3; ++c) {
                    const double undimmed = floorThroughFog(scene, i, j, 0.0);
                    const double expected = undimmed * std::exp(-double(sigmaA[c]) * thickness);
                    worst = std::max(worst, std::fabs(film.at(0, i, j)[c] - expected) / expected);
                    worstUndimmed = std::max(worstUndimmed, std::fabs(film.at(0, i, j)[c] - undimmed) / undimmed);
                }
            }
        CHECK(worst < 0.005);
        CHECK(worstUndimmed > 0.1);  // the slab is thick enough to tell the two apart
    }
}

TEST_CASE("path: through scattering fog the floor's direct light E<RD>L is exp(-sigma_t d) dimmer, unbiased (t-test)") {
    // Coloured: the free flights are drawn by one channel and weighed over all three (pbrt-v4 14.2).
    const Rgb sigmaA{0.1f, 0.05f, 0.0f}, sigmaS{0.2f, 0.4f, 0.6f};
    const Scene scene = fogFloor(sigmaA, sigmaS);
    const Film film = renderPath(scene, {{"direct", "E<RD>L"}}, 16);
    for (int c = 0; c < 3; ++c) {
        CAPTURE(c);
        std::vector<double> ratios;
        for (int j = 0; j < film.height(); ++j)
            for (int i = 0; i < film.width(); ++i)
                ratios.push_back(film.at(1, i, j)[c] / floorThroughFog(scene, i, j, sigmaA[c] + sigmaS[c]));
        CHECK(test::studentTTest(ratios, 1.0) > kPValue);
        CHECK(test::studentTTest(ratios, 1.05) < kPValue);  // the control: 5% off is rejected
    }
}

// The camera inside an emitting sphere (radiance Le, no reflection) filled with the world's medium.
Scene furnace(Rgb sigmaA, Rgb sigmaS, float g) {
    Scene scene;
    scene.camera = test::centredCamera({0.1f, -0.2f, 0.3f}, {1, 0, 0}, {0, 1, 0}, 15);
    scene.camera.verticalFovDegrees = 90.0f;
    PhongMaterial wall;
    wall.name = "wall";
    wall.emission = Rgb{1.0f};
    test::addSphere(scene, "wall", test::addMaterial(scene, wall), {0, 0, 0}, 1.0f);
    scene.worldMedium = addMedium(scene, "fog", sigmaA, sigmaS, g);
    return scene;
}

double meanOf(const Film& film, std::size_t layer, int c) {
    double sum = 0.0;
    for (int j = 0; j < film.height(); ++j)
        for (int i = 0; i < film.width(); ++i) sum += film.at(layer, i, j)[c];
    return sum / (film.width() * film.height());
}

TEST_CASE("path: white furnace: a medium that does not absorb leaves the walls' radiance, one that absorbs dims it") {
    // Coloured, forward-scattering: every channel's own free flights and the phase function in the loop.
    const Film conserving = renderPath(furnace(Rgb{0.0f}, {1.0f, 1.5f, 2.0f}, 0.4f), {}, 256);
    for (int c = 0; c < 3; ++c) {
        CAPTURE(c);
        std::vector<double> pixels;
        for (int j = 0; j < conserving.height(); ++j)
            for (int i = 0; i < conserving.width(); ++i) pixels.push_back(conserving.at(0, i, j)[c]);
        CHECK(meanOf(conserving, 0, c) == doctest::Approx(1.0).epsilon(0.01));
        CHECK(test::studentTTest(pixels, 1.0) > kPValue);
        CHECK(test::studentTTest(pixels, 0.97) < kPValue);  // the control: 3% off is rejected
    }
    const Film absorbing = renderPath(furnace(Rgb{0.5f}, Rgb{2.0f}, 0.0f), {}, 32);
    for (int c = 0; c < 3; ++c) CHECK(meanOf(absorbing, 0, c) < 0.9);
}

TEST_CASE("path with media: the classes AOVs sum to the beauty, volume light goes to volume, rest is zero, and C<V>.*, C<V>L fill") {
    Scene scene = fogFloor(Rgb{0.05f}, Rgb{0.3f});
    PhongMaterial glass;
    glass.name = "glass";
    glass.kt = Rgb{1.0f};
    glass.fresnel = true;
    test::addSphere(scene, "ball", test::addMaterial(scene, glass), {0.3f, 0.4f, 0.2f}, 0.3f);
    scene.objects.back().interior = addMedium(scene, "smoke", Rgb{0.2f}, Rgb{3.0f}, 0.6f);
    const Film classes = renderPath(scene, classesSet(), 4, 8);
    CHECK(test::worstSumError(classes) <= 1.0);
    CHECK(test::finiteNonNegative(classes));
    // `volume` (E.*V.*L) holds the light through V events and the six partition: `rest` is zero.
    REQUIRE(classes.layerNames()[6] == "volume");
    CHECK(meanOf(classes, 6, 1) > 0.0);
    for (int c = 0; c < 3; ++c) CHECK(meanOf(classes, classes.layerCount() - 1, c) == 0.0);

    // Arnold's volume AOVs (the camera ray scatters first in a medium), one medium's light, and a
    // partition: paths with a V event anywhere and paths with none.
    const Film arnold = renderPath(scene, {{"volume", "C<V>.*"}, {"volume_direct", "C<V>L"},
                                           {"smoke", "C.*<V'smoke'>.*"}, {"any_volume", "C.*V.*"}, {"surfaces", "C[^V]*"}},
                                   4, 8);
    for (std::size_t layer = 1; layer <= 4; ++layer) CHECK(meanOf(arnold, layer, 1) > 0.0);
    double split = 0.0, beauty = 0.0;
    for (int j = 0; j < arnold.height(); ++j)
        for (int i = 0; i < arnold.width(); ++i) {
            split += arnold.at(4, i, j).g + arnold.at(5, i, j).g;
            beauty += arnold.at(0, i, j).g;
        }
    CHECK(split == doctest::Approx(beauty).epsilon(1e-5));
}

// Single scattering from a point light in an infinite, isotropic, homogeneous medium (the airlight
// integral of Sun et al. 2005) along the ray from `eye` in direction w:
//   L = ∫0^∞ sigma_s e^(-sigma_t t) 1/(4 pi) (pi I) e^(-sigma_t d(t)) / d(t)² dt,  d(t) = |eye + t w - light|
// by Simpson's rule in double, converged (the tail beyond t = 80 is below e^-32).
double airlight(const glm::dvec3& eye, const glm::dvec3& w, const glm::dvec3& light, double sigmaS, double sigmaT,
                double intensity) {
    constexpr int kIntervals = 40000;
    constexpr double kEnd = 80.0;
    const double h = kEnd / kIntervals;
    double sum = 0.0;
    for (int k = 0; k <= kIntervals; ++k) {
        const double t = k * h;
        const glm::dvec3 toLight = light - (eye + t * w);
        const double d2 = glm::dot(toLight, toLight);
        const double f = sigmaS * std::exp(-sigmaT * (t + std::sqrt(d2))) * intensity / 4.0 / d2;
        sum += f * (k == 0 || k == kIntervals ? 1.0 : k % 2 == 1 ? 4.0 : 2.0);
    }
    return sum * h / 3.0;
}

TEST_CASE("single scattering from a point light in infinite fog matches the airlight integral, raycast and path's E V <L.>" *
          doctest::test_suite("statistical")) {
    const glm::dvec3 light{2.5, 0.3, -2.0};  // outside the view: no camera ray passes near it
    constexpr double kSigmaS = 0.3, kSigmaA = 0.1, kI = 5.0;
    Scene scene;
    scene.camera = test::centredCamera({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 41);
    scene.camera.verticalFovDegrees = 40.0f;
    scene.lights.push_back(PointLight{"key", Vec3(light), Rgb{float(kI)}, Vec3{0, 0, 1}});
    scene.worldMedium = addMedium(scene, "fog", Rgb{float(kSigmaA)}, Rgb{float(kSigmaS)});
    const std::vector<lpe::NamedExpression> single{{"single", "E<V><L.>"}};
    const auto ratios = [&](const Film& film) {
        std::vector<double> r;
        for (int j = 0; j < film.height(); ++j)
            for (int i = 0; i < film.width(); ++i)
                r.push_back(film.at(1, i, j).g / airlight(glm::dvec3(scene.camera.eye), test::pixelDirection(scene.camera, i, j),
                                                          light, kSigmaS, kSigmaS + kSigmaA, kI));
        return r;
    };
    const auto mean = [](const std::vector<double>& v) {
        double sum = 0.0;
        for (double x : v) sum += x;
        return sum / v.size();
    };
    SUBCASE("raycast, at the pixel centres") {
        const AovSet aovs(single);
        RenderOptions options;
        options.integrator = "raycast";
        options.seed = 7;
        const std::vector<double> r = ratios(Renderer(scene, aovs, options).render().film);
        CHECK(mean(r) == doctest::Approx(1.0).epsilon(0.01));
        CHECK(test::studentTTest(r, 1.0) > kPValue);
        CHECK(test::studentTTest(r, 1.03) < kPValue);  // the control: 3% off is rejected
    }
    SUBCASE("path's E V <L.>") {
        const std::vector<double> r = ratios(renderPath(scene, single, 16));
        CHECK(mean(r) == doctest::Approx(1.0).epsilon(0.01));
        CHECK(test::studentTTest(r, 1.0) > kPValue);
        CHECK(test::studentTTest(r, 1.03) < kPValue);
    }
}

}  // namespace
}  // namespace lightpath::media_transport_test
