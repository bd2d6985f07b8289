#pragma once
// `lightpath bench error`: run time against error. Renders reference scenes at increasing sample
// budgets for each sampler (and adaptive sampling), measures CPU seconds and the error against a
// reference that does not come from the renderer under test where one exists:
//   area-light plane  a Lambertian floor under a quad light, seen from straight above: per pixel,
//                     Lambert's closed-form polygon irradiance averaged over the pixel footprint
//   furnace           a closed emissive diffuse sphere seen from inside: Le / (1 - rho) everywhere
//   taxonomy          the lecture scene, against a high-sample render computed once and cached
// then path tracing against bidirectional path tracing:
//   mirror-caustic    the light a mirror throws on a floor (E(D|G)S+L) under a point light: the
//                     light's mirror image in closed form; only bdpt's light tracing finds it
//   glass-caustic     a glass ball's caustic on a floor under a small area light (E(D|G)S+L), which
//                     the path tracer finds only by hitting the light through the ball: against a
//                     cached high-sample path-traced render of that AOV
//   cornell-lamp      the Cornell box under its area light, against a cached high-sample render
//   cornell           the diffuse Cornell box, against the path tracer's cached high-sample render
// Radiosity gets its own rows on the furnace and the Cornell box, one per patch budget; photon
// mapping its own on mirror-caustic: sppm as passes double (with its slope), fixed-radius photon
// mapping against its radius (the bias of the blur).
#include <filesystem>
#include <string>
#include <vector>

namespace lightpath {

struct ErrorBenchmarkRow {
    std::string scene, integrator, sampler;
    int spp = 0;              // samples per pixel (the most a pixel may take, for adaptive)
    std::size_t patches = 0;  // radiosity's patch count (0 for the path tracer)
    double seconds = 0.0;     // CPU seconds of the render, one thread
    double rmse = 0.0;        // root mean squared error over pixels and channels
    double relmse = 0.0;      // mean of squared error / (reference^2 + 1e-2)
};

struct ErrorBenchmarkSummary {
    std::string scene, sampler;  // for the integrator comparison: the integrator
    double slope = 0.0;       // fitted d log(rmse) / d log(seconds)
    // Seconds to reach the common error, over independent sampling's (samplers) or over the path
    // tracer's at its largest budget (integrators).
    double timeRatio = 0.0;  // 0: not compared (sppm)
    // Integrators: rays cast per pixel sample (camera, shadow and connection rays, walks' bounces)
    // at the largest budget; their ratio to the path tracer's is the cost of the extra strategies.
    double raysPerSample = 0.0;
    // Integrators: the error at the path tracer's time at its largest budget, over the path
    // tracer's (0: not compared). Where path's error is bias that never falls (mirror-caustic), the
    // time ratio extrapolates and this says more.
    double equalTimeErrorRatio = 0.0;
};

struct ErrorBenchmarkResult {
    std::vector<ErrorBenchmarkRow> rows;
    std::vector<ErrorBenchmarkSummary> summaries;
};

// `scenes`: the folder of shipped scenes; `cache`: where the lecture scene's reference is kept.
// `integratorsOnly`: only path against bdpt.
ErrorBenchmarkResult runErrorBenchmark(bool quick, bool integratorsOnly, const std::filesystem::path& scenes,
                                       const std::filesystem::path& cache);

}  // namespace lightpath
