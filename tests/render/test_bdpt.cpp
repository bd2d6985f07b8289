// Bidirectional path tracing against references that do not come from it: the path tracer on
// scenes both can converge on, the furnace's closed forms, the inverse-square law for light
// tracing alone, a mirror's caustic as the light's mirror image, and the MIS weights of every
// strategy of random paths summing to one. Statistical checks are Student's t-tests with a control
// 5% off that must be rejected.
#include <doctest/doctest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>
#include <vector>

#include "film/aov_set.h"
#include "integrators/bdpt.h"
#include "integrators/bdpt_allocation.h"
#include "integrators/bdpt_vertex.h"
#include "integrators/registry.h"
#include "film/aov_presets.h"
#include "math/random.h"
#include "render/renderer.h"
#include "scene/scene_loader.h"
#include "render_world.h"
#include "scene_builder.h"
#include "../support/paired_agreement.h"
#include "../support/statistics.h"

namespace lightpath {
namespace {

using test::studentTTest;

constexpr double kPValue = 0.001;

// `lightWalkFraction` > 0 forces bdpt's fraction of camera samples that walk from a light.
RenderOptions renderOptions(const char* integrator, int spp, int maxDepth, std::uint64_t seed, int threads = 0,
                            double lightWalkFraction = 0.0) {
    RenderOptions options;
    options.integrator = integrator;
    options.samplesPerPixel = spp;
    options.maxDepth = maxDepth;
    options.seed = seed;
    options.threads = threads;
    if (lightWalkFraction > 0.0) {
        ParameterValues values(findIntegrator("bdpt")->schema);
        values.set("light-walk-fraction", lightWalkFraction);
        options.integratorParameters = values;
    }
    return options;
}

Film render(const Scene& scene, const std::vector<lpe::NamedExpression>& set, const char* integrator, int spp,
            int maxDepth, std::uint64_t seed, int threads = 0, double lightWalkFraction = 0.0) {
    const AovSet aovs(set);
    return Renderer(scene, aovs, renderOptions(integrator, spp, maxDepth, seed, threads, lightWalkFraction)).render().film;
}

TEST_CASE("bdpt: the Cornell box with its area light, every classes AOV equals the path tracer's (t-test)" * doctest::test_suite("statistical")) {
    Scene scene = loadScene(LIGHTPATH_SOURCE_DIR "/tests/render/data/cornell-lamp.toml");
    scene.camera.width = scene.camera.height = 32;
    // The same seed: both see the same jittered first hits (common random numbers), so the paired
    // differences are small and the test sharp, while their expectations stay each method's own.
    const Film bdpt = render(scene, classesSet(), "bdpt", 128, 5, 11);
    const Film path = render(scene, classesSet(), "path", 128, 5, 11);
    test::checkPairedAgreement(bdpt, path, kPValue);
}

// A light walk for a quarter of the camera samples: its strategies count 1/4 in the weights and
// their contributions 4x, so the image's expectation is the same (and the path tracer's).
TEST_CASE("bdpt: with a light walk for a quarter of the camera samples, every classes AOV equals the path tracer's (t-test)" * doctest::test_suite("statistical")) {
    Scene scene = loadScene(LIGHTPATH_SOURCE_DIR "/tests/render/data/cornell-lamp.toml");
    scene.camera.width = scene.camera.height = 32;
    const Film bdpt = render(scene, classesSet(), "bdpt", 128, 5, 11, 0, 0.25);
    const Film path = render(scene, classesSet(), "path", 128, 5, 11);
    test::checkPairedAgreement(bdpt, path, kPValue);
}

// Half the light walks aimed at the mirror ball and the glass ball (lights/emission_guide.h): the
// walks' weights and every strategy's MIS weight read the mixture's density, so each classes AOV,
// the caustics through the glass and the lamp seen in the mirror among them, stays the path
// tracer's. (Broken on purpose, the walk's first step weighed by the lamp's own density instead of
// the mixture's: red, p < 1e-17 on the beauty and ray casting's layer.)
TEST_CASE("bdpt: with light walks aimed at a mirror ball and a glass ball, every classes AOV equals the path tracer's (t-test)" * doctest::test_suite("statistical")) {
    Scene scene = loadScene(LIGHTPATH_SOURCE_DIR "/tests/render/data/cornell-lamp.toml");
    scene.camera.width = scene.camera.height = 64;
    PhongMaterial mirror, glass;
    mirror.name = "mirror";
    mirror.kr = Rgb{0.9f};
    glass.name = "glass";
    glass.kt = Rgb{0.95f};
    glass.ior = 1.5f;
    test::addSphere(scene, "mirror-ball", test::addMaterial(scene, mirror), {-0.35f, 1.25f, 0.3f}, 0.22f);
    test::addSphere(scene, "glass-ball", test::addMaterial(scene, glass), {0.3f, 1.1f, 0.45f}, 0.22f);
    REQUIRE(test::RenderWorld(scene).lights.emissionGuide().targets().size() == 2);
    // The lamp seen straight or in the mirror (EL, ES+L) is the eye's walk alone in both, the same
    // paths with the same numbers: no difference to test, and too few pixels for the control. The
    // caustics are in `indirect` (a layer of their own is too noisy under the path tracer for the
    // control).
    std::vector<lpe::NamedExpression> set;
    for (const lpe::NamedExpression& e : classesSet())
        if (e.name != "mirror" && e.name != "emission") set.push_back(e);
    const Film bdpt = render(scene, set, "bdpt", 256, 5, 11);
    const Film path = render(scene, set, "path", 256, 5, 11);
    test::checkPairedAgreement(bdpt, path, kPValue);
}

// A closed sphere seen from its centre.
Scene furnace(float albedo, Rgb emission) {
    Scene scene;
    scene.camera = test::centredCamera({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 25);
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
    CAPTURE(test::meanOf(values));
    CHECK(studentTTest(values, expected) > kPValue);
    CHECK(studentTTest(values, expected * 1.05) < kPValue);
}

TEST_CASE("bdpt: furnace, a closed emissive diffuse sphere has radiance Le / (1 - rho), split as the path tracer splits it") {
    const double rho = 0.5, le = 1.0;
    // The light-walk fraction the pilot picks (1/16 here).
    const Film film = render(furnace(float(rho), Rgb{float(le)}), classesSet(), "bdpt", 32, 64, 3);
    checkLayer(film, "beauty", le / (1.0 - rho));
    checkLayer(film, "raycast", rho * le);
    checkLayer(film, "indirect", le * rho * rho / (1.0 - rho));
    checkLayer(film, "emission", le);
    // E D L resolves a bias of -0.0033%: bdpt read 0.4999834 when its densities came from the
    // traced rays rather than the vertices (linkThrough), and that mean must be rejected too.
    const auto& names = film.layerNames();
    const auto raycast = static_cast<std::size_t>(std::find(names.begin(), names.end(), "raycast") - names.begin());
    const std::vector<double> values = test::channelValues(film, raycast, 0);
    CAPTURE(test::meanOf(values) - rho * le);
    CHECK(studentTTest(values, rho * le * (1.0 - 3.3e-5)) < kPValue);
}

TEST_CASE("bdpt: furnace, a point light of radiant intensity pi at the centre of a unit sphere with kd 0.5") {
    Scene scene = furnace(0.5f, Rgb{0.0f});
    scene.lights.push_back(PointLight{"centre", {0, 0, 0}, Rgb{1.0f}, {0, 0, 1}});
    const Film film = render(scene, classesSet(), "bdpt", 32, 64, 5);
    checkLayer(film, "beauty", 1.0);
    checkLayer(film, "raycast", 0.5);
    checkLayer(film, "indirect", 0.5);
}

TEST_CASE("bdpt: bit-identical images on 1, 2 and 8 threads, splats included") {
    Scene scene = loadScene(LIGHTPATH_SOURCE_DIR "/scenes/glass-sphere.toml");
    scene.camera.width = 40;
    scene.camera.height = 30;
    const std::vector<lpe::NamedExpression> set{{"caustic", "E(D|G)S+L"}};
    const Film one = render(scene, set, "bdpt", 2, 5, 1, 1);
    for (int threads : {2, 8}) {
        const Film other = render(scene, set, "bdpt", 2, 5, 1, threads);
        const auto a = one.interleaved(), b = other.interleaved();
        CHECK(std::equal(a.begin(), a.end(), b.begin(), b.end()));
    }
}

// A light walk for a quarter of the camera samples, two per sample, and two or three (2.5).
TEST_CASE("bdpt: with 1/4, 2 and 2.5 light walks per camera sample, bit-identical images on 1 and 2 threads") {
    Scene scene = loadScene(LIGHTPATH_SOURCE_DIR "/scenes/glass-sphere.toml");
    scene.camera.width = 40;
    scene.camera.height = 30;
    for (const double q : {0.25, 2.0, 2.5}) {
        CAPTURE(q);
        const Film one = render(scene, classesSet(), "bdpt", 4, 5, 1, 1, q);
        const Film two = render(scene, classesSet(), "bdpt", 4, 5, 1, 2, q);
        const auto a = one.interleaved(), b = two.interleaved();
        CHECK(std::equal(a.begin(), a.end(), b.begin(), b.end()));
    }
}

TEST_CASE("bdpt: with 1/4 and 2 light walks per camera sample, explain's terms sum to the pixel, splats included") {
    Scene scene = loadScene(LIGHTPATH_SOURCE_DIR "/scenes/glass-sphere.toml");
    scene.camera.width = 24;
    scene.camera.height = 18;
    const AovSet aovs(std::vector<lpe::NamedExpression>{});
    for (const double q : {0.25, 2.0}) {
    CAPTURE(q);
    const Renderer renderer(scene, aovs, renderOptions("bdpt", 4, 5, 3, 1, q));
    const Film film = renderer.render().film;
    // Pixels on the caustic under the ball (light tracing's), on the floor and on the ball.
    for (const std::pair<int, int>& pixel : std::vector<std::pair<int, int>>{{14, 13}, {3, 15}, {12, 9}}) {
        const int x = pixel.first, y = pixel.second;  // not a structured binding: clang 14's CAPTURE
        Rgb sum{0.0f};
        int splatted = 0;
        for (const LoggedContribution& c : renderer.explainPixel(x, y)) {
            sum += c.value;
            splatted += c.splatted ? 1 : 0;
        }
        CAPTURE(x);
        CAPTURE(y);
        CAPTURE(splatted);
        for (int c = 0; c < 3; ++c) CHECK(double(sum[c]) == doctest::Approx(film.at(0, x, y)[c]).epsilon(1e-4));
    }
    }
}

// The pilot's variance per camera sample at each fraction against closed forms, and its choice.
TEST_CASE("bdpt: the light-walk pilot's variance at each fraction is the closed form's, and it picks least variance x work") {
    // Two pixels of two samples each, built by hand: the eye's strategies give e, the joins j and
    // the splats squares s2, the same at every fraction; the work of the eye's walk, of one light
    // walk with its splats, and of the first walk's joins.
    auto sample = [](double e, double j, double s2, double eyeWork, double lightWork, double joinWork) {
        PilotSample p;
        p.eye.fill(e);
        p.join.fill(j);
        p.splatSquares.fill(s2);
        p.eyeWork = eyeWork;
        p.lightWalkWork = lightWork;
        p.joinWork = joinWork;
        return p;
    };
    LightWalkPilot pilot(2);
    pilot.add(sample(1.0, 0.5, 0.0, 4.0, 8.0, 8.0));
    pilot.add(sample(3.0, 0.5, 2.0, 4.0, 8.0, 8.0));
    pilot.add(sample(2.0, 0.0, 0.0, 4.0, 8.0, 8.0));
    pilot.add(sample(2.0, 1.0, 0.0, 4.0, 8.0, 8.0));
    CHECK(pilot.samples() == 4);
    for (std::size_t k = 0; k < kLightWalkFractions.size(); ++k) {
        const double q = kLightWalkFractions[k];
        // The joins come from the first walk, which a sample has with probability p = min(q, 1):
        // per pixel E[e^2 + 2 e j + j^2 / p] - (e + j)_1 (e + j)_2 (the unbiased square of the mean);
        // the splats of q walks, each / q: 2 / q over the 4 samples.
        const double p = q < 1.0 ? q : 1.0;
        const double first = (1.0 + 1.0 + 0.25 / p + 9.0 + 3.0 + 0.25 / p) / 2.0 - 1.5 * 3.5;
        const double second = (4.0 + 0.0 + 0.0 + 4.0 + 4.0 + 1.0 / p) / 2.0 - 2.0 * 3.0;
        const LightWalkPilot::Estimate e = pilot.estimate(k);
        CAPTURE(q);
        CHECK(e.variance == doctest::Approx((first + second) / 2.0 + 2.0 / q / 4.0));
        CHECK(e.work == doctest::Approx(4.0 + 8.0 * q + 8.0 * p));
    }
    // Variance x work, q <= 1: (a + b / q)(4 + 16 q), a = b = 0.875, least at q = sqrt(4 b / (16 a))
    // = 0.5 (35, 31.5 and 35 at q = 1, 0.5, 0.25); q = 2: (1.25 + 0.25)(12 + 16) = 42.
    CHECK(kLightWalkFractions[pilot.best()] == 0.5);

    // Splats carrying the variance: every sample e = 1 or 7 (a pixel's variance 18 per sample, at
    // every q), j = 0, s2 = 64 (64 / q); eye work 4, a light walk 2, the joins 8: q > 1 costs
    // (18 + 64 / q)(12 + 2 q): 728, 680, 800 and 1148 at q = 8, 4, 2, 1; q = 1/2: (18 + 128) 9.
    LightWalkPilot splatty(2);
    for (int i = 0; i < 2; ++i) {
        splatty.add(sample(1.0, 0.0, 64.0, 4.0, 2.0, 8.0));
        splatty.add(sample(7.0, 0.0, 64.0, 4.0, 2.0, 8.0));
    }
    for (std::size_t k = 0; k < kLightWalkFractions.size(); ++k) {
        const double q = kLightWalkFractions[k], p = q < 1.0 ? q : 1.0;
        const LightWalkPilot::Estimate e = splatty.estimate(k);
        CAPTURE(q);
        CHECK(e.variance == doctest::Approx(18.0 + 64.0 / q));
        CHECK(e.work == doctest::Approx(4.0 + 2.0 * q + 8.0 * p));
    }
    CHECK(kLightWalkFractions[splatty.best()] == 4.0);
    // No variance at all: every candidate costs 0, and the tie goes to one walk per sample.
    LightWalkPilot flat(2);
    for (int i = 0; i < 4; ++i) flat.add(sample(1.0, 0.0, 0.0, 4.0, 2.0, 8.0));
    CHECK(kLightWalkFractions[flat.best()] == 1.0);
}

// The render's choice: the fewest light walks the pilot cannot tell from the least variance x work.
TEST_CASE("bdpt: the light-walk pilot takes fewer walks when one pixel alone makes them look worse") {
    // Eight pixels of two samples, eye values a and b: a pixel's variance (a - b)^2 / 2 at every
    // fraction, no joins, no splats; work 4 + 8 q per sample (W = 12 at q = 1, 4.5 at 1/16).
    auto pixel = [](LightWalkPilot& pilot, double atLeastOne, double belowOne) {
        for (double value : {0.0, 1.0}) {
            PilotSample p;
            for (std::size_t k = 0; k < kLightWalkFractions.size(); ++k)
                p.eye[k] = value * (kLightWalkFractions[k] < 1.0 ? belowOne : atLeastOne);
            p.eyeWork = 4.0;
            p.lightWalkWork = 8.0;
            pilot.add(p);
        }
    };
    const std::size_t one = 3, sixteenth = kLightWalkFractions.size() - 1;
    REQUIRE(kLightWalkFractions[one] == 1.0);
    REQUIRE(kLightWalkFractions[sixteenth] == 0.0625);
    // A firefly: seven pixels of variance 2 at every fraction, one of 2 at q >= 1 and 32 below.
    // Below one walk the variance is (7 * 2 + 32) / 8 = 5.75, so variance x work is 2 x 12 = 24 at
    // q = 1 (the least) and 5.75 x 4.5 = 25.875 at 1/16. Their difference per pixel, 4.5 u - 24:
    // -15 seven times and 120 once, mean 1.875: deviations -16.875 seven times and 7 x 16.875
    // once, sample variance 16.875^2 (7 + 49) / 7 = 8 x 16.875^2, so the standard error
    // sqrt(8 x 16.875^2 / 8) = 16.875: 1/16, 1.875 above, is well within one of it.
    LightWalkPilot firefly(2);
    for (int i = 0; i < 7; ++i) pixel(firefly, 2.0, 2.0);
    pixel(firefly, 2.0, 8.0);
    CHECK(firefly.estimate(one).variance * firefly.estimate(one).work == doctest::Approx(24.0));
    CHECK(firefly.estimate(sixteenth).variance * firefly.estimate(sixteenth).work == doctest::Approx(25.875));
    CHECK(firefly.best() == one);
    CHECK(firefly.differenceError(sixteenth) == doctest::Approx(16.875));
    CHECK(firefly.differenceError(one) == 0.0);
    CHECK(kLightWalkFractions[firefly.choice()] == 0.0625);
    // The control: the same estimates at every fraction, every pixel alike (variance 5.75 below one
    // walk in each), so the difference has no spread and the least variance x work is kept.
    LightWalkPilot even(2);
    for (int i = 0; i < 8; ++i) pixel(even, 2.0, std::sqrt(11.5));
    CHECK(even.estimate(sixteenth).variance * even.estimate(sixteenth).work == doctest::Approx(25.875));
    CHECK(even.differenceError(sixteenth) == doctest::Approx(0.0).epsilon(1e-6));
    CHECK(kLightWalkFractions[even.choice()] == 1.0);
    // No variance at all: every difference is 0 with no spread, and one walk per sample is kept.
    LightWalkPilot flat(2);
    for (int i = 0; i < 8; ++i) pixel(flat, 0.0, 0.0);
    CHECK(kLightWalkFractions[flat.choice()] == 1.0);
}

TEST_CASE("splat film: sums faint and bright splats with a relative step, in any order") {
    // 2^-20 absolute steps lost every splat below 5e-7 and overflowed above 8.8e12.
    SplatFilm film(2, 1, 1);
    for (int i = 0; i < 1000; ++i) film.add(0, 0, 0, Rgb{1e-9f, 3e-12f, 1.0f});
    film.add(1, 0, 0, Rgb{1e13f, 3e15f, -2e14f});
    film.add(1, 0, 0, Rgb{1e13f, 1.0f, 1e14f});
    const Rgb faint = film.at(0, 0, 0), bright = film.at(1, 0, 0);
    const auto close = [](float value, double expected) { return std::fabs(value / expected - 1.0) < 1e-6; };
    CHECK(close(faint[0], 1e-6));
    CHECK(close(faint[1], 3e-9));
    CHECK(close(faint[2], 1000.0));
    CHECK(close(bright[0], 2e13));
    CHECK(close(bright[1], 3e15));
    CHECK(close(bright[2], -1e14));
}

TEST_CASE("bdpt: an image scales with its light, faint (1e-9) and bright (1e+12) alike, splats included") {
    // The point-light furnace: light tracing (splats) carries much of every pixel. Depth 2 keeps
    // Russian roulette, which reads the light walk's absolute throughput, out of the comparison.
    const auto lit = [](float intensity) {
        Scene scene = furnace(0.5f, Rgb{0.0f});
        scene.lights.push_back(PointLight{"centre", {0, 0, 0}, Rgb{intensity}, {0, 0, 1}});
        return scene;
    };
    const Film reference = render(lit(1.0f), classesSet(), "bdpt", 4, 2, 5, 2);
    for (const float scale : {1e-9f, 1e12f}) {
        CAPTURE(scale);
        const Film scaled = render(lit(scale), classesSet(), "bdpt", 4, 2, 5, 2);
        const auto a = reference.interleaved(), b = scaled.interleaved();
        REQUIRE(a.size() == b.size());
        double worst = 0.0;
        for (std::size_t i = 0; i < a.size(); ++i)
            for (int c = 0; c < 3; ++c)
                worst = std::max(worst, std::fabs(double(b[i][c]) / scale - double(a[i][c])) / (1e-6 + std::fabs(double(a[i][c]))));
        CHECK(worst < 1e-5);
        // Still bit-identical for any number of threads.
        const Film one = render(lit(scale), classesSet(), "bdpt", 4, 2, 5, 1);
        CHECK(std::equal(one.interleaved().begin(), one.interleaved().end(), b.begin(), b.end()));
    }
}

// The pieces a test can hold: a scene with its geometry, lights and automaton.
using World = test::RenderWorld;

TEST_CASE("camera: project() inverts generateRay, and importance integrates to one over the image") {
    CameraDescription d;
    d.eye = {0.3f, 1.2f, 4.0f};
    d.lookAt = {-0.2f, 0.8f, 0.0f};
    d.width = 64;
    d.height = 40;
    d.verticalFovDegrees = 50.0f;
    const Camera camera(d);
    Pcg32 rng(9, 1);
    for (int i = 0; i < 1000; ++i) {
        const float x = rng.nextFloat() * 64.0f, y = rng.nextFloat() * 40.0f;
        const Ray ray = camera.generateRay(x, y);
        const auto p = camera.project(ray.at(0.5f + 10.0f * rng.nextFloat()));
        REQUIRE(p);
        CHECK(p->x == doctest::Approx(x).epsilon(1e-4));
        CHECK(p->y == doctest::Approx(y).epsilon(1e-4));
    }
    CHECK_FALSE(camera.project(d.eye + (d.eye - d.lookAt)));           // behind the camera
    CHECK_FALSE(camera.project(camera.generateRay(-1.0f, 5.0f).at(2)));  // left of the image
    // The directional density over the image is normalised: sum pdf(w) dw over a fine grid of
    // pixels, dw = dA cos^3 / 1 on the plane at distance 1 (independent of the formula's form).
    const double halfHeight = std::tan(glm::radians(25.0)), halfWidth = halfHeight * 64.0 / 40.0;
    double integral = 0.0;
    const int n = 400;
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            const Ray ray = camera.generateRay((i + 0.5f) * 64.0f / n, (j + 0.5f) * 40.0f / n);
            const double u = (2.0 * (i + 0.5) / n - 1.0) * halfWidth, v = (2.0 * (j + 0.5) / n - 1.0) * halfHeight;
            const double r2 = 1.0 + u * u + v * v;
            const double dA = (2.0 * halfWidth / n) * (2.0 * halfHeight / n);
            integral += camera.pdfDirection(ray.direction) * dA / (r2 * std::sqrt(r2));
        }
    }
    CHECK(integral == doctest::Approx(1.0).epsilon(1e-3));
}

// Random paths x0 (on a light) ... x(n-1) (the eye) inside a closed sphere whose wall is diffuse,
// glossy, a mirror and an emitter at once, lit also by a point light and by a small emitting
// sphere that light sampling samples by the cone it subtends (not by area, as emission does):
// every strategy can make every path (the weights are of the points given, whatever lies between).
// Each strategy's subpaths are rebuilt through the given points by the integrator's own vertex
// code, and their weights must sum to one.
TEST_CASE("bdpt: the MIS weights of all strategies of a path sum to 1 over random paths") {
    Scene scene;
    scene.camera = test::centredCamera({0.1f, -0.2f, 0.3f}, {0, 0, -1}, {0, 1, 0}, 33);
    scene.camera.verticalFovDegrees = 70.0f;
    PhongMaterial wall;
    wall.name = "wall";
    wall.kd = Rgb{0.4f};
    wall.ks = Rgb{0.3f};
    wall.n = 12.0f;
    wall.kr = Rgb{0.2f};
    wall.emission = Rgb{1.0f};
    test::addSphere(scene, "room", test::addMaterial(scene, wall), {0, 0, 0}, 1.0f);
    scene.lights.push_back(PointLight{"bulb", {-0.2f, 0.4f, 0.1f}, Rgb{1.0f}, {0, 0, 1}});
    PhongMaterial lamp;
    lamp.name = "lamp";
    lamp.kd = Rgb{0.5f};
    lamp.emission = Rgb{3.0f};
    test::addSphere(scene, "lamp", test::addMaterial(scene, lamp), {0.3f, 0.2f, -0.4f}, 0.1f);
    const World world(scene);
    const RenderContext& ctx = world.context;
    const Light& areaLight = *world.lights.lightOfObject(0);
    const Light& sphereLight = *world.lights.lightOfObject(1);
    const Light& pointLight = *world.lights.deltaLights()[0];
    int coneSampled = 0;

    Pcg32 rng(2024, 1);
    auto u2 = [&] { return Vec2{rng.nextFloat(), rng.nextFloat()}; };
    auto smoothLobe = [&] { return rng.nextFloat() < 0.5f ? PhongMaterial::kDiffuse : PhongMaterial::kHighlight; };
    // Every material here is Phong's: a lobe index is one of its lobes.
    auto isDelta = [](int lobe) { return PhongMaterial::kLobes[lobe].delta(); };
    int paths = 0, shared = 0, withDelta = 0;
    double worst = 0.0;
    for (int trial = 0; trial < 3000; ++trial) {
        const int n = 3 + trial % 5;  // 3 .. 7 vertices
        const Light& light = trial % 3 == 0 ? areaLight : trial % 3 == 1 ? sphereLight : pointLight;
        // x0 and a light walk to x(n-3), then the eye's first hit x(n-2) and the eye x(n-1).
        std::vector<SurfaceHit> hits(n);
        std::vector<int> lobes(n, PhongMaterial::kDiffuse);
        const EmittedRay e = light.sampleEmission(u2(), u2());
        CHECK(light.pdfEmissionDirection(e.normal, e.ray.direction) == doctest::Approx(e.pdfDirection).epsilon(1e-4));
        Ray ray{e.ray.origin + 1e-4f * e.ray.direction, e.ray.direction};  // off the light's own surface
        bool ok = true;
        for (int i = 1; i <= n - 3 && ok; ++i) {
            const auto hit = world.geometry.intersect(ray);
            if (!hit) { ok = false; break; }
            hits[i] = *hit;
            const ShadingPoint sp = makeShadingPoint(*hit, ray, ctx, TransportMode::Importance);
            const auto step = sampledStep(sp, rng.nextFloat(), u2());
            if (i == n - 3) {
                lobes[i] = smoothLobe();  // the last light-side vertex meets the eye's: smooth
                break;
            }
            if (!step) {
                ok = false;
                break;
            }
            lobes[i] = step->lobe;
            withDelta += step->delta;
            ray = Ray{hit->point + 1e-4f * step->wi, step->wi};
        }
        const Ray cameraRay = world.camera.generateRay(33.0f * rng.nextFloat(), 33.0f * rng.nextFloat());
        const auto first = world.geometry.intersect(cameraRay);
        if (!ok || !first) continue;
        hits[n - 2] = *first;
        lobes[n - 2] = smoothLobe();
        std::vector<Vec3> points(n);
        points[0] = e.ray.origin;
        for (int i = 1; i < n - 1; ++i) points[i] = hits[i].point;
        points[n - 1] = world.camera.eye();

        double sum = 0.0, sumMoreWalks = 0.0;
        int contributing = 0;
        for (int s = 0; s < n; ++s) {
            const int t = n - s;
            std::array<BdptVertex, kMaxSubpathVertices> lightPath, eyePath;
            // Light subpath x0 .. x(s-1), as a light walk would have made it.
            if (s >= 1) {
                // Light sampling from x1 picks x0 by its own density; emission by e.pdfPosition.
                const float pdfPosition =
                    light.isDelta() ? e.pdfPosition : lightSamplingAreaDensity(light, points[1], points[0], e.normal);
                lightPath[0] = lightVertex(light, points[0], e.normal, pdfPosition, e.pdfPosition);
                lightPath[0].pdfFwd = world.lights.emitterProbability(light) * e.pdfPosition;
                coneSampled += !light.samplesByArea(points[1]);
                float pdf = light.pdfEmissionDirection(e.normal, glm::normalize(points[1] - points[0]));
                bool delta = false;
                for (int i = 1; i < s; ++i) {
                    const Vec3 w = glm::normalize(points[i] - points[i - 1]);
                    setSurfaceVertex(lightPath[i], hits[i], Ray{points[i - 1], w}, Rgb{1.0f}, lightPath[i - 1], pdf, delta,
                                     ctx, TransportMode::Importance);
                    if (i >= 2) linkThrough(lightPath[i - 2], lightPath[i - 1], lightPath[i]);
                    if (i + 1 < s) {
                        const ScatterStep step =
                            prescribedStep(*lightPath[i].surface, lobes[i], glm::normalize(points[i + 1] - points[i]));
                        lightPath[i].lobe = step.lobe;
                        lightPath[i].delta = step.delta;
                        pdf = step.pdf;
                        delta = step.delta;
                    }
                }
            }
            // Eye subpath x(n-1) .. x(s), as the eye's walk would have made it.
            eyePath[0] = cameraVertex(points[n - 1]);
            float pdf = world.camera.pdfDirection(glm::normalize(points[n - 2] - points[n - 1]));
            bool delta = false;
            for (int j = 1; j < t; ++j) {
                const int i = n - 1 - j;
                const Vec3 w = glm::normalize(points[i] - points[i + 1]);
                const SurfaceHit hit = i == 0 ? SurfaceHit{1.0f, points[0], e.normal, e.normal, 0} : hits[i];
                setSurfaceVertex(eyePath[j], hit, Ray{points[i + 1], w}, Rgb{1.0f}, eyePath[j - 1], pdf, delta, ctx,
                                 TransportMode::Radiance);
                if (j >= 2) linkThrough(eyePath[j - 2], eyePath[j - 1], eyePath[j]);
                if (j + 1 < t) {
                    const ScatterStep step = prescribedStep(*eyePath[j].surface, lobes[i], glm::normalize(points[i - 1] - points[i]));
                    eyePath[j].lobe = step.lobe;
                    eyePath[j].delta = step.delta;
                    pdf = step.pdf;
                    delta = step.delta;
                }
            }
            if (s == 0) {
                if (light.isDelta()) continue;  // nothing hits a point
                markEmitter(eyePath[t - 1], light, eyePath[t - 2]);
            }
            const int lightLobe = s >= 1 ? lobes[s - 1] : int(PhongMaterial::kDiffuse);
            const int eyeLobe = lobes[s];
            // A join cannot pass through a mirror bounce: that strategy does not make this path.
            if ((s >= 2 && isDelta(lightLobe)) || (t >= 2 && s >= 1 && isDelta(eyeLobe))) continue;
            const PathDensities densities = joinedDensities({lightPath.data(), std::size_t(s)}, lightLobe,
                                                            {eyePath.data(), std::size_t(t)}, eyeLobe, ctx);
            const float w = misWeight(densities, s, 1.0);
            // 2.5 light walks per camera sample: light tracing counts 2.5, the joins 1.
            const float w2 = misWeight(densities, s, 2.5);
            REQUIRE(std::isfinite(w));
            REQUIRE(std::isfinite(w2));
            sum += w;
            sumMoreWalks += w2;
            contributing += w > 1e-6f;
        }
        ++paths;
        shared += contributing >= 2;
        worst = std::max(worst, std::fabs(sum - 1.0));
        CAPTURE(n);
        CAPTURE(trial);
        CHECK(sum == doctest::Approx(1.0).epsilon(1e-4));
        CHECK(sumMoreWalks == doctest::Approx(1.0).epsilon(1e-4));
    }
    CAPTURE(worst);
    CHECK(paths > 2000);
    CHECK(shared > paths / 2);  // most paths are found by more than one strategy
    CHECK(withDelta > 100);     // and many pass a mirror bounce
    CHECK(coneSampled > 1000);  // and many start on the sphere light seen from outside
}

// Renders with light tracing alone (t = 1, unweighted), splats summed as the renderer does.
Film lightTrace(const World& world, int spp) {
    const int width = world.camera.width(), height = world.camera.height();
    BdptIntegrator integrator(BdptIntegrator::Strategies::LightTracingOnly);
    BdptIntegrator& base = integrator;
    base.preprocess(world.context);
    SplatFilm splats(width, height, world.aovs.layerCount());
    std::vector<Rgb> layers(world.aovs.layerCount());
    ContributionSink sink(layers, &splats);
    RayCounters counters;
    PathState path(world.context, sink, counters);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            for (int i = 0; i < spp; ++i) {
                Sampler sampler = Sampler::forPixel(SamplerKind::Independent, x, y, i, spp, 1);
                path.sampler = &sampler;
                REQUIRE(path.push({lpe::EventType::Camera, lpe::Scatter::None, Subject::None, 0, world.camera.eye()}));
                base.traceCameraRay(world.camera.generateRay(x + 0.5f, y + 0.5f), path);
                path.pop();
            }
        }
    }
    CHECK(isBlack(layers[0]));  // light tracing adds only through splats
    Film film(width, height, world.aovs.layerNames());
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (std::size_t l = 0; l < world.aovs.layerCount(); ++l) film.at(l, x, y) = splats.at(x, y, l) / float(spp);
    return film;
}

