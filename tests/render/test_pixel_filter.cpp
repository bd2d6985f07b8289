// Filter importance sampling (sampling/pixel_filter.h): the offsets a filter draws are distributed
// as the filter, checked against each filter's integral written out in closed form here (not the
// table the code inverts), by a Kolmogorov-Smirnov test with a control that must fail.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include "math/random.h"
#include "sampling/pixel_filter.h"

namespace lightpath {
namespace {

using Cdf = std::function<double(double)>;

double tentCdf(double x) { return x <= 0.0 ? 0.5 * (x + 1.0) * (x + 1.0) : 1.0 - 0.5 * (1.0 - x) * (1.0 - x); }

// exp(-x^2 / (2 sigma^2)) with sigma = 0.5, cut at |x| = 1.5: a truncated normal.
double gaussianCdf(double x) {
    auto phi = [](double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); };
    const double sigma = 0.5, radius = 1.5;
    return (phi(x / sigma) - phi(-radius / sigma)) / (phi(radius / sigma) - phi(-radius / sigma));
}

// a0 - a1 cos(p) + a2 cos(2p) - a3 cos(3p) with p = pi x / R + pi runs over [0, 2 pi] on [-R, R];
// its integral from -R, over the whole, (a0 p - a1 sin p + a2 sin 2p / 2 - a3 sin 3p / 3) / (2 pi a0).
double blackmanHarrisCdf(double x) {
    const double a0 = 0.35875, a1 = 0.48829, a2 = 0.14128, a3 = 0.01168, radius = 1.5;
    const double p = M_PI * x / radius + M_PI;
    return (a0 * p - a1 * std::sin(p) + a2 * std::sin(2.0 * p) / 2.0 - a3 * std::sin(3.0 * p) / 3.0) / (2.0 * M_PI * a0);
}

std::vector<double> offsets(PixelFilterKind kind, int count, bool yAxis) {
    const PixelFilter filter(kind);
    Pcg32 rng(7, 11);
    std::vector<double> xs;
    for (int i = 0; i < count; ++i) {
        const Vec2 u{rng.nextFloat(), rng.nextFloat()};
        const Vec2 offset = filter.sample(u);
        xs.push_back(yAxis ? offset.y : offset.x);
    }
    std::sort(xs.begin(), xs.end());
    return xs;
}

// The Kolmogorov-Smirnov statistic of sorted samples against `cdf`.
double ksStatistic(const std::vector<double>& sorted, const Cdf& cdf) {
    const double n = static_cast<double>(sorted.size());
    double d = 0.0;
    for (std::size_t i = 0; i < sorted.size(); ++i) {
        const double f = cdf(sorted[i]);
        d = std::max({d, f - static_cast<double>(i) / n, static_cast<double>(i + 1) / n - f});
    }
    return d;
}

constexpr int kSamples = 1 << 16;
// The 0.1% critical value of the KS statistic: 1.95 / sqrt(n).
const double kCritical = 1.95 / std::sqrt(double(kSamples));

TEST_CASE("pixel filters: offsets are distributed as the filter, on both axes (Kolmogorov-Smirnov)") {
    const std::pair<PixelFilterKind, Cdf> cases[] = {
        {PixelFilterKind::Tent, tentCdf},
        {PixelFilterKind::Gaussian, gaussianCdf},
        {PixelFilterKind::BlackmanHarris, blackmanHarrisCdf},
    };
    for (const auto& c : cases) {  // no structured binding: CAPTURE's lambda cannot capture one (clang 14)
        const PixelFilterKind kind = c.first;
        for (bool yAxis : {false, true}) {
            CAPTURE(pixelFilterName(kind));
            CAPTURE(yAxis);
            CHECK(ksStatistic(offsets(kind, kSamples, yAxis), c.second) < kCritical);
        }
    }
}

TEST_CASE("control: a filter's offsets fail another filter's distribution") {
    CHECK(ksStatistic(offsets(PixelFilterKind::Box, kSamples, false), tentCdf) > kCritical);
    CHECK(ksStatistic(offsets(PixelFilterKind::Gaussian, kSamples, false), blackmanHarrisCdf) > kCritical);
    CHECK(ksStatistic(offsets(PixelFilterKind::Tent, kSamples, false), gaussianCdf) > kCritical);
}

TEST_CASE("pixel filters: the box is the pixel's square exactly, and every map is monotone within the support") {
    const PixelFilter box(PixelFilterKind::Box);
    for (float u : {0.0f, 0.25f, 0.5f, 0.999f}) CHECK(box.sample({u, u}).x + 0.5f == u);
    for (PixelFilterKind kind : {PixelFilterKind::Tent, PixelFilterKind::Gaussian, PixelFilterKind::BlackmanHarris}) {
        CAPTURE(pixelFilterName(kind));
        const PixelFilter filter(kind);
        float previous = -filter.radius();
        for (int i = 0; i < 4096; ++i) {
            const float x = filter.sample({static_cast<float>(i) / 4096.0f, 0.5f}).x;
            CHECK(x >= previous);
            CHECK(std::fabs(x) <= filter.radius());
            previous = x;
        }
    }
}

TEST_CASE("pixel filters: names parse and print back") {
    for (PixelFilterKind kind : {PixelFilterKind::Box, PixelFilterKind::Tent, PixelFilterKind::Gaussian,
                                 PixelFilterKind::BlackmanHarris}) {
        PixelFilterKind parsed = PixelFilterKind::Box;
        CHECK(parsePixelFilterKind(pixelFilterName(kind), parsed));
        CHECK(parsed == kind);
    }
    PixelFilterKind unused;
    CHECK_FALSE(parsePixelFilterKind("mitchell", unused));
}

}  // namespace
}  // namespace lightpath
