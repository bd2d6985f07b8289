#pragma once
// Pearson's chi-square test of sampled directions against the density that claims to describe
// them, the way Nori's chi2test judges a warping or a BSDF: histogram many sampled directions over
// (cos theta, phi) cells about +z, integrate the claimed density over the same cells for the
// expected counts, pool the cells expecting fewer than 5 (Pearson's test requires it) and read the
// statistic's p-value. One extra cell counts samples that returned no direction; its expected
// count is the density's deficit from 1.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <random>
#include <vector>

#include "math/types.h"
#include "statistics.h"

namespace lightpath::test {

struct DirectionHistogram {
    int cosBins = 16, phiBins = 32;
    int samples = 200000;
    int subdivisions = 12;  // per cell and axis: the midpoint rule that integrates the density
    std::uint64_t seed = 12345;
};

// Cell of a unit direction in the frame of +z: cos theta in [-1, 1], phi in [0, 2 pi). A
// non-finite direction goes to the cell of samples without a direction (and converting NaN to int
// would be undefined behaviour).
inline int directionCell(const DirectionHistogram& h, const Vec3& w) {
    if (!(std::isfinite(w.x) && std::isfinite(w.y) && std::isfinite(w.z))) return h.cosBins * h.phiBins;
    const int c = std::clamp(static_cast<int>((w.z + 1.0f) * 0.5f * h.cosBins), 0, h.cosBins - 1);
    float phi = std::atan2(w.y, w.x);
    if (phi < 0.0f) phi += 2.0f * kPi;
    const int p = std::clamp(static_cast<int>(phi / (2.0f * kPi) * h.phiBins), 0, h.phiBins - 1);
    return c * h.phiBins + p;
}

// p-value that the directions `sample(rng)` returns (std::optional<Vec3>, nullopt for none) follow
// `density(wi)` (solid-angle density, double). 0 when samples land where the density says almost none.
template <typename Sample, typename Density>
double directionChiSquarePValue(const DirectionHistogram& h, Sample&& sample, Density&& density) {
    const int cells = h.cosBins * h.phiBins;
    std::vector<double> observed(cells + 1, 0.0);
    std::mt19937_64 rng(h.seed);
    for (int i = 0; i < h.samples; ++i) {
        const std::optional<Vec3> wi = sample(rng);
        observed[wi ? directionCell(h, *wi) : cells] += 1.0;
    }

    // Expected: the density integrated over each cell (midpoint rule; dw = dcos dphi). A grid of
    // half the subdivisions bounds the rule's error by |coarse - fine| (it falls as the step
    // squared for a smooth density, only as the step where a density is steep at the horizon, as
    // a refraction lobe from grazing incidence is): where that is above a fifth of the cell's
    // Poisson noise (or a peak is narrower than a sub-cell, e.g. a nearly smooth GGX lobe or one
    // that Snell's law squeezes), the cell is integrated again with twice the subdivisions, three
    // times at most. Only the few cells at a peak or an edge pay for it.
    std::vector<double> expected(observed.size(), 0.0);
    double total = 0.0, integrationError = 0.0;  // the error in counts, summed over the cells
    const auto integrate = [&](int c, int p, int sub) {
        double integral = 0.0;
        for (int a = 0; a < sub; ++a) {
            for (int b = 0; b < sub; ++b) {
                const double z = -1.0 + 2.0 * (c + (a + 0.5) / sub) / h.cosBins;
                const double phi = 2.0 * M_PI * (p + (b + 0.5) / sub) / h.phiBins;
                const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
                integral += density(Vec3{float(r * std::cos(phi)), float(r * std::sin(phi)), float(z)});
            }
        }
        return integral / (double(sub) * sub);
    };
    const double cellCounts = (2.0 / h.cosBins) * (2.0 * M_PI / h.phiBins) * h.samples;  // counts per unit mean density
    for (int c = 0; c < h.cosBins; ++c) {
        for (int p = 0; p < h.phiBins; ++p) {
            int sub = std::max(2, h.subdivisions);
            double coarse = integrate(c, p, sub / 2), fine = integrate(c, p, sub);
            for (int refinement = 0;
                 refinement < 3 && std::fabs(coarse - fine) * cellCounts > 0.2 * std::sqrt(std::max(1.0, fine * cellCounts));
                 ++refinement) {
                sub *= 2;
                coarse = fine;
                fine = integrate(c, p, sub);
            }
            const double cell = fine * cellCounts / h.samples;
            expected[c * h.phiBins + p] = cell * h.samples;
            total += cell;
            integrationError += std::fabs(coarse - fine) * cellCounts;
        }
    }
    expected.back() = std::max(0.0, 1.0 - total) * h.samples;

    double statistic = 0.0, pooledObserved = 0.0, pooledExpected = 0.0;
    int used = 0;
    for (std::size_t i = 0; i < observed.size(); ++i) {
        if (expected[i] < 5.0) {
            pooledObserved += observed[i];
            pooledExpected += expected[i];
            continue;
        }
        // The deficit cell's expectation, 1 minus the sum of all the others, carries their
        // integration errors (each within its own cell's noise, together above the deficit's):
        // their estimate joins its Poisson variance.
        const double variance = i + 1 == observed.size() ? expected[i] + integrationError * integrationError : expected[i];
        statistic += (observed[i] - expected[i]) * (observed[i] - expected[i]) / variance;
        ++used;
    }
    if (pooledExpected >= 5.0) {
        statistic += (pooledObserved - pooledExpected) * (pooledObserved - pooledExpected) / pooledExpected;
        ++used;
    } else if (pooledObserved > 10.0) {
        return 0.0;  // samples where the density says there are (almost) none
    }
    if (used < 2) return 1.0;  // one cell holds everything: nothing to compare
    return chiSquarePValue(statistic, used - 1);
}

}  // namespace lightpath::test