// The mean over pixel (i, j) of a function of the floor point y = 0 its rays see, by an 8x8 grid:
// light tracing estimates the pixel's mean radiance, not its centre's.
template <class F>
double pixelMean(const Camera& camera, int i, int j, F f) {
    double sum = 0.0;
    for (int b = 0; b < 8; ++b) {
        for (int a = 0; a < 8; ++a) {
            const Ray ray = camera.generateRay(i + (a + 0.5f) / 8.0f, j + (b + 0.5f) / 8.0f);
            const glm::dvec3 d(ray.direction), o(ray.origin);
            sum += f(o + (-o.y / d.y) * d);
        }
    }
    return sum / 64.0;
}

Scene floorUnderLight(const glm::dvec3& light, const glm::dvec3& attenuation) {
    Scene scene;
    scene.camera = test::centredCamera({0.3f, 1.0f, 0.2f}, {0.3f, 0, 0.2f}, {0, 0, -1}, 21);
    scene.camera.verticalFovDegrees = 60.0f;
    PhongMaterial floor;
    floor.name = "floor";
    floor.kd = Rgb{0.6f};
    test::addPlane(scene, "floor", test::addMaterial(scene, floor), {0, 0, 0}, {0, 1, 0});
    scene.lights.push_back(PointLight{"key", Vec3(light), Rgb{3.0f}, Vec3(attenuation)});
    return scene;
}

