#pragma once
// Turns a scene and a set of outputs into a film: camera rays per pixel, tiles handed out to
// worker threads, every pixel's samples drawn from its own deterministic sequence so the image is
// bit-identical for any number of threads.
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "film/aov_set.h"
#include "film/film.h"
#include "film/splat_film.h"
#include "geometry/numerics.h"
#include "accel/scene_geometry.h"
#include "integrators/bdpt.h"
#include "integrators/contribution_sink.h"
#include "integrators/event_symbols.h"
#include "integrators/integrator.h"
#include "integrators/photon.h"
#include "integrators/sppm.h"
#include "integrators/radiosity.h"
#include "integrators/ray_counters.h"
#include "lights/light_set.h"
#include "scene/camera.h"
#include "sampling/pixel_filter.h"
#include "sampling/sampler.h"
#include "scene/scene_analysis.h"
#include "scene/scene.h"

namespace lightpath {

struct StepCounter;  // util/progress.h

struct RenderOptions {
    std::string integrator = "whitted";
    int maxDepth = 5;
    int samplesPerPixel = 1;
    int threads = 0;  // 0: all hardware threads
    std::uint64_t seed = 0;
    // Without the beauty (and so without `rest`, its complement) only the requested AOVs are
    // computed, and every path none of them can accept is skipped.
    bool writeBeauty = true;
    bool skip = true;  // false: `--no-skip`, trace and evaluate everything
    // `--shadows on|off`; unset: the integrator's own (on; the rasteriser has none). Off is refused
    // for integrators whose scattered rays meet light (registry.h, ShadowRays).
    std::optional<bool> shadows;
    NumericsOptions numerics;
    // Owen-scrambled Sobol by default: on the Cornell box it reaches independent sampling's error
    // in about a third of the time (README, Performance).
    SamplerKind sampler = SamplerKind::Sobol;
    // Where a pixel's camera rays go around its centre (filter importance sampling); one sample
    // per pixel always goes through the centre.
    PixelFilterKind filter = PixelFilterKind::Box;
    // Adaptive sampling when > 0: a pixel stops once the standard error of its mean luminance is
    // below this fraction of the mean; samplesPerPixel is then the most it may take.
    double targetError = 0.0;
    // Set (e.g. by a Ctrl-C handler) to stop the workers after their current tile.
    const std::atomic<bool>* cancel = nullptr;
    Accelerator accelerator = Accelerator::Bvh;
    bool progress = false;  // a progress bar on stderr (only if it is a terminal; util/progress.h)
    // If set, the integrator's preprocess (radiosity's solve) counts its steps there as it runs.
    StepCounter* preprocessSteps = nullptr;
    RadiosityOptions radiosity;  // meshing and solve of --integrator radiosity, when set directly
    // The integrator's own parameters (its schema's; config/render_config.h fills them): when
    // set, they replace the integrator's defaults and `radiosity` above.
    std::optional<ParameterValues> integratorParameters;
};

struct RenderStats {
    RayCounters rays;
    double seconds = 0.0;
    // CPU seconds of the workers alone (no image module loading beside them): what benchmarks
    // against other renderers compare on a machine other processes load.
    double cpuSeconds = 0.0;
    std::uint64_t samples = 0;
    int threads = 1;
    AcceleratorStats accelerator;  // what building the BVH (or Embree's) cost, before the render
    std::optional<RadiosityStats> radiosity;  // its mesh and solve, before the render
    std::optional<PhotonStats> photon;        // the photons shot and kept, before the render
    std::optional<BdptStats> bdpt;            // the fraction of samples that walked from a light
    // Wall seconds of the integrator's preprocess (radiosity's solve, the photons, bdpt's pilot),
    // run once when the Renderer is built: not in `seconds`, which is the render alone.
    double preprocessSeconds = 0.0;
    // CPU seconds of each worker in the render loop, and of the render's serial parts on the
    // calling thread (the film, the splats): load on the machine stretches wall time but not
    // these, so serial + the busiest worker is what the render would take on an idle machine, and
    // a worker's time growing with the thread count shows cache lines passed between cores.
    std::vector<double> workerCpuSeconds;
    double serialCpuSeconds = 0.0;
};

// What a render holds in proportion to its pixels, known before any of it is allocated (issue
// #28): a render that cannot get it is refused with the amount, not ended by std::bad_alloc.
struct PixelMemory {
    int width = 0, height = 0;
    std::vector<std::string> layers;  // the film's layers (Renderer::layerNames)
    std::uint64_t film = 0;           // the film: Film::bytes
    std::uint64_t splats = 0;         // light tracing's splat film, for an integrator that splats
    std::uint64_t preprocess = 0;     // what the integrator's preprocess keeps (the rasteriser's z-buffer)
    std::uint64_t total() const { return film + splats + preprocess; }
    // "a 640x480 image of 7 layers (beauty, raycast, ..., rest)", for messages.
    std::string describe() const;
};

// What Renderer::explainPixel may be asked beyond the pixel.
struct ExplainOptions {
    int samplesPerPixel = 0;  // 0: RenderOptions::samplesPerPixel
    // Set to abandon the explanation: checked before each other pixel light tracing traces (one
    // pixel's own samples are bounded work, and always answered).
    const std::atomic<bool>* cancel = nullptr;
};

// Thrown by Renderer::explainPixel when ExplainOptions::cancel was set before it finished.
class ExplainCancelled : public std::runtime_error {
public:
    ExplainCancelled() : std::runtime_error("the explanation was cancelled") {}
};

struct RenderResult {
    Film film;
    RenderStats stats;
    bool cancelled = false;  // stopped through RenderOptions::cancel: the film is incomplete
};

class Renderer {
public:
    // Throws std::invalid_argument for an unknown integrator or an option out of range.
    Renderer(const Scene& scene, const AovSet& aovs, const RenderOptions& options);
    // The same over geometry already built from `scene`'s shapes with options.numerics and
    // options.accelerator (see buildGeometry): renderers of one scene share its BVH.
    Renderer(const Scene& scene, const AovSet& aovs, const RenderOptions& options,
             std::shared_ptr<const SceneGeometry> geometry);
    static std::shared_ptr<const SceneGeometry> buildGeometry(const Scene& scene, const RenderOptions& options);
    // The bytes a renderer of these arguments allocates in proportion to the image, without
    // building it: the one computation of them. Throws std::invalid_argument for an unknown integrator.
    static PixelMemory pixelMemory(const Scene& scene, const AovSet& aovs, const RenderOptions& options);

