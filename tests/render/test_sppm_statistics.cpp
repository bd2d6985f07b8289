// The per-visible-point statistics of stochastic progressive photon mapping against hand-evaluated
// updates and the closed form of a uniform flux density, which the progressive estimate must
// reproduce exactly for any alpha and any photon counts (Hachisuka and Jensen 2009, sec. 4).
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <numbers>

#include "integrators/sppm_statistics.h"

namespace lightpath {
namespace {

TEST_CASE("sppm statistics: count and radius follow the update by hand") {
    SppmStatistics stats(1, 1, 1.0f);
    const std::array<Rgb, 1> none{Rgb{0.0f}};
    // Pass 1: M = 30, N' = 2/3 30 = 20, R'^2 = 1 * 20 / 30.
    stats.update(0, 30, none, 2.0 / 3.0);
    CHECK(stats.photonCount(0) == doctest::Approx(20.0));
    CHECK(stats.radius(0) == doctest::Approx(std::sqrt(2.0 / 3.0)).epsilon(1e-6));
    // Pass 2: M = 15, N' = 20 + 10 = 30, R'^2 = 2/3 * 30 / 35 = 4/7.
    stats.update(0, 15, none, 2.0 / 3.0);
    CHECK(stats.photonCount(0) == doctest::Approx(30.0));
    CHECK(stats.radius(0) == doctest::Approx(std::sqrt(4.0 / 7.0)).epsilon(1e-6));
    // A pass that found nothing changes nothing.
    stats.update(0, 0, none, 2.0 / 3.0);
    CHECK(stats.photonCount(0) == doctest::Approx(30.0));
    CHECK(stats.radius(0) == doctest::Approx(std::sqrt(4.0 / 7.0)).epsilon(1e-6));
}

TEST_CASE("sppm statistics: a uniform flux density is estimated exactly for any alpha") {
    // Each pass finds flux rho pi R^2 within the current radius, whatever its photon count: by
    // induction tau_i = i rho pi R_i^2, so tau / (passes pi R^2) is rho after every pass, per layer.
    const std::array<Rgb, 2> density{Rgb{0.5f, 1.0f, 2.0f}, Rgb{0.125f, 0.0f, 3.0f}};
    for (const double alpha : {2.0 / 3.0, 0.3, 1.0}) {
        CAPTURE(alpha);
        SppmStatistics stats(1, density.size(), 0.25f);
        for (int pass = 1; pass <= 12; ++pass) {
            const double area = std::numbers::pi * double(stats.radius(0)) * double(stats.radius(0));
            const std::array<Rgb, 2> flux{density[0] * float(area), density[1] * float(area)};
            stats.update(0, std::uint64_t(7 + (pass * 13) % 17), flux, alpha);
            for (std::size_t layer = 0; layer < density.size(); ++layer) {
                const Rgb estimate = stats.radiance(0, layer, pass);
                for (int c = 0; c < 3; ++c) CHECK(estimate[c] == doctest::Approx(density[layer][c]).epsilon(1e-5));
            }
        }
        if (alpha < 1.0) CHECK(stats.radius(0) < 0.25f * 0.6f);
    }
}

TEST_CASE("sppm statistics: memory is the same after 2 and 8 passes") {
    const std::size_t points = 64 * 48, layers = 4;
    SppmStatistics stats(points, layers, 0.1f);
    const std::array<Rgb, layers> flux{Rgb{1.0f}, Rgb{2.0f}, Rgb{0.0f}, Rgb{3.0f}};
    const auto passes = [&](int count) {
        for (int pass = 0; pass < count; ++pass)
            for (std::size_t point = 0; point < points; ++point) stats.update(point, 5, flux, 2.0 / 3.0);
    };
    passes(2);
    const std::size_t afterTwo = stats.bytes();
    passes(6);
    CHECK(stats.bytes() == afterTwo);
    // N, R and one tau per layer for each point: nothing per pass.
    CHECK(afterTwo == points * (sizeof(double) + sizeof(float) + layers * sizeof(Rgb)));
}

}  // namespace
}  // namespace lightpath