void checkAgainst(const Film& film, std::size_t layer, const Camera& camera,
                  const std::function<double(const glm::dvec3&)>& expected) {
    std::vector<double> differences, wrong;
    for (int j = 0; j < film.height(); ++j) {
        for (int i = 0; i < film.width(); ++i) {
            const double e = pixelMean(camera, i, j, expected);
            differences.push_back(film.at(layer, i, j).g - e);
            wrong.push_back(film.at(layer, i, j).g - 1.05 * e);
        }
    }
    CAPTURE(test::meanOf(differences));
    CHECK(studentTTest(differences, 0.0) > kPValue);
    CHECK(studentTTest(wrong, 0.0) < kPValue);
}

TEST_CASE("bdpt: light tracing alone lights a Lambertian plane under a point light as kd I cos(theta) falloff(d)") {
    const glm::dvec3 light{0.7, 1.5, -0.4};
    for (const glm::dvec3 attenuation : {glm::dvec3{0, 0, 1}, glm::dvec3{1, 0.1, 0.01}}) {
        CAPTURE(attenuation.x);
        const World world(floorUnderLight(light, attenuation), {});
        const Film film = lightTrace(world, 1024);
        checkAgainst(film, 0, world.camera, [&](const glm::dvec3& p) {
            const glm::dvec3 toLight = light - p;
            const double d = glm::length(toLight);
            return 0.6 * 3.0 * (toLight.y / d) / (attenuation.x + attenuation.y * d + attenuation.z * d * d);
        });
    }
}

