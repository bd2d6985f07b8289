#pragma once
// Stochastic progressive photon mapping (Hachisuka and Jensen 2009) in its probabilistic form
// (Knaus and Zwicker 2011, "Progressive Photon Mapping: A Probabilistic Approach"): pass i is an
// independent photon map whose radius shrinks as r_{i+1}^2 = r_i^2 (i + alpha) / (i + 1), the
// schedule SPPM's per-point update N += alpha M follows, and the image is the mean of the passes'
// estimates, so its bias (the blur) and its variance both vanish as passes grow. A pixel's sample
// k reads pass k mod passes, so --spp counts passes and the renderer's per-pixel mean is the
// progressive estimate; each contribution is classified when it is made, as photon mapping's are
// (photon.h), so the AOVs need no flux of their own per visible point.
#include <vector>

#include "integrators/photon.h"

namespace lightpath {

// Photon paths per pass when no --photons is given (the schema's default says the same), and the
// default radius reduction (Hachisuka and Jensen 2009 use 0.7; pbrt 2/3).
inline constexpr std::uint64_t kDefaultSppmPhotons = 20000;
inline constexpr double kDefaultSppmAlpha = 2.0 / 3.0;

// The radius of pass `pass` (from 0) after `firstRadius`: r_{i+1}^2 = r_i^2 (i + alpha) / (i + 1).
float sppmRadius(float firstRadius, double alpha, int pass);

class SppmIntegrator final : public Integrator {
public:
    void preprocess(const RenderContext& context) override;
    void traceCameraRay(const Ray& ray, PathState& path) const override;
    const PhotonStats& stats() const { return stats_; }

private:
    struct Pass {
        PhotonMap caustic, global;
    };
    std::vector<Pass> passes_;
    PhotonStats stats_;
};

}  // namespace lightpath
