#pragma once
#include <string>
#include <vector>

#include "integrators/integrator.h"

namespace lightpath {

// Bidirectional path tracing (Veach and Guibas 1995; Veach 1997, ch. 10). Per camera sample, a
// walk from a light (chosen by power) and a walk from the eye; every vertex of one is joined to
// every vertex of the other by a shadow ray, each join (s light vertices, t eye vertices) one
// strategy, all weighted by the power heuristic:
//   s = 0   the eye's walk hits an emitter (the path tracer's BSDF-sampled emission)
//   s = 1   light sampling at an eye vertex (the path tracer's next-event estimation)
//   t = 1   light tracing: a light vertex joined to the pinhole, splatted where it lands
//   s, t >= 2  a light vertex joined to an eye vertex
// Only light walks find E (D|G) S+ L under a point light (caustics): no eye walk can hit a point
// and no light sampling can pass through a delta lobe. Each contribution's whole path, the eye's
// vertices, the join, then the light's vertices reversed, runs through the automaton with the
// events the other integrators use, so every AOV means the same light. Produces E .* L.
// The fraction of camera samples that walked from a light, and why (--stats).
struct BdptStats {
    double lightWalkFraction = 1.0;
    std::string reason;
    std::uint64_t pilotSamples = 0;
    struct Candidate {
        double fraction, variance, work;  // variance and work (rays) per camera sample
        double error;  // standard error of its variance x work minus the least's (0 for the least)
    };
    std::vector<Candidate> candidates;  // the pilot's estimates, when one chose
    double seconds = 0.0;               // the pilot's
};

class BdptIntegrator final : public Integrator {
public:
    enum class Strategies : std::uint8_t {
        All,               // every strategy, MIS-weighted
        LightTracingOnly,  // t = 1 alone, unweighted: pure light tracing (tests, lectures)
    };
    explicit BdptIntegrator(Strategies strategies = Strategies::All) : strategies_(strategies) {}

    void preprocess(const RenderContext& context) override;
    void traceCameraRay(const Ray& ray, PathState& path) const override;
    bool splats() const override { return true; }
    const BdptStats& stats() const { return stats_; }

private:
    // q, the fraction of camera samples that walk from a light: the light-walk-fraction
    // parameter, or the pilot's choice (bdpt_allocation.h).
    void chooseLightWalkFraction(const RenderContext& context);

    // False when no requested output accepts a path with a scattering event before its light:
    // then no light walk could add anything, none is traced, and the strategies s >= 2 are out of
    // the weights (what remains is the path tracer's s = 0 and s = 1).
    bool lightWalks_ = true;
    double fraction_ = 1.0;
    BdptStats stats_;
    Strategies strategies_;
};

}  // namespace lightpath
