#include "bench/error_benchmark.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <cstdio>
#include <numbers>

#include "util/timing.h"
#include "film/aov_set.h"
#include "integrators/registry.h"
#include "io/image_reader.h"
#include "io/image_writer.h"
#include "lights/point_light.h"
#include "materials/phong_material.h"
#include "render/renderer.h"
#include "scene/scene_loader.h"

namespace lightpath {
namespace {

using Reference = std::vector<Rgb>;  // per pixel, row by row

// One configuration of the comparison: a sampler, optionally with adaptive sampling.
struct Strategy {
    std::string name;
    SamplerKind sampler;
    double targetError;  // 0: fixed spp
};

const std::vector<Strategy> kStrategies = {
    {"independent", SamplerKind::Independent, 0.0},
    {"stratified", SamplerKind::Stratified, 0.0},
    {"sobol", SamplerKind::Sobol, 0.0},
    {"adaptive", SamplerKind::Sobol, 0.2},  // target relative error at 1 spp
};

// Lambert's formula: irradiance at p (normal n) from a polygon of uniform radiance le.
double polygonIrradiance(const glm::dvec3& p, const glm::dvec3& n, const std::vector<glm::dvec3>& polygon, double le) {
    double sum = 0.0;
    for (std::size_t k = 0; k < polygon.size(); ++k) {
        const glm::dvec3 a = glm::normalize(polygon[k] - p), b = glm::normalize(polygon[(k + 1) % polygon.size()] - p);
        sum += std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0)) * glm::dot(n, glm::normalize(glm::cross(a, b)));
    }
    return le / 2.0 * std::fabs(sum);
}

Scene areaLightPlane(int size, std::vector<glm::dvec3>& quad, double& radiance, double& albedo) {
    Scene scene;
    scene.camera.eye = {0.0f, 1.0f, 0.0f};
    scene.camera.lookAt = {0.0f, 0.0f, 0.0f};
    scene.camera.up = {0.0f, 0.0f, -1.0f};
    scene.camera.verticalFovDegrees = 70.0f;
    scene.camera.width = scene.camera.height = size;
    albedo = 0.6;
    radiance = 5.0;
    PhongMaterial floor, lamp;
    floor.name = "floor";
    floor.kd = Rgb{static_cast<float>(albedo)};
    lamp.name = "lamp";
    lamp.emission = Rgb{static_cast<float>(radiance)};
    scene.materials = {floor, lamp};
    scene.objects = {{"floor", 0}, {"lamp", 1}};
    scene.planes.push_back({{0, 0, 0}, {0, 1, 0}, 0});
    // A 0.8 x 0.5 quad at height 1.5 (above the camera), shining down.
    const Vec3 q0{-0.6f, 1.5f, -0.45f}, q1{0.2f, 1.5f, -0.45f}, q2{0.2f, 1.5f, 0.05f}, q3{-0.6f, 1.5f, 0.05f};
    scene.triangles.push_back({q0, q1, q2, 1});
    scene.triangles.push_back({q0, q2, q3, 1});
    quad = {glm::dvec3(q0), glm::dvec3(q1), glm::dvec3(q2), glm::dvec3(q3)};
    return scene;
}

// The exact pixel values of the area-light plane: rho/pi E averaged over each pixel's footprint
// (an 8 x 8 grid of points per pixel, by the pinhole model written out here).
Reference areaLightPlaneReference(const Scene& scene, const std::vector<glm::dvec3>& quad, double radiance, double albedo) {
    const CameraDescription& c = scene.camera;
    const double halfHeight = std::tan(glm::radians(double(c.verticalFovDegrees)) / 2.0);
    Reference reference;
    constexpr int kSub = 8;
    for (int j = 0; j < c.height; ++j) {
        for (int i = 0; i < c.width; ++i) {
            double sum = 0.0;
            for (int a = 0; a < kSub; ++a) {
                for (int b = 0; b < kSub; ++b) {
                    // Looking straight down with up = -z: film x -> world x, film y -> world z.
                    const double u = (2.0 * (i + (a + 0.5) / kSub) / c.width - 1.0) * halfHeight;
                    const double v = (1.0 - 2.0 * (j + (b + 0.5) / kSub) / c.height) * halfHeight;
                    const glm::dvec3 p{u * c.eye.y, 0.0, -v * c.eye.y};
                    sum += albedo / std::numbers::pi * polygonIrradiance(p, {0, 1, 0}, quad, radiance);
                }
            }
            reference.push_back(Rgb{static_cast<float>(sum / (kSub * kSub))});
        }
    }
    return reference;
}