// A mirror wall x = 1 beside a diffuse floor: light reaching the floor by the mirror (E D S L) is
// the light's mirror image at (2 - x, y, z), kr times as bright, under the inverse-square law.
// lightWalkFraction 0 leaves the number of light walks to the pilot.
void checkMirrorCaustic(int spp, std::uint64_t seed, double lightWalkFraction) {
    const glm::dvec3 light{0.3, 1.2, 0.1}, image{2.0 - light.x, light.y, light.z};
    const double kr = 0.8;
    Scene scene = floorUnderLight(light, {0, 0, 1});
    scene.camera = test::centredCamera({0.2f, 1.0f, 0.1f}, {0.2f, 0, 0.1f}, {0, 0, -1}, 31);
    scene.camera.verticalFovDegrees = 50.0f;
    PhongMaterial mirror;
    mirror.name = "mirror";
    mirror.kr = Rgb{float(kr)};
    test::addPlane(scene, "mirror", test::addMaterial(scene, mirror), {1, 0, 0}, {-1, 0, 0});
    const std::vector<lpe::NamedExpression> set{{"caustic", "E(D|G)S+L"}};
    const Film film = render(scene, set, "bdpt", spp, 5, seed, 0, lightWalkFraction);
    checkAgainst(film, 1, Camera(scene.camera), [&](const glm::dvec3& p) {
        const glm::dvec3 toImage = image - p;
        const double d = glm::length(toImage);
        return kr * 0.6 * 3.0 * (toImage.y / d) / (d * d);
    });
}

