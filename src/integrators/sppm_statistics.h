#pragma once
// The per-visible-point statistics of stochastic progressive photon mapping (Hachisuka and Jensen
// 2009, "Stochastic Progressive Photon Mapping", sec. 4; the update pbrt-v3's SPPMIntegrator
// makes): per point a photon count N, a radius R and an unnormalised flux tau, here one tau per
// image layer (the beauty and each requested output), since each photon's contribution is
// classified when it is found. After a pass that found M photons within R carrying flux Phi,
//     N' = N + alpha M,   R' = R sqrt(N' / (N + M)),   tau' = (tau + Phi) R'^2 / R^2,
// and the radiance after `passes` passes is tau / (passes pi R^2), the photons' power being already
// divided by the paths shot per pass (photon_map.h).
// Memory is O(points x layers) and independent of the passes: a pass's flux is folded in and
// dropped. The integrator that traces the visible points and shoots the passes is not built on
// this yet (sppm.h still keeps a photon map per pass).
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "math/types.h"

namespace lightpath {

class SppmStatistics {
public:
    SppmStatistics(std::size_t points, std::size_t layers, float initialRadius);

    std::size_t points() const { return photonCount_.size(); }
    std::size_t layers() const { return layers_; }
    float radius(std::size_t point) const { return radius_[point]; }
    double photonCount(std::size_t point) const { return photonCount_[point]; }
    std::span<const Rgb> tau(std::size_t point) const { return {tau_.data() + point * layers_, layers_}; }

    // Folds one pass into `point`: `found` photons within radius(point), whose classified flux per
    // layer is `flux` (layers() values). A pass that found none changes nothing (N + M = 0 would
    // divide by zero, and Phi is 0).
    void update(std::size_t point, std::uint64_t found, std::span<const Rgb> flux, double alpha);

    // The radiance of `layer` at `point` after `passes` passes.
    Rgb radiance(std::size_t point, std::size_t layer, int passes) const;

    // What the statistics keep: the same after any number of passes.
    std::size_t bytes() const;

private:
    std::size_t layers_;
    std::vector<double> photonCount_;  // N: fractional after the first pass (alpha M)
    std::vector<float> radius_;
    std::vector<Rgb> tau_;  // points x layers, point-major
};

}  // namespace lightpath