Scene furnaceScene(int size, double rho, double le) {
    Scene scene;
    scene.camera.eye = Vec3{0.0f};
    scene.camera.lookAt = {0.0f, 0.0f, -1.0f};
    scene.camera.verticalFovDegrees = 90.0f;
    scene.camera.width = scene.camera.height = size;
    PhongMaterial wall;
    wall.name = "wall";
    wall.kd = Rgb{static_cast<float>(rho)};
    wall.emission = Rgb{static_cast<float>(le)};
    scene.materials = {wall};
    scene.objects = {{"furnace", 0}};
    scene.spheres.push_back({Vec3{0.0f}, 1.0f, 0});
    return scene;
}

// A diffuse floor beside a mirror wall x = 1 under a point light, seen from above: the light the
// mirror throws on the floor (E D S L, a caustic) is the light's mirror image at (2 - x, y, z),
// kr times as bright (inverse-square law), averaged over each pixel's footprint.
Scene mirrorCausticScene(int size, Reference& caustic) {
    Scene scene;
    scene.camera.eye = {0.2f, 1.0f, 0.1f};
    scene.camera.lookAt = {0.2f, 0.0f, 0.1f};
    scene.camera.up = {0.0f, 0.0f, -1.0f};
    scene.camera.verticalFovDegrees = 50.0f;
    scene.camera.width = scene.camera.height = size;
    const double albedo = 0.6, kr = 0.8, intensity = 3.0;
    const glm::dvec3 light{0.3, 1.2, 0.1}, image{2.0 - light.x, light.y, light.z};
    PhongMaterial floor, mirror;
    floor.name = "floor";
    floor.kd = Rgb{static_cast<float>(albedo)};
    mirror.name = "mirror";
    mirror.kr = Rgb{static_cast<float>(kr)};
    scene.materials = {floor, mirror};
    scene.objects = {{"floor", 0}, {"mirror", 1}};
    scene.planes.push_back({{0, 0, 0}, {0, 1, 0}, 0});
    scene.planes.push_back({{1, 0, 0}, {-1, 0, 0}, 1});
    scene.lights.push_back(PointLight{"key", Vec3(light), Rgb{static_cast<float>(intensity)}, {0, 0, 1}});
    const Camera camera(scene.camera);
    constexpr int kSub = 8;
    for (int j = 0; j < size; ++j) {
        for (int i = 0; i < size; ++i) {
            double sum = 0.0;
            for (int b = 0; b < kSub; ++b) {
                for (int a = 0; a < kSub; ++a) {
                    const Ray ray = camera.generateRay(i + (a + 0.5f) / kSub, j + (b + 0.5f) / kSub);
                    const glm::dvec3 o(ray.origin), d(ray.direction);
                    const glm::dvec3 p = o + (-o.y / d.y) * d, toImage = image - p;
                    const double distance = glm::length(toImage);
                    sum += kr * albedo * intensity * (toImage.y / distance) / (distance * distance);
                }
            }
            caustic.push_back(Rgb{static_cast<float>(sum / (kSub * kSub))});
        }
    }
    return scene;
}

// A glass ball (ior 1.5, Fresnel) held above a diffuse floor, a small square lamp above and to the
// side, seen obliquely: the ball focuses the lamp into a bright spot on the floor beside its shadow
// (E D T T L, and E D R L off its surface). The path tracer reaches the caustic only when a diffuse
// bounce off the floor happens to pass through the ball onto the lamp, so it finds it slowly.
Scene glassCausticScene(int size) {
    Scene scene;
    scene.camera.eye = {0.0f, 2.2f, 3.0f};
    scene.camera.lookAt = {0.35f, 0.2f, 0.0f};
    scene.camera.up = {0.0f, 1.0f, 0.0f};
    scene.camera.verticalFovDegrees = 40.0f;
    scene.camera.width = scene.camera.height = size;
    PhongMaterial floor, glass, lamp;
    floor.name = "floor";
    floor.kd = Rgb{0.6f};
    glass.name = "glass";
    glass.kt = Rgb{1.0f};
    glass.ior = 1.5f;
    glass.fresnel = true;
    lamp.name = "lamp";
    lamp.emission = Rgb{40.0f};
    scene.materials = {floor, glass, lamp};
    scene.objects = {{"floor", 0}, {"ball", 1}, {"lamp", 2}};
    scene.planes.push_back({{0, 0, 0}, {0, 1, 0}, 0});
    scene.spheres.push_back({{0.0f, 0.9f, 0.0f}, 0.5f, 1});
    // A 0.3 x 0.3 quad at height 3, facing down, up and to the left of the ball.
    const Vec3 q0{-0.95f, 3.0f, -0.15f}, q1{-0.65f, 3.0f, -0.15f}, q2{-0.65f, 3.0f, 0.15f}, q3{-0.95f, 3.0f, 0.15f};
    scene.triangles.push_back({q0, q1, q2, 2});
    scene.triangles.push_back({q0, q3, q2, 2});
    return scene;
}