    // Throws MemoryLimitError (render/memory_limit.h) when the film would not fit in memory; callers
    // that can say what to change check Renderer::pixelMemory before building the renderer.
    RenderResult render() const;
    // The same render with the per-pixel sample sequences seeded by `seed` instead of
    // RenderOptions::seed: renders with different seeds are independent estimates, so a caller
    // can refine an image pass by pass, averaging them, without rebuilding the acceleration
    // structure (`lightpath serve`).
    RenderResult render(std::uint64_t seed) const;
    // The same with `samplesPerPixel` instead of RenderOptions::samplesPerPixel: one renderer (one
    // preprocess, e.g. one radiosity solve) serves a pass at the pixel centres and jittered passes.
    // Throws std::invalid_argument for a count the integrator cannot take.
    RenderResult render(std::uint64_t seed, int samplesPerPixel) const;
    // Whether the integrator renders pass by pass (sppm): its passes refine one state (each
    // pixel's shrinking radius), so a caller that refines an image continues one render rather
    // than averaging independent ones.
    bool progressive() const;
    // Shown the film between the passes of a progressive render: the sum of the passes so far
    // and the samples a pixel it holds (their mean is sum / samples). Not called after the last.
    using PassObserver = std::function<void(const Film& sum, int samples)>;
    // render(seed, samplesPerPixel) calling `observer` between passes (serve's refining image).
    RenderResult render(std::uint64_t seed, int samplesPerPixel, const PassObserver& observer) const;
    // How many renderers have run their integrator's preprocess in this process: what a caller
    // that must build one renderer, not two, is checked by.
    static std::uint64_t preprocessesRun();
    // The layers render() produces, in order.
    std::vector<std::string> layerNames() const;
    // Every contribution to pixel (x, y), in the order the integrator produced them.
    // With `rejections`, also the terms that added nothing there, and why. Under light tracing this
    // traces every pixel's paths on the calling thread; `options.cancel` stops it (ExplainCancelled).
    std::vector<LoggedContribution> explainPixel(int x, int y, std::vector<Rejection>* rejections = nullptr,
                                                 const ExplainOptions& options = {}) const;

private:
    // Samples one pixel into `layers` (their mean); returns the number of samples taken.
    int renderPixel(int x, int y, std::uint64_t seed, int samplesPerPixel, std::span<Rgb> layers, PathState& path) const;
    // Traces sample `sample` of `samplesPerPixel` of pixel (x, y), adding to the path's sink; through
    // `progressive` when the render goes pass by pass.
    void traceSample(int x, int y, std::uint64_t seed, int sample, int samplesPerPixel, PathState& path,
                     ProgressiveRender* progressive = nullptr) const;
    void checkSamplesPerPixel(int samplesPerPixel) const;
    bool cancelled() const;  // RenderOptions::cancel is set
    // Light tracing's contributions, added to the film once every tile is done.
    void addSplats(const SplatFilm& splats, int samplesPerPixel, Film& film) const;

    const Scene& scene_;
    const AovSet& aovs_;
    RenderOptions options_;
    std::shared_ptr<const SceneGeometry> geometry_;
    EventSymbols symbols_;
    SceneAnalysis analysis_;
    LightSet lights_;
    LobeStepTable lobeSteps_;
    Camera camera_;
    PixelFilter filter_;
    // Indices into AovSet::layerNames(): every layer, or all but beauty and rest.
    static std::vector<std::size_t> writtenLayers(const AovSet& aovs, bool writeBeauty);
    std::vector<std::size_t> writtenLayers_;
    std::unique_ptr<Integrator> integrator_;
    RenderContext context_;
    double preprocessSeconds_ = 0.0;  // RenderStats::preprocessSeconds
};

}  // namespace lightpath
