// One light transport for every method (docs/design.md, "One light transport"). The lecture's
// taxonomy nests by construction: ray casting's light is the path tracer's E(D|G)L, and what
// Whitted adds is the path tracer's ES+(D|G)L and ES+L — tested as expectations on every shipped
// scene (a t-test on the AOV means and per-pixel Welch tests), each with a control, the scene made
// 5% brighter for one integrator, that must be rejected. And the path tracer still converges to the
// Cornell box it rendered before the unification, when it agreed with a production path tracer.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "film/aov_set.h"
#include "render/renderer.h"
#include "lights/point_light.h"
#include "../support/shipped_scenes.h"
#include "scene/scene_loader.h"
#include "../support/statistics.h"

namespace lightpath {
namespace {

constexpr double kPValue = 0.001;  // rejection threshold of one test
constexpr int kRenders = 16;       // independent renders per estimate: per-pixel variances

// Per pixel, over kRenders independent renders: the mean and sample variance of one expression's
// AOV, R + G + B.
struct PixelEstimates {
    std::vector<double> mean, variance;
    double count = kRenders;
};

PixelEstimates estimate(const Scene& scene, const std::string& integrator, int spp, const std::string& expression) {
    const AovSet aovs(std::vector<lpe::NamedExpression>{{"a", expression}});
    const std::size_t pixels = static_cast<std::size_t>(scene.camera.width) * scene.camera.height;
    PixelEstimates e{std::vector<double>(pixels, 0.0), std::vector<double>(pixels, 0.0)};
    std::vector<double> sumOfSquares(pixels, 0.0);
    for (int r = 0; r < kRenders; ++r) {
        RenderOptions options;
        options.integrator = integrator;
        options.samplesPerPixel = spp;
        options.seed = 1000 + r;
        // Independent samples, not the default Sobol: the per-pixel Welch tests need each render's
        // pixel to vary roughly normally, with a variance 16 renders can estimate. Under Sobol a
        // pixel's few samples hit an edge or a small highlight a nearly fixed number of times, so
        // its 16 estimates take one or two values and their spread misjudges the variance (under
        // Sobol, two scenes had 8 pixels rejected where 7 are allowed, with the means agreeing).
        options.sampler = SamplerKind::Independent;
        options.writeBeauty = false;
        const Film film = Renderer(scene, aovs, options).render().film;
        for (int y = 0; y < film.height(); ++y) {
            for (int x = 0; x < film.width(); ++x) {
                const Rgb a = film.at(0, x, y);
                const double v = double(a.r) + a.g + a.b;
                const std::size_t i = static_cast<std::size_t>(y) * film.width() + x;
                e.mean[i] += v / kRenders;
                sumOfSquares[i] += v * v;
            }
        }
    }
    for (std::size_t i = 0; i < pixels; ++i)
        e.variance[i] = std::max(0.0, (sumOfSquares[i] - kRenders * e.mean[i] * e.mean[i]) / (kRenders - 1));
    return e;
}

struct Verdict {
    double meanPValue;        // t-test over pixels that the per-pixel differences average to zero
    int pixelsRejected;       // pixels whose Welch test rejects at 1%
    int pixelsAllowed;        // how many of those H0 explains (binomial mean + 4 sigma)
    double classicMean, pathMean;
    bool accepted() const { return meanPValue > kPValue && pixelsRejected <= pixelsAllowed; }
    bool rejected() const { return meanPValue < kPValue && pixelsRejected > pixelsAllowed; }
};

Verdict compare(const PixelEstimates& path, const PixelEstimates& classic) {
    Verdict v{1.0, 0, 0, 0.0, 0.0};
    std::vector<double> differences;
    const std::size_t n = path.mean.size();
    for (std::size_t i = 0; i < n; ++i) {
        differences.push_back(path.mean[i] - classic.mean[i]);
        v.pathMean += path.mean[i] / double(n);
        v.classicMean += classic.mean[i] / double(n);
        if (test::welchTTest(path.mean[i], path.variance[i], path.count, classic.mean[i], classic.variance[i], classic.count) < 0.01)
            ++v.pixelsRejected;
    }
    v.meanPValue = test::studentTTest(differences, 0.0);
    v.pixelsAllowed = static_cast<int>(0.01 * n + 4.0 * std::sqrt(0.01 * 0.99 * n));
    return v;
}

Scene smallScene(const std::filesystem::path& file, int width = 16) {
    Scene scene = loadScene(file);
    scene.camera.height = std::max(1, scene.camera.height * width / scene.camera.width);
    scene.camera.width = width;
    return scene;
}

// Every light and the background 5% brighter: the control that must be rejected.
Scene brighter(Scene scene) {
    for (LightSlot& light : scene.lights) pointLightOf(light).intensity *= 1.05f;
    for (MaterialSlot& material : scene.materials) material->emission = material->emission.constant() * 1.05f;
    scene.background *= 1.05f;
    return scene;
}

using test::shippedScenes;

bool allZero(const PixelEstimates& e) {
    return std::all_of(e.mean.begin(), e.mean.end(), [](double v) { return v == 0.0; });
}

// Every light but the ambient term — the lights of the scene file (L) and emitting surfaces (O): the
// classic methods' fake stands in for light the path tracer computes, and so does sky light on
// diffuse surfaces (E D B), which only the path tracer gathers.
constexpr const char* kRealLights = "(<L[^'ambient']>|O)";

// The classic integrator's light on `expression` against the path tracer's on the same expression.
void checkNesting(const std::string& classic, const std::string& expression, const char* controlScene) {
    const auto scenes = shippedScenes();
    REQUIRE(scenes.size() >= 10);
    for (const auto& file : scenes) {
        CAPTURE(file.filename().string());
        const Scene scene = smallScene(file);
        const PixelEstimates classicLight = estimate(scene, classic, 4, expression);
        const PixelEstimates pathLight = estimate(scene, "path", 64, expression);
        if (allZero(classicLight)) {
            // Nothing on these paths in this scene (no mirror, no glass): none for the path tracer either.
            CHECK(allZero(pathLight));
            continue;
        }
        const Verdict v = compare(pathLight, classicLight);
        CAPTURE(v.classicMean);
        CAPTURE(v.pathMean);
        CAPTURE(v.meanPValue);
        CAPTURE(v.pixelsRejected);
        CHECK(v.accepted());
    }
    // The control: a scene whose light on these paths fills the image, 5% brighter under the
    // classic integrator only.
    const Scene scene = smallScene(std::filesystem::path(LIGHTPATH_SOURCE_DIR "/scenes") / controlScene, 32);
    const Verdict control = compare(estimate(scene, "path", 256, expression),
                                    estimate(brighter(scene), classic, 4, expression));
    CAPTURE(control.classicMean);
    CAPTURE(control.pathMean);
    CAPTURE(control.meanPValue);
    CAPTURE(control.pixelsRejected);
    CHECK(control.rejected());
}

TEST_CASE("nesting: ray casting without its ambient is the path tracer's E(D|G)(<L[^'ambient']>|O) on every shipped scene" * doctest::test_suite("statistical")) {
    checkNesting("raycast", std::string("E(D|G)") + kRealLights, "lecture-room.toml");
}

TEST_CASE("nesting: what Whitted adds (ES+(D|G)(<L[^'ambient']>|O)) is the path tracer's" * doctest::test_suite("statistical")) {
    checkNesting("whitted", std::string("ES+(D|G)") + kRealLights, "mirror-hall.toml");
}

TEST_CASE("nesting: the emitters Whitted sees through mirrors and glass (ES+L) are the path tracer's" * doctest::test_suite("statistical")) {
    checkNesting("whitted", "ES+L", "mirror-sphere.toml");
}

// The nest extended to participating media (issue #24) on the shipped fog scene: a classic
// integrator's single scattering against the path tracer's on the same expression, over the pixels
// that hold any of that light (elsewhere both are zero: the fog's shafts cover part of the image,
// the glass ball's refractions a small part), and the control, the lamp 5% brighter for the classic
// integrator only, rejected by the mean's t-test.
Scene fogShafts(int width) {
    Scene scene = smallScene(std::filesystem::path(LIGHTPATH_SOURCE_DIR "/scenes") / "fog-shafts.toml", width);
    REQUIRE(!scene.media.empty());
    return scene;
}

// The fog scene seen closer: the camera turned to the glass ball and its field of view narrowed to
// frame it, so every pixel holds light through the glass. At the scene's own framing the ball
// covers 3% of the image, and the path tracer spent 97% of its samples where E S+ V <L.> is zero.
Scene glassBallCloseUp(int width) {
    Scene scene = fogShafts(width);
    const auto glass = std::find_if(scene.spheres.begin(), scene.spheres.end(), [&](const Sphere& s) {
        return scene.objects[s.object].name == "glass-ball";
    });
    REQUIRE(glass != scene.spheres.end());
    CameraDescription& camera = scene.camera;
    camera.lookAt = glass->center;
    const float halfAngle = std::asin(glass->radius / glm::length(glass->center - camera.eye));
    camera.verticalFovDegrees = glm::degrees(2.0f * halfAngle) * 1.1f;
    return scene;
}

void checkMediaNesting(const Scene& scene, const std::string& classic, const std::string& expression, int pathSpp) {
    const auto lit = [](const PixelEstimates& a, const PixelEstimates& b) {
        PixelEstimates x{{}, {}}, y{{}, {}};
        for (std::size_t i = 0; i < a.mean.size(); ++i) {
            if (a.mean[i] == 0.0 && b.mean[i] == 0.0) continue;
            x.mean.push_back(a.mean[i]);
            x.variance.push_back(a.variance[i]);
            y.mean.push_back(b.mean[i]);
            y.variance.push_back(b.variance[i]);
        }
        REQUIRE(x.mean.size() >= 8);  // the light this expression names is seen
        return compare(x, y);
    };
    // One scene for the test and its control, so the comparison has the power the control shows,
    // and the path tracer's estimate serves both.
    const PixelEstimates pathLight = estimate(scene, "path", pathSpp, expression);
    const Verdict v = lit(pathLight, estimate(scene, classic, 4, expression));
    CAPTURE(v.classicMean);
    CAPTURE(v.pathMean);
    CAPTURE(v.meanPValue);
    CAPTURE(v.pixelsRejected);
    CHECK(v.accepted());
    const Verdict control = lit(pathLight, estimate(brighter(scene), classic, 4, expression));
    CAPTURE(control.classicMean);
    CAPTURE(control.pathMean);
    CAPTURE(control.meanPValue);
    CAPTURE(control.pixelsRejected);
    // The mean over the lit pixels must reject it; per pixel, 5% is within the path tracer's
    // noise on the few pixels of the glass ball (accepted() above still holds each pixel to 1%).
    CHECK(control.meanPValue < kPValue);
}

TEST_CASE("nesting with fog: ray casting's single scattering is the path tracer's E V <L.>" * doctest::test_suite("statistical")) {
    checkMediaNesting(fogShafts(32), "raycast", "EV<L.>", 256);
}

TEST_CASE("nesting with fog: Whitted's single scattering seen through glass (E S+ V <L.>) is the path tracer's" * doctest::test_suite("statistical")) {
    // The path tracer reaches these paths only through the glass ball (a camera ray that scatters
    // before meeting glass is cut there), each a free flight behind it.
    checkMediaNesting(glassBallCloseUp(32), "whitted", "ES+V<L.>", 512);
}

// The reference: tests/render/data/cornell-lamp.reference, one R G B line per pixel.
std::vector<Rgb> readReference(const std::filesystem::path& file) {
    std::ifstream in(file);
    REQUIRE(in);
    std::vector<Rgb> pixels;
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream values(line);
        Rgb v;
        values >> v.r >> v.g >> v.b;
        pixels.push_back(v);
    }
    return pixels;
}

TEST_CASE("the path tracer still converges to its Cornell box from before the shared transport") {
    const std::filesystem::path data = LIGHTPATH_SOURCE_DIR "/tests/render/data";
    const Scene scene = loadScene(data / "cornell-lamp.toml");
    const std::vector<Rgb> reference = readReference(data / "cornell-lamp.reference");
    REQUIRE(reference.size() == static_cast<std::size_t>(scene.camera.width * scene.camera.height));
    const AovSet none(std::vector<lpe::NamedExpression>{});
    RenderOptions options;
    options.integrator = "path";
    options.samplesPerPixel = 512;
    options.maxDepth = 64;
    options.seed = 3;
    const Film film = Renderer(scene, none, options).render().film;
    for (int c = 0; c < 3; ++c) {
        CAPTURE(c);
        std::vector<double> differences, differencesWrong;
        for (int y = 0; y < film.height(); ++y) {
            for (int x = 0; x < film.width(); ++x) {
                const double expected = reference[static_cast<std::size_t>(y) * film.width() + x][c];
                differences.push_back(film.at(0, x, y)[c] - expected);
                differencesWrong.push_back(film.at(0, x, y)[c] - 1.05 * expected);
            }
        }
        CHECK(test::studentTTest(differences, 0.0) > kPValue);
        CHECK(test::studentTTest(differencesWrong, 0.0) < kPValue);  // the control: 5% off is seen
    }
}

}  // namespace
}  // namespace lightpath