struct Measurement {
    double seconds, rmse, relmse;
    std::size_t patches = 0;
    double raysPerSample = 0.0;
};

// The error of the beauty, or of the one AOV `expression` when it is given. CPU seconds include
// the Renderer's construction, where radiosity meshes and solves.
Measurement measure(const Scene& scene, const Reference& reference, const RenderOptions& options,
                    const std::string& expression = "") {
    std::vector<lpe::NamedExpression> set;
    if (!expression.empty()) set.push_back({"measured", expression});
    const AovSet aovs(set);
    const std::size_t layer = expression.empty() ? 0 : 1;
    Film film(1, 1, {});
    const double start = processCpuSeconds();
    const RenderResult result = Renderer(scene, aovs, options).render();
    const double seconds = processCpuSeconds() - start;
    film = result.film;
    double squared = 0.0, relative = 0.0;
    std::size_t n = 0;
    for (int y = 0; y < film.height(); ++y) {
        for (int x = 0; x < film.width(); ++x) {
            const Rgb& value = film.at(layer, x, y);
            const Rgb& truth = reference[static_cast<std::size_t>(y * film.width() + x)];
            for (int c = 0; c < 3; ++c) {
                const double e = double(value[c]) - double(truth[c]);
                squared += e * e;
                relative += e * e / (double(truth[c]) * truth[c] + 1e-2);
                ++n;
            }
        }
    }
    return {seconds, std::sqrt(squared / n), relative / n, result.stats.radiosity ? result.stats.radiosity->patches : 0,
            static_cast<double>(result.stats.rays.total()) / static_cast<double>(std::max<std::uint64_t>(1, result.stats.samples))};
}

// Least-squares slope of log(rmse) against log(seconds).
double fitSlope(const std::vector<ErrorBenchmarkRow>& rows) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (const auto& r : rows) {
        const double x = std::log(r.seconds), y = std::log(r.rmse);
        sx += x, sy += y, sxx += x * x, sxy += x * y;
    }
    const double n = static_cast<double>(rows.size());
    return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

// Seconds at which a strategy's error curve reaches `error`, interpolated in log-log between the
// two budgets around it (extrapolated along the fitted slope outside them).
double secondsToReach(const std::vector<ErrorBenchmarkRow>& rows, double error) {
    for (std::size_t i = 1; i < rows.size(); ++i) {
        const auto& a = rows[i - 1];
        const auto& b = rows[i];
        if ((a.rmse - error) * (b.rmse - error) <= 0.0 && a.rmse != b.rmse) {
            const double t = (std::log(error) - std::log(a.rmse)) / (std::log(b.rmse) - std::log(a.rmse));
            return std::exp(std::log(a.seconds) + t * (std::log(b.seconds) - std::log(a.seconds)));
        }
    }
    // Outside: from the nearer end (an error above the smallest budget's, as bdpt's on the glass
    // caustic against path's, from the smallest).
    const auto& last = error > rows.front().rmse ? rows.front() : rows.back();
    return std::exp(std::log(last.seconds) + (std::log(error) - std::log(last.rmse)) / fitSlope(rows));
}

// A strategy's error at `seconds`, interpolated in log-log between the two budgets around it
// (extrapolated along the fitted slope outside them): secondsToReach's inverse.
double errorAt(const std::vector<ErrorBenchmarkRow>& rows, double seconds) {
    for (std::size_t i = 1; i < rows.size(); ++i) {
        const auto& a = rows[i - 1];
        const auto& b = rows[i];
        if ((a.seconds - seconds) * (b.seconds - seconds) <= 0.0 && a.seconds != b.seconds) {
            const double t = (std::log(seconds) - std::log(a.seconds)) / (std::log(b.seconds) - std::log(a.seconds));
            return std::exp(std::log(a.rmse) + t * (std::log(b.rmse) - std::log(a.rmse)));
        }
    }
    const auto& last = seconds < rows.front().seconds ? rows.front() : rows.back();
    return std::exp(std::log(last.rmse) + (std::log(seconds) - std::log(last.seconds)) * fitSlope(rows));
}

