#include "integrators/sppm_statistics.h"

#include <cmath>

namespace lightpath {

SppmStatistics::SppmStatistics(std::size_t points, float initialRadius)
    : photonCount_(points, 0.0), radius_(points, initialRadius) {}

void SppmStatistics::update(std::size_t point, double found, double alpha) {
    if (!(found > 0.0)) return;
    const double n = photonCount_[point];
    const double nNew = n + alpha * found;
    // R'^2 / R^2 = N' / (N + M): the disc shrinks in the share of the new photons kept.
    photonCount_[point] = nNew;
    radius_[point] = float(double(radius_[point]) * std::sqrt(nNew / (n + found)));
}

std::size_t SppmStatistics::bytes() const {
    return photonCount_.capacity() * sizeof(double) + radius_.capacity() * sizeof(float);
}

}  // namespace lightpath
