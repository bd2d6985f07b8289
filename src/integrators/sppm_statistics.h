#pragma once
// The per-pixel statistics of stochastic progressive photon mapping (Hachisuka and Jensen 2009,
// "Stochastic Progressive Photon Mapping", sec. 4; the update pbrt-v3's SPPMIntegrator makes): a
// photon count N and a radius R per pixel, whose visible points are traced anew in every pass.
// After a pass that found M photons within R,
//     N' = N + alpha M,   R' = R sqrt(N' / (N + M)),
// and Hachisuka and Jensen's flux tau' = (tau + Phi) R'^2 / R^2 makes the radiance after n passes
//     tau_n / (n pi R_n^2) = (1/n) sum_i Phi_i / (pi R_i^2),
// since the factors R'^2 / R^2 telescope: the mean of each pass's density estimate at that pass's
// radius. So no flux is kept here: each photon's contribution is classified and added to the
// pixel's image layers when it is found, as photon mapping's are, and memory is O(pixels),
// independent of the passes.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace lightpath {

class SppmStatistics {
public:
    SppmStatistics(std::size_t points, float initialRadius);

    std::size_t points() const { return photonCount_.size(); }
    float radius(std::size_t point) const { return radius_[point]; }
    double photonCount(std::size_t point) const { return photonCount_[point]; }

    // Folds one pass that found `found` photons within radius(point) into `point` (a mean over the
    // pass's camera rays when it took several). A pass that found none changes nothing (N + M = 0
    // would divide by zero).
    void update(std::size_t point, double found, double alpha);

    // What the statistics keep: the same after any number of passes.
    std::size_t bytes() const;

private:
    std::vector<double> photonCount_;  // N: fractional after the first pass (alpha M)
    std::vector<float> radius_;
};

}  // namespace lightpath
