#include "integrator_checks.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "film/aov_presets.h"
#include "film/aov_set.h"
#include "integrators/photon.h"
#include "lights/point_light.h"
#include "scene/scene_loader.h"
#include "cases.h"
#include "film_checks.h"
#include "sanitizer.h"
#include "statistics.h"

namespace lightpath::conformance {
namespace {

constexpr int kAgreementRenders = 12;

RenderResult render(const IntegratorInfo& integrator, const Scene& scene, const AovSet& aovs, RenderOptions options) {
    options.integrator = integrator.name;
    return Renderer(scene, aovs, options).render();
}

bool sameLayer(const Film& a, std::size_t la, const Film& b, std::size_t lb) {
    const auto x = a.layer(la), y = b.layer(lb);
    return std::equal(x.begin(), x.end(), y.begin(), y.end());
}

// Every value of every layer finite and non-negative, and no contribution dropped as non-finite.
void checkFinite(const RenderResult& rendered, const char* scene, CheckResult& result) {
    if (rendered.stats.rays.nonFinite != 0)
        result.fail(scene, ": ", rendered.stats.rays.nonFinite, " non-finite contributions dropped");
    if (!test::finiteNonNegative(rendered.film)) result.fail(scene, ": a pixel is not finite and non-negative");
}

double imageMean(const Film& film, std::size_t layer) {
    double total = 0.0;
    for (const Rgb& v : film.layer(layer)) total += double(v.r) + v.g + v.b;
    return total / (double(film.width()) * film.height());
}

}  // namespace

RenderOptions checkOptions(const IntegratorInfo& integrator) {
    RenderOptions options;
    // An integrator that sees pixels only at their centres takes exactly one sample (the renderer
    // refuses more).
    options.samplesPerPixel = integrator.make()->samplesPixelCentres() ? 1 : 4;
    options.threads = 2;
    options.radiosity.patchBudget = 1024;
    return options;
}

namespace {

// The sum, thread and skip checks compare renders with each other, not with light: they need
// every code path, not accuracy. Radiosity's solve was 90% of their CPU at checkOptions' 1024
// patches (7.2 s a render against 0.6 s for every other integrator); at 512 its first mesh (476
// elements) still spans two of its 256-element chunks and its refined one (1904) eight, so 3
// threads still split every pass of the solve. Its rays were the rest (3.7 s a render in Release,
// about 10x that under the sanitizers): 16 form-factor rays and 4 light samples (2x2 strata, the
// fewest the refinement's noise estimate pairs) still cut patches in every refinement pass.
//
// Under the sanitizers photon mapping's 200000 photons were then most of these checks' time (its
// preprocess, shot again for each render): a fifth of them (test::sanitizedCount) still fills ten
// of shootPhotons' 4096-photon chunks, which 3 threads split, and both maps. SPPM's passes keep
// their default: its 20000 photons a pass are five chunks already.
RenderOptions structuralOptions(const IntegratorInfo& integrator) {
    RenderOptions options = checkOptions(integrator);
    options.radiosity.patchBudget = 512;
    options.radiosity.formFactorRays = 16;
    options.radiosity.lightSamples = 4;
    if (test::kSanitized && std::string_view(integrator.name) == "photon") {
        ParameterValues parameters(integrator.schema);
        parameters.set("photons", test::sanitizedCount(int(kDefaultPhotons)));
        options.integratorParameters = std::move(parameters);
    }
    return options;
}

}  // namespace

CheckResult checkAovsSumToBeauty(const IntegratorInfo& integrator, const Scene& scene) {
    CheckResult result;
    const AovSet aovs(classesSet());
    const Film film = render(integrator, scene, aovs, structuralOptions(integrator)).film;
    for (int y = 0; y < film.height(); ++y)
        for (int x = 0; x < film.width(); ++x)
            if (film.at(film.layerCount() - 1, x, y) != Rgb{0.0f})
                result.fail("pixel ", x, ",", y, ": rest is not zero: a path outside every class");
    const double worst = test::worstSumError(film);
    if (!(worst <= 1.0)) result.fail("the AOVs do not sum to the beauty: worst error ", worst, " times the tolerance");
    if (!(imageMean(film, 0) > 0.0)) result.fail("the beauty is black");
    return result;
}

CheckResult checkThreadDeterminism(const IntegratorInfo& integrator, const Scene& scene) {
    CheckResult result;
    const AovSet aovs(classesSet());
    RenderOptions options = structuralOptions(integrator);
    options.threads = 1;
    const Film one = render(integrator, scene, aovs, options).film;
    options.threads = 3;
    const Film three = render(integrator, scene, aovs, options).film;
    for (std::size_t l = 0; l < one.layerCount(); ++l)
        if (!sameLayer(one, l, three, l)) result.fail("layer ", one.layerNames()[l], " differs between 1 and 3 threads");
    return result;
}

CheckResult checkSkipIdentity(const IntegratorInfo& integrator, const Scene& scene) {
    CheckResult result;
    const AovSet full(classesSet());
    const Film all = render(integrator, scene, full, structuralOptions(integrator)).film;
    for (std::size_t i = 0; i < classesSet().size(); ++i) {
        const lpe::NamedExpression& aov = classesSet()[i];
        RenderOptions options = structuralOptions(integrator);
        options.writeBeauty = false;  // only this AOV: every path it cannot accept is skipped
        const Film alone = render(integrator, scene, AovSet({aov}), options).film;
        if (!sameLayer(alone, 0, all, i + 1))
            result.fail("AOV ", aov.name, " alone differs from the same AOV in the full render");
    }
    return result;
}

Scene brighter(Scene scene, float factor) {
    for (LightSlot& light : scene.lights)
        if (auto* point = dynamic_cast<PointLight*>(&*light)) point->intensity *= factor;
    for (MaterialSlot& material : scene.materials) material->emission = material->emission.constant() * factor;
    scene.background *= factor;
    scene.ambient *= factor;
    return scene;
}

Agreements agreementsWithPath(const IntegratorInfo& integrator, const Scene& scene, const Scene& control) {
    const AovSet shared(std::vector<lpe::NamedExpression>{{"shared", integrator.pathLanguage}});
    // Independent samples, so that the renders' means are independent estimates, as Welch's test
    // needs. An integrator that sees each pixel at its centre takes one sample per render; the
    // path tracer then takes one too, which goes through the centre, so both estimate the same
    // pixel values, and each estimate averages passes of such renders.
    const bool centres = integrator.make()->samplesPixelCentres();
    RenderOptions options = checkOptions(integrator);
    options.writeBeauty = false;
    options.sampler = SamplerKind::Independent;
    options.samplesPerPixel = centres ? 1 : 16;
    RenderOptions pathOptions = options;
    pathOptions.integrator = "path";
    pathOptions.samplesPerPixel = centres ? 1 : 64;  // the path tracer is the reference: less noise
    options.integrator = integrator.name;
    const Renderer pathRenderer(scene, shared, pathOptions);
    const int passes = centres ? 16 : 1, pathPasses = centres ? 48 : 1;
    const auto estimate = [](const Renderer& r, int count, std::uint64_t seed) {
        double mean = 0.0;
        for (int pass = 0; pass < count; ++pass) mean += imageMean(r.render(seed + pass).film, 0) / count;
        return mean;
    };
    const auto moments = [](const std::vector<double>& v, double& mean, double& variance) {
        mean = variance = 0.0;
        for (double x : v) mean += x / double(v.size());
        for (double x : v) variance += (x - mean) * (x - mean) / double(v.size() - 1);
    };
    std::vector<double> pathMeans;
    for (int r = 0; r < kAgreementRenders; ++r) pathMeans.push_back(estimate(pathRenderer, pathPasses, 1000 + 100 * r));
    double pathMean = 0.0, pathVariance = 0.0;
    moments(pathMeans, pathMean, pathVariance);
    const auto against = [&](const Scene& rendered) {
        const Renderer renderer(rendered, shared, options);
        std::vector<double> means;
        for (int r = 0; r < kAgreementRenders; ++r) means.push_back(estimate(renderer, passes, 1000 + 100 * r));
        Agreement a;
        a.pathMean = pathMean;
        double variance = 0.0;
        moments(means, a.mean, variance);
        // The difference the integrator's approximation allows is taken off before the test.
        const double allowed = agreementAllowance(integrator) * pathMean, difference = a.mean - pathMean;
        const double beyond = std::copysign(std::max(0.0, std::fabs(difference) - allowed), difference);
        a.pValue = test::welchTTest(pathMean + beyond, variance, kAgreementRenders, pathMean, pathVariance, kAgreementRenders);
        return a;
    };
    return {against(scene), against(control)};
}

CheckResult checkDegenerateScenes(const IntegratorInfo& integrator) {
    CheckResult result;
    const AovSet aovs(classesSet());
    const std::string camera = R"(
[camera]
eye = [0, 0.5, 0]
look_at = [0, 0, -1]
fov = 40
resolution = [9, 9]
)";
    RenderOptions options = checkOptions(integrator);
    if (options.samplesPerPixel > 1) options.samplesPerPixel = 16;