// The path tracer's render at `spp`, read from `cacheFile` or rendered and written there: the
// beauty, or the AOV `expression` when it is given.
Reference cachedReference(const Scene& scene, const std::filesystem::path& cacheFile, int spp,
                          const std::string& expression = "") {
    const std::size_t layer = expression.empty() ? 0 : 1;
    if (std::filesystem::exists(cacheFile)) {
        const Film cached = readFilm(cacheFile);
        if (cached.width() == scene.camera.width && cached.height() == scene.camera.height && cached.layerCount() > layer)
            return cached.layer(layer);
    }
    std::vector<lpe::NamedExpression> set;
    if (!expression.empty()) set.push_back({"reference", expression});
    const AovSet aovs(set);
    RenderOptions options;
    options.integrator = "path";
    options.samplesPerPixel = spp;
    options.sampler = SamplerKind::Sobol;
    options.seed = 0x5eed;
    const Film film = Renderer(scene, aovs, options).render().film;
    writeFilm(film, cacheFile, {{"lightpath:reference_spp", std::to_string(spp)}});
    return film.layer(layer);
}

// Path tracing against bidirectional path tracing (the default sampler, 1 thread): error against
// time on a caustic only light tracing finds, and on the Cornell box with its area light, where
// both converge; bdpt's time to reach the path tracer's error at its largest budget, over path's.
void compareIntegrators(bool quick, const std::filesystem::path& scenesDirectory,
                        const std::filesystem::path& cacheDirectory, ErrorBenchmarkResult& result) {
    struct Comparison {
        std::string name;
        Scene scene;
        Reference reference;
        std::string expression;  // the AOV measured; empty: the beauty
    };
    std::vector<Comparison> comparisons;
    {
        Reference caustic;
        Scene scene = mirrorCausticScene(quick ? 32 : 64, caustic);
        comparisons.push_back({"mirror-caustic", std::move(scene), std::move(caustic), "E(D|G)S+L"});
    }
    {
        // The glass ball's caustic AOV against the path tracer's, converged (it does find it): at
        // 131,072 spp its RMSE is about 0.0014 (path's 0.088 at 32 spp over 64), half bdpt's at 32
        // spp, which it raises by about 10%; 140 CPU seconds, once. --quick (and CI's end-to-end
        // run) takes 16,384 spp, 17 s: RMSE 0.004, which raises bdpt's error, not path's, so it
        // understates bdpt's lead.
        Scene scene = glassCausticScene(32);
        const int spp = quick ? 16384 : 131072;
        Reference reference = cachedReference(
            scene, cacheDirectory / ("glass-caustic-32-" + std::to_string(spp) + "-reference.exr"), spp, "E(D|G)S+L");
        comparisons.push_back({"glass-caustic", std::move(scene), std::move(reference), "E(D|G)S+L"});
    }
    {
        // The Cornell box lit by its ceiling lamp alone (the MTL's Ke), against a cached path
        // tracer reference: both integrators converge to it.
        Scene cornell = loadScene(scenesDirectory / "cornell-original.toml");
        cornell.lights.clear();
        cornell.camera.width = cornell.camera.height = 32;
        Reference reference = cachedReference(cornell, cacheDirectory / "cornell-lamp-32-reference.exr", 4096);
        comparisons.push_back({"cornell-lamp", std::move(cornell), std::move(reference), ""});
    }
    const int maxLog2 = quick ? 5 : 8;
    // Each render is repeated, interleaved (path, bdpt, path, ...), and its median CPU time kept:
    // one run of a small render is at the mercy of the other processes on a shared machine. The
    // images of the repeats are identical (same seed), so the error is the first's.
    constexpr int kRepetitions = 3;
    const char* const integrators[] = {"path", "bdpt"};
    for (const Comparison& c : comparisons) {
        std::vector<std::vector<ErrorBenchmarkRow>> curves(2);
        std::vector<std::vector<std::vector<double>>> seconds(2, std::vector<std::vector<double>>(maxLog2 + 1));
        std::vector<double> raysPerSample(2, 0.0);
        for (int rep = 0; rep < kRepetitions; ++rep) {
            for (int k = 0; k <= maxLog2; ++k) {
                for (std::size_t i = 0; i < 2; ++i) {
                    RenderOptions options;
                    options.integrator = integrators[i];
                    options.threads = 1;
                    options.samplesPerPixel = 1 << k;
                    options.seed = 1;
                    const Measurement m = measure(c.scene, c.reference, options, c.expression);
                    seconds[i][static_cast<std::size_t>(k)].push_back(m.seconds);
                    if (rep > 0) continue;
                    curves[i].push_back({c.name, integrators[i], samplerName(options.sampler), options.samplesPerPixel, 0,
                                         0.0, m.rmse, m.relmse});
                    raysPerSample[i] = m.raysPerSample;
                }
            }
        }
        for (std::size_t i = 0; i < 2; ++i) {
            for (std::size_t k = 0; k < curves[i].size(); ++k) curves[i][k].seconds = median(seconds[i][k]);
            result.rows.insert(result.rows.end(), curves[i].begin(), curves[i].end());
        }
        // The path tracer's error at its largest budget; on the mirror caustic it never falls (it
        // finds none of the light), so bdpt's time to reach it extrapolates nothing of path's, and
        // the error ratio at path's largest time says more.
        // Path reaches its own error at its largest budget's time (its curve may be flat there).
        const double error = curves[0].back().rmse;
        const double pathSeconds = curves[0].back().seconds;
        result.summaries.push_back({c.name, "path", fitSlope(curves[0]), 1.0, raysPerSample[0], 1.0});
        result.summaries.push_back({c.name, "bdpt", fitSlope(curves[1]), secondsToReach(curves[1], error) / pathSeconds,
                                    raysPerSample[1], errorAt(curves[1], curves[0].back().seconds) / error});
    }
}