// About a million camera samples: statistical (the sanitizer stage runs the 2.5-walk case below,
// the same code at half the samples).
TEST_CASE("bdpt: a mirror's caustic is the mirror image of the point light, scaled by kr" * doctest::test_suite("statistical")) {
    checkMirrorCaustic(1024, 21, 0.0);
}

// More light walks than camera samples: light tracing's splats count q in the weights and are
// divided by q, the joins keep the first walk's, so the caustic (splats alone) and the furnace
// (every strategy) keep their closed forms. 2.5: two walks, and a third for half the samples.
TEST_CASE("bdpt: with 2.5 light walks per camera sample, the mirror's caustic is the light's mirror image") {
    checkMirrorCaustic(512, 23, 2.5);
}

TEST_CASE("bdpt: with 2 light walks per camera sample, the point-light furnace keeps its closed forms") {
    Scene scene = furnace(0.5f, Rgb{0.0f});
    scene.lights.push_back(PointLight{"centre", {0, 0, 0}, Rgb{1.0f}, {0, 0, 1}});
    const Film film = render(scene, classesSet(), "bdpt", 32, 64, 7, 0, 2.0);
    checkLayer(film, "beauty", 1.0);
    checkLayer(film, "raycast", 0.5);
    checkLayer(film, "indirect", 0.5);
}