    const Scene empty = loadSceneFromText(camera + "[world]\nbackground = [0.25, 0.5, 1]\n", "empty.toml");
    const RenderResult sky = render(integrator, empty, aovs, options);
    checkFinite(sky, "an empty scene", result);
    for (const Rgb& v : sky.film.layer(0))
        if (v != empty.background) {
            result.fail("an empty scene: a pixel is ", v.r, " ", v.g, " ", v.b, ", not the background");
            break;
        }

    // The sphere light, on the camera's axis, fills the centre pixel (9 pixels over 40 degrees:
    // 4.4 degrees each; the sphere, 3.35 away, subtends 2 asin(0.5/3.35) = 17 degrees).
    const Scene lightOnly = loadSceneFromText(camera + R"(
[[lights]]
type = "sphere"
center = [0, -1, -3]
radius = 0.5
radiance = 2
)", "light-only.toml");
    const RenderResult lit = render(integrator, lightOnly, aovs, options);
    checkFinite(lit, "a light alone", result);
    for (const Rgb& v : lit.film.layer(0))
        if (maxComponent(v) > 2.0f * (1.0f + 1e-5f)) result.fail("a light alone: a pixel is brighter than the light: ", v.g);
    if (std::fabs(lit.film.at(0, 4, 4).g - 2.0f) > 2e-5f)
        result.fail("a light alone: the pixel on the light is ", lit.film.at(0, 4, 4).g, ", not its radiance 2");

