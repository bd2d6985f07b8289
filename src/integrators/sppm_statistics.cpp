#include "integrators/sppm_statistics.h"

#include <cassert>
#include <cmath>
#include <numbers>

namespace lightpath {

SppmStatistics::SppmStatistics(std::size_t points, std::size_t layers, float initialRadius)
    : layers_(layers), photonCount_(points, 0.0), radius_(points, initialRadius), tau_(points * layers, Rgb{0.0f}) {}

void SppmStatistics::update(std::size_t point, std::uint64_t found, std::span<const Rgb> flux, double alpha) {
    assert(flux.size() == layers_);
    if (found == 0) return;
    const double n = photonCount_[point];
    const double nNew = n + alpha * double(found);
    // R'^2 / R^2 = N' / (N + M): the area shrinks in the share of the new photons kept.
    const double shrink = nNew / (n + double(found));
    photonCount_[point] = nNew;
    radius_[point] = float(double(radius_[point]) * std::sqrt(shrink));
    Rgb* tau = tau_.data() + point * layers_;
    for (std::size_t layer = 0; layer < layers_; ++layer)
        tau[layer] = Rgb((glm::dvec3(tau[layer]) + glm::dvec3(flux[layer])) * shrink);
}

Rgb SppmStatistics::radiance(std::size_t point, std::size_t layer, int passes) const {
    const double r = radius_[point];
    if (passes <= 0 || r <= 0.0) return Rgb{0.0f};
    return Rgb(glm::dvec3(tau(point)[layer]) / (double(passes) * std::numbers::pi * r * r));
}

std::size_t SppmStatistics::bytes() const {
    return photonCount_.capacity() * sizeof(double) + radius_.capacity() * sizeof(float) +
           tau_.capacity() * sizeof(Rgb);
}

}  // namespace lightpath