TEST_CASE("bdpt: the caustic under a point light behind a glass ball is found by bdpt and is exactly zero under path") {
    Scene scene = loadScene(LIGHTPATH_SOURCE_DIR "/scenes/glass-sphere.toml");
    scene.camera.width = 64;
    scene.camera.height = 48;
    // A bare L also matches the background, which the path tracer does see through the glass from
    // the floor (E D S B): without a background, E(D|G)S+L is light from the lamp alone.
    scene.background = Rgb{0.0f};
    const std::vector<lpe::NamedExpression> set{{"caustic", "E(D|G)S+L"}};
    auto total = [](const Film& film) {
        double sum = 0.0;
        for (int y = 0; y < film.height(); ++y)
            for (int x = 0; x < film.width(); ++x) sum += film.at(1, x, y).g;
        return sum;
    };
    const double path = total(render(scene, set, "path", 4, 5, 1));
    const double bdpt = total(render(scene, set, "bdpt", 4, 5, 1));
    CHECK(path == 0.0);
    CHECK(bdpt > 0.0);
}

// Light tracing and the eye's samples must estimate one integral per pixel: the pixel filter's
// weighted mean of the radiance. A point light two pixels above a floor seen from above makes a
// spot sharp enough that a tent's mean, a box's mean and the centre's value differ by several
// percent: a bdpt that splats with a box while its eye samples follow the tent (or go through the
// centre at 1 spp) lands between them, by the MIS weights. Light tracing's weight against the eye's
// is r^2 / (1 + r^2) (power heuristic), r the ratio of their densities on the floor: 1 / (4 pi d^2)
// for the light, 1 / (the image's area on the floor) for the eye, so r = N^2 / (16 pi) at N x N
// pixels: about 4.5 at 15 (light tracing carries the spot), about 0.2 at 3 (the eye does).
struct SpotFloor {
    static constexpr double kHeight = 2.0, kKd = 0.6, kIntensity = 3.0;
    Scene scene;
    int size;
    double lightHeight;

