// The per-pixel statistics of stochastic progressive photon mapping against hand-evaluated updates
// and against Hachisuka and Jensen's flux update evaluated independently here: the mean of the
// passes' density estimates at the radii these statistics give must equal tau_n / (n pi R_n^2),
// the identity sppm's image rests on (sppm_statistics.h).
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "integrators/sppm_statistics.h"

namespace lightpath {
namespace {

TEST_CASE("sppm statistics: count and radius follow the update by hand") {
    SppmStatistics stats(1, 1.0f);
    // Pass 1: M = 30, N' = 2/3 30 = 20, R'^2 = 1 * 20 / 30.
    stats.update(0, 30, 2.0 / 3.0);
    CHECK(stats.photonCount(0) == doctest::Approx(20.0));
    CHECK(stats.radius(0) == doctest::Approx(std::sqrt(2.0 / 3.0)).epsilon(1e-6));
    // Pass 2: M = 15, N' = 20 + 10 = 30, R'^2 = 2/3 * 30 / 35 = 4/7.
    stats.update(0, 15, 2.0 / 3.0);
    CHECK(stats.photonCount(0) == doctest::Approx(30.0));
    CHECK(stats.radius(0) == doctest::Approx(std::sqrt(4.0 / 7.0)).epsilon(1e-6));
    // A pass that found nothing changes nothing.
    stats.update(0, 0, 2.0 / 3.0);
    CHECK(stats.photonCount(0) == doctest::Approx(30.0));
    CHECK(stats.radius(0) == doctest::Approx(std::sqrt(4.0 / 7.0)).epsilon(1e-6));
}

TEST_CASE("sppm statistics: the mean of the passes' estimates is Hachisuka and Jensen's tau / (n pi R^2)") {
    for (const double alpha : {2.0 / 3.0, 0.3, 1.0}) {
        CAPTURE(alpha);
        SppmStatistics stats(1, 0.25f);
        double n = 0.0, tau = 0.0, meanOfPasses = 0.0;  // N and tau as the paper updates them
        for (int pass = 1; pass <= 20; ++pass) {
            const std::uint64_t found = std::uint64_t((pass * 13) % 17);  // some passes find none
            const double flux = 0.01 * double(found) * (1.0 + 0.5 * std::sin(pass));
            const double r = stats.radius(0);
            meanOfPasses += (flux / (std::numbers::pi * r * r) - meanOfPasses) / pass;
            if (found > 0) {
                const double nNew = n + alpha * double(found);
                tau = (tau + flux) * nNew / (n + double(found));
                n = nNew;
            }
            stats.update(0, found, alpha);
            const double rNew = stats.radius(0);
            CHECK(tau / (pass * std::numbers::pi * rNew * rNew) == doctest::Approx(meanOfPasses).epsilon(1e-5));
        }
        CHECK(stats.photonCount(0) == doctest::Approx(n));
        if (alpha < 1.0) CHECK(stats.radius(0) < 0.25f * 0.6f);
    }
}

TEST_CASE("sppm statistics: memory is the same after 2 and 8 passes") {
    const std::size_t points = 64 * 48;
    SppmStatistics stats(points, 0.1f);
    const auto passes = [&](int count) {
        for (int pass = 0; pass < count; ++pass)
            for (std::size_t point = 0; point < points; ++point) stats.update(point, 5, 2.0 / 3.0);
    };
    passes(2);
    const std::size_t afterTwo = stats.bytes();
    passes(6);
    CHECK(stats.bytes() == afterTwo);
    // N and R for each point: nothing per pass.
    CHECK(afterTwo == points * (sizeof(double) + sizeof(float)));
}

}  // namespace
}  // namespace lightpath