    // Inside a sphere of albedo 0.5, radius 2, around a point light of intensity 1 (inverse square).
    const Scene inside = loadSceneFromText(camera + R"(
[materials.white]
kd = 0.5
[[spheres]]
center = [0, 0, 0]
radius = 2
material = "white"
[[lights]]
position = [0, 0, 0]
attenuation = [0, 0, 1]
)", "inside.toml");
    const RenderResult enclosed = render(integrator, inside, aovs, options);
    checkFinite(enclosed, "a camera inside a sphere", result);
    const double direct = 0.5 * 1.0 / (2.0 * 2.0);
    const auto names = enclosed.film.layerNames();
    const std::size_t raycast = static_cast<std::size_t>(std::find(names.begin(), names.end(), "raycast") - names.begin());
    const double seen = imageMean(enclosed.film, raycast) / 3.0, total = imageMean(enclosed.film, 0) / 3.0;
    if (std::fabs(seen - direct) > 0.02 * direct)
        result.fail("a camera inside a sphere: E D L is ", seen, ", not rho I / R^2 = ", direct);
    if (!(total <= direct / (1.0 - 0.5) * 1.02))
        result.fail("a camera inside a sphere: the beauty ", total, " is more than every bounce gives, ", direct / 0.5);
    return result;
}

}  // namespace lightpath::conformance