    explicit SpotFloor(int pixels) : size(pixels) {
        scene.camera = test::centredCamera({0, float(kHeight), 0}, {0, 0, 0}, {0, 0, -1}, size);
        scene.camera.verticalFovDegrees = 60.0f;
        const double pixel = 2.0 * kHeight * std::tan(kPi / 6.0) / size;
        lightHeight = 2.0 * pixel;
        PhongMaterial floor;
        floor.name = "floor";
        floor.kd = Rgb{float(kKd)};
        test::addPlane(scene, "floor", test::addMaterial(scene, floor), {0, 0, 0}, {0, 1, 0});
        scene.lights.push_back(PointLight{"key", {0, float(lightHeight), 0}, Rgb{float(kIntensity)}, {0, 0, 1}});
    }
    // kd I cos(theta) / d^2 at floor point p.
    double radiance(const glm::dvec3& p) const {
        const glm::dvec3 toLight = glm::dvec3{0, lightHeight, 0} - p;
        const double d = glm::length(toLight);
        return kKd * kIntensity * (toLight.y / d) / (d * d);
    }
    // The filter-weighted mean of the radiance over pixel (i, j): profile(x) profile(y) over
    // [-radius, radius]^2 around its centre, by a fine midpoint grid.
    template <class Profile>
    double filtered(int i, int j, double radius, Profile profile) const {
        const Camera camera(scene.camera);
        constexpr int kGrid = 96;
        double sum = 0.0, weights = 0.0;
        for (int b = 0; b < kGrid; ++b) {
            for (int a = 0; a < kGrid; ++a) {
                const double x = -radius + 2.0 * radius * (a + 0.5) / kGrid, y = -radius + 2.0 * radius * (b + 0.5) / kGrid;
                const double w = profile(x) * profile(y);
                const Ray ray = camera.generateRay(float(i + 0.5 + x), float(j + 0.5 + y));
                const glm::dvec3 d(ray.direction), o(ray.origin);
                sum += w * radiance(o + (-o.y / d.y) * d);
                weights += w;
            }
        }
        return sum / weights;
    }
    double tent(int i, int j) const { return filtered(i, j, 1.0, [](double x) { return 1.0 - std::fabs(x); }); }
    double box(int i, int j) const { return filtered(i, j, 0.5, [](double) { return 1.0; }); }
};

