#pragma once
// The integrator contract (docs/design.md). Every method reads the same light transport: the
// scene's materials through Bsdf (materials/bsdf.h), its lights through Light (lights/light.h),
// and meets the LPE automaton only through PathState. A new integrator is one file implementing
// this, plus its row in the registry.
#include <atomic>
#include <cstddef>
#include <memory>
#include <string_view>

#include "accel/scene_geometry.h"
#include "integrators/event_symbols.h"
#include "integrators/path_state.h"
#include "integrators/radiosity_options.h"
#include "lights/light_set.h"
#include "lpe/automaton.h"
#include "math/ray.h"
#include "sampling/pixel_filter.h"
#include "scene/camera.h"
#include "scene/scene.h"
#include "scene/scene_analysis.h"
#include "schema/parameter_values.h"

namespace lightpath {

struct StepCounter;  // util/progress.h
class ProgressiveRender;

struct RenderContext {
    const Scene& scene;
    const SceneGeometry& geometry;
    const lpe::Automaton& automaton;
    const EventSymbols& symbols;
    const SceneAnalysis& analysis;
    const LightSet& lights;
    const LobeStepTable& lobeSteps;  // the automaton's answers for direct light (path_state.h)
    const Camera& camera;
    // The most scattering events (R or T) a path may have before its light: 1 is ray casting's
    // E(D|G)L, and every integrator cuts its paths at the same length.
    int maxDepth = 5;
    // The outputs the user asked for. When every contribution is wanted (the beauty or `rest` is
    // written, or skipping is off) nothing may be skipped on their account.
    lpe::OutputMask requested = 0;
    bool keepAllPaths = true;
    // Off (`--no-skip`): evaluate every term and trace every ray, even those that cannot add
    // anything, so tests and lectures can compare against the work skipping saves.
    bool skipEnabled = true;
    // For preprocess(): radiosity's meshing and solve, the worker threads it may use (0: all
    // cores), a progress bar on stderr, and a flag that asks it to stop early (Ctrl-C).
    RadiosityOptions radiosity{};
    int threads = 0;
    bool progress = false;
    const std::atomic<bool>* cancel = nullptr;
    // If set, preprocess counts its steps there too, for a caller that shows them (serve's page).
    StepCounter* preprocessSteps = nullptr;
    // Off (`--shadows off`): direct light counts every light as visible and casts no shadow ray,
    // Szymczak's formula with its shadow term S_i = 1 (raycast and whitted; the rasteriser has no
    // rays, so it is always off there).
    bool shadows = true;
    // The pixel filter the renderer spreads each pixel's samples with; light tracing weighs its
    // splats by it. Null: the box.
    const PixelFilter* filter = nullptr;
    // The integrator's own parameters (its registry row's schema) as the user gave them; null when
    // the caller set `radiosity` above directly (tests), which then stand.
    const ParameterValues* parameters = nullptr;
    // The render's seed (--seed), for work a preprocess draws at random (photon mapping's photons).
    std::uint64_t seed = 0;
    // The samples each pixel takes (--spp): progressive photon mapping's passes by default.
    int samplesPerPixel = 1;
    // The medium the eye is in (cameraMedium, direct_light.h), found once per render since every
    // camera ray leaves the one pinhole.
    std::uint32_t eyeMedium = kNoMedium;
};

class Integrator {
public:
    virtual ~Integrator() = default;
    // Once per render, before any camera ray: a solve over the whole scene (radiosity) or
    // anything else that does not depend on the pixel.
    virtual void preprocess(const RenderContext&) {}
    // Traces one camera ray. The camera event is already on `path`.
    virtual void traceCameraRay(const Ray& ray, PathState& path) const = 0;
    // True when the integrator splats (PathState::splat) into pixels other than the one sampled.
    virtual bool splats() const { return false; }
    // True when the integrator sees each pixel only at its centre (the rasteriser's fixed sample
    // grid): the renderer then takes exactly one sample per pixel.
    virtual bool samplesPixelCentres() const { return false; }
    // The bytes preprocess keeps in proportion to the image (the rasteriser's z-buffer), so a
    // render that cannot get them is refused before preprocess allocates them.
    virtual std::size_t preprocessBytes(int /*width*/, int /*height*/) const { return 0; }
    // True when a render goes pass by pass over the whole image instead of pixel by pixel
    // (progressive photon mapping: a pass's photons serve every pixel, then make way for the next
    // pass's); startProgressive then starts one (`samplesPerPixel` is the render's --spp), a
    // render or an explanation each its own.
    virtual bool progressive() const { return false; }
    virtual std::unique_ptr<ProgressiveRender> startProgressive(const RenderContext&, int /*samplesPerPixel*/) const {
        return nullptr;
    }
};

// The state of one progressive render: the renderer calls beginPass(k) for k = 0 .. passes() - 1,
// and between two calls every pixel's samples of pass k (samplesPerPass() of them), on any worker;
// traceCameraRay may keep state of pixel (x, y) alone, so the image is the same on any number of
// threads.
class ProgressiveRender {
public:
    virtual ~ProgressiveRender() = default;
    virtual int passes() const = 0;
    virtual int samplesPerPass() const = 0;
    virtual void beginPass(int pass) = 0;
    // Traces one camera ray of pixel (x, y) in the current pass. The camera event is already on `path`.
    virtual void traceCameraRay(const Ray& ray, PathState& path, int x, int y) = 0;
};

// A name of the registry (registry.h); nullptr for an unknown name.
std::unique_ptr<Integrator> makeIntegrator(std::string_view name);

}  // namespace lightpath
