#pragma once
// Stochastic progressive photon mapping (Hachisuka and Jensen 2009). The render goes pass by pass
// (ProgressiveRender): each pass shoots its photons (photon_map.h) and drops the last pass's, then
// every pixel traces a camera ray to its visible points (photon.h's eye walk: direct light by
// next-event estimation, photons at the first diffuse or glossy vertex) and merges the photons
// within its own radius R, which shrinks by the photons it found (sppm_statistics.h), so the blur
// and the noise both vanish as passes grow. Each photon's contribution is classified when it is
// found, as photon mapping's are, and the image is the mean of the passes: memory is the pixels'
// statistics and one pass's photons, whatever the number of passes.
#include <optional>

#include "integrators/photon.h"
#include "integrators/sppm_statistics.h"

namespace lightpath {

// Photon paths per pass when no --photons is given (the schema's default says the same), and the
// default share of new photons each pass keeps (Hachisuka and Jensen 2009 use 0.7; pbrt 2/3).
inline constexpr std::uint64_t kDefaultSppmPhotons = 20000;
inline constexpr double kDefaultSppmAlpha = 2.0 / 3.0;

struct SppmSettings {
    std::uint64_t photons = kDefaultSppmPhotons;  // per pass
    int passes = 0;  // 0: the render's samples per pixel, one a pass; else spp / passes a pass
    float firstRadius = 0.0f;
    double alpha = kDefaultSppmAlpha;
};

// One sppm render: the pixels' statistics and the current pass's photons.
class SppmRender final : public ProgressiveRender {
public:
    SppmRender(const RenderContext& context, const SppmSettings& settings, int samplesPerPixel);

    int passes() const override { return passes_; }
    int samplesPerPass() const override { return samplesPerPass_; }
    void beginPass(int pass) override;
    void traceCameraRay(const Ray& ray, PathState& path, int x, int y) override;
    // Photons shot and kept over the passes, the largest pass's bytes with the statistics', and
    // the pixels' mean radius in the last pass.
    PhotonStats stats() const;

private:
    const RenderContext& context_;
    SppmSettings settings_;
    int passes_, samplesPerPass_;
    std::optional<lpe::SuffixReader> reader_;
    SppmStatistics pixels_;
    // The photons each pixel's camera rays found in the current pass (M, summed over its samples):
    // folded into the statistics when the next pass begins, so every ray of a pass merges with
    // the radius the pass began with (a radius shrunk by this pass's own photons would favour them).
    std::vector<std::uint64_t> found_;
    int pass_ = -1;
    PhotonMap caustic_, global_;
    PhotonStats stats_;
};

class SppmIntegrator final : public Integrator {
public:
    void preprocess(const RenderContext& context) override;
    // sppm renders pass by pass only: the renderer calls startProgressive, never this.
    void traceCameraRay(const Ray& ray, PathState& path) const override;
    bool progressive() const override { return true; }
    std::unique_ptr<ProgressiveRender> startProgressive(const RenderContext& context, int samplesPerPixel) const override;

private:
    SppmSettings settings_;
};

}  // namespace lightpath