// The centre pixel and its four neighbours from `renders` independent renders.
std::vector<std::vector<double>> spotPixels(const SpotFloor& spot, const char* integrator, PixelFilterKind filter, int spp,
                                            int renders) {
    std::vector<std::vector<double>> values(5);
    const int c = spot.size / 2;
    const int pixels[5][2] = {{c, c}, {c + 1, c}, {c - 1, c}, {c, c + 1}, {c, c - 1}};
    const AovSet aovs({});
    for (int r = 0; r < renders; ++r) {
        RenderOptions options;
        options.integrator = integrator;
        options.samplesPerPixel = spp;
        options.maxDepth = 1;
        options.seed = 1000 + r;
        options.filter = filter;
        const Film film = Renderer(spot.scene, aovs, options).render().film;
        for (int k = 0; k < 5; ++k) values[k].push_back(film.at(0, pixels[k][0], pixels[k][1]).g);
    }
    return values;
}

void checkSpot(const std::vector<std::vector<double>>& values, const std::vector<double>& expected, double control) {
    for (std::size_t k = 0; k < values.size(); ++k) {
        CAPTURE(k);
        CAPTURE(test::meanOf(values[k]));
        CAPTURE(expected[k]);
        CHECK(studentTTest(values[k], expected[k]) > kPValue);
    }
    // The control: the centre pixel is told apart from the other integral.
    CAPTURE(control);
    CHECK(studentTTest(values[0], control) < kPValue);
}

TEST_CASE("bdpt: with a tent filter, splats and eye samples estimate the tent's mean, as the path tracer does" * doctest::test_suite("statistical")) {
    const SpotFloor spot(15);
    const int c = spot.size / 2;
    const std::vector<double> tent = {spot.tent(c, c), spot.tent(c + 1, c), spot.tent(c - 1, c), spot.tent(c, c + 1),
                                      spot.tent(c, c - 1)};
    const double box = spot.box(c, c);
    CAPTURE(tent[0]);
    CAPTURE(box);
    REQUIRE(std::fabs(box / tent[0] - 1.0) > 0.04);  // the integrals differ enough to tell apart
    checkSpot(spotPixels(spot, "path", PixelFilterKind::Tent, 64, 16), tent, box);
    checkSpot(spotPixels(spot, "bdpt", PixelFilterKind::Tent, 64, 64), tent, box);
}

TEST_CASE("bdpt: at 1 spp, splats and eye samples estimate the same pixel mean") {
    const SpotFloor spot(3);
    const int c = spot.size / 2;
    const std::vector<double> box = {spot.box(c, c), spot.box(c + 1, c), spot.box(c - 1, c), spot.box(c, c + 1),
                                     spot.box(c, c - 1)};
    const Camera camera(spot.scene.camera);
    const Ray centreRay = camera.generateRay(c + 0.5f, c + 0.5f);
    const glm::dvec3 d(centreRay.direction), o(centreRay.origin);
    const double centre = spot.radiance(o + (-o.y / d.y) * d);
    CAPTURE(centre);
    REQUIRE(std::fabs(box[0] / centre - 1.0) > 0.04);
    checkSpot(spotPixels(spot, "bdpt", PixelFilterKind::Box, 1, 4096), box, centre);
}


// The glass ball's caustic at 24 x 18 pixels under bdpt on one thread: small enough to trace
// every light path of the image in a test.
struct SmallCaustic {
    Scene scene = [] {
        Scene s = loadScene(LIGHTPATH_SOURCE_DIR "/scenes/glass-sphere.toml");
        s.camera.width = 24;
        s.camera.height = 18;
        return s;
    }();
    AovSet aovs{std::vector<lpe::NamedExpression>{{"caustic", "E(D|G)S+L"}}};
    RenderOptions options = [] {
        RenderOptions o;
        o.integrator = "bdpt";
        o.threads = 1;
        return o;
    }();
};

TEST_CASE("bdpt: one renderer renders at one sample per pixel exactly as a renderer built for one does, splats included") {
    SmallCaustic small;
    const Scene& scene = small.scene;
    const AovSet& aovs = small.aovs;
    RenderOptions options = small.options;
    options.samplesPerPixel = 1;
    const Film single = Renderer(scene, aovs, options).render(3).film;
    options.samplesPerPixel = 4;
    const Renderer four(scene, aovs, options);
    const Film overridden = four.render(3, 1).film;
    const auto a = single.interleaved(), b = overridden.interleaved();
    CHECK(std::equal(a.begin(), a.end(), b.begin(), b.end()));
    CHECK_THROWS_AS(four.render(3, 0), std::invalid_argument);
}

TEST_CASE("bdpt: an explanation stops when cancelled: its light tracing would trace every pixel on one thread") {
    SmallCaustic small;
    const Scene& scene = small.scene;
    const AovSet& aovs = small.aovs;
    RenderOptions options = small.options;
    const Renderer renderer(scene, aovs, options);
    std::atomic<bool> cancel{false};
    const auto answered = renderer.explainPixel(12, 9, nullptr, {.cancel = &cancel});
    CHECK_FALSE(answered.empty());
    cancel = true;
    CHECK_THROWS_AS(renderer.explainPixel(12, 9, nullptr, {.cancel = &cancel}), ExplainCancelled);
    // Without light tracing an explanation is the pixel's own samples: bounded, always answered.
    options.integrator = "path";
    const Renderer path(scene, aovs, options);
    CHECK_NOTHROW(path.explainPixel(12, 9, nullptr, {.cancel = &cancel}));
}

}  // namespace
}  // namespace lightpath