// Photon mapping on the mirror caustic, against its closed form: sppm's error as passes double
// (one pass per pixel sample, photons per pass fixed; its slope says how fast bias and noise fall
// together), and fixed-radius photon mapping's error against its radius at many photons, where
// error is the blur (bias) at large radii and noise at small ones: a minimum between.
void photonMappingRows(bool quick, ErrorBenchmarkResult& result) {
    Reference caustic;
    const Scene scene = mirrorCausticScene(quick ? 32 : 64, caustic);
    const std::string expression = "E(D|G)S+L";
    std::vector<ErrorBenchmarkRow> curve;
    for (int k = 0; k <= (quick ? 5 : 7); ++k) {
        RenderOptions options;
        options.integrator = "sppm";
        options.threads = 1;
        options.samplesPerPixel = 1 << k;
        options.seed = 1;
        ParameterValues values(findIntegrator("sppm")->schema);
        values.set("photons", 10000);
        options.integratorParameters = values;
        const Measurement m = measure(scene, caustic, options, expression);
        curve.push_back({"mirror-caustic", "sppm", "passes", options.samplesPerPixel, 0, m.seconds, m.rmse, m.relmse});
    }
    result.rows.insert(result.rows.end(), curve.begin(), curve.end());
    result.summaries.push_back({"mirror-caustic", "sppm", fitSlope(curve), 0.0});
    for (const double radius : {0.64, 0.32, 0.16, 0.08, 0.04, 0.02}) {
        RenderOptions options;
        options.integrator = "photon";
        options.threads = 1;
        options.samplesPerPixel = 4;
        options.seed = 1;
        ParameterValues values(findIntegrator("photon")->schema);
        values.set("photons", quick ? 200000 : 1000000);
        values.set("photon-radius", radius);
        options.integratorParameters = values;
        const Measurement m = measure(scene, caustic, options, expression);
        char name[32];
        std::snprintf(name, sizeof name, "radius %.2f", radius);
        result.rows.push_back({"mirror-caustic", "photon", name, options.samplesPerPixel, 0, m.seconds, m.rmse, m.relmse});
    }
}

}  // namespace

ErrorBenchmarkResult runErrorBenchmark(bool quick, bool integratorsOnly, const std::filesystem::path& scenesDirectory,
                                        const std::filesystem::path& cacheDirectory) {
    ErrorBenchmarkResult result;
    if (integratorsOnly) {
        compareIntegrators(quick, scenesDirectory, cacheDirectory, result);
        photonMappingRows(quick, result);
        return result;
    }
    struct BenchScene {
        std::string name;
        Scene scene;
        Reference reference;
    };
    std::vector<BenchScene> scenes;
    const int size = quick ? 32 : 64;
    {
        std::vector<glm::dvec3> quad;
        double radiance = 0, albedo = 0;
        Scene scene = areaLightPlane(size, quad, radiance, albedo);
        Reference reference = areaLightPlaneReference(scene, quad, radiance, albedo);
        scenes.push_back({"area-light-plane", std::move(scene), std::move(reference)});
    }
    scenes.push_back({"furnace", furnaceScene(size, 0.5, 1.0), Reference(std::size_t(size) * size, Rgb{2.0f})});
    if (!quick) {
        Scene taxonomy = loadScene(scenesDirectory / "taxonomy.toml");
        taxonomy.camera.width = 96;
        taxonomy.camera.height = 54;
        Reference reference = cachedReference(taxonomy, cacheDirectory / "taxonomy-96x54-reference.exr", 4096);
        scenes.push_back({"taxonomy", std::move(taxonomy), std::move(reference)});
        Scene cornell = loadScene(scenesDirectory / "cornell-original.toml");
        cornell.camera.width = cornell.camera.height = size;
        reference = cachedReference(cornell, cacheDirectory / "cornell-original-64x64-reference.exr", 4096);
        scenes.push_back({"cornell", std::move(cornell), std::move(reference)});
    }

    const int maxLog2 = quick ? 5 : 8;
    for (const BenchScene& bench : scenes) {
        std::vector<std::vector<ErrorBenchmarkRow>> curves;
        for (const Strategy& strategy : kStrategies) {
            std::vector<ErrorBenchmarkRow> curve;
            for (int k = 0; k <= maxLog2; ++k) {
                RenderOptions options;
                options.integrator = "path";
                options.threads = 1;
                options.samplesPerPixel = 1 << k;
                options.sampler = strategy.sampler;
                options.targetError = strategy.targetError;
                options.seed = 1;
                // Adaptive sampling: a pixel may take up to 8x the budget, and the error it stops
                // at shrinks as 1/sqrt(budget), so the curve keeps descending like the others.
                if (strategy.targetError > 0.0) {
                    options.samplesPerPixel = 8 << k;
                    options.targetError = strategy.targetError / std::sqrt(double(1 << k));
                }
                const Measurement m = measure(bench.scene, bench.reference, options);
                curve.push_back({bench.name, "path", strategy.name, options.samplesPerPixel, 0, m.seconds, m.rmse, m.relmse});
            }
            result.rows.insert(result.rows.end(), curve.begin(), curve.end());
            curves.push_back(std::move(curve));
        }
        // The common error: what independent sampling reaches with its largest budget.
        const double error = curves[0].back().rmse;
        const double independentSeconds = secondsToReach(curves[0], error);
        for (std::size_t s = 0; s < kStrategies.size(); ++s)
            result.summaries.push_back({bench.name, kStrategies[s].name, fitSlope(curves[s]),
                                        secondsToReach(curves[s], error) / independentSeconds});

        // Radiosity where all light is diffuse (the area-light plane has an infinite floor, which
        // radiosity clips): patch budgets 4x apart, the solve's time included.
        if (bench.name != "furnace" && bench.name != "cornell") continue;
        std::vector<ErrorBenchmarkRow> curve;
        for (std::size_t budget = 64; budget <= (quick ? std::size_t{1024} : std::size_t{16384}); budget *= 4) {
            RenderOptions options;
            options.integrator = "radiosity";
            options.threads = 1;
            options.radiosity.patchBudget = budget;
            // Camera rays only: pixels average their footprint, like the reference's.
            options.samplesPerPixel = 16;
            options.sampler = SamplerKind::Sobol;
            const Measurement m = measure(bench.scene, bench.reference, options);
            curve.push_back({bench.name, "radiosity", "radiosity", options.samplesPerPixel, m.patches, m.seconds, m.rmse,
                             m.relmse});
        }
        result.rows.insert(result.rows.end(), curve.begin(), curve.end());
        // Radiosity's error is the mesh's, not noise: when its coarsest mesh is already below the
        // common error, that mesh's time is the time to reach it.
        const double seconds = curve.front().rmse <= error ? curve.front().seconds : secondsToReach(curve, error);
        result.summaries.push_back({bench.name, "radiosity", fitSlope(curve), seconds / independentSeconds});
    }
    compareIntegrators(quick, scenesDirectory, cacheDirectory, result);
    photonMappingRows(quick, result);
    return result;
}

}  // namespace lightpath
