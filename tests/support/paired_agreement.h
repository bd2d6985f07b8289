#pragma once
// Two unbiased renders of one scene agree: per layer and channel, the paired per-pixel differences
// (common random numbers keep them small) have mean 0 by Student's t-test, and a control, the first
// against 1.05 times the second, is rejected wherever the layer holds light. Where the two
// estimators coincide (bdpt's direct light under a camera it cannot join is the path tracer's),
// their differences are float rounding, as systematic as it is small, which a t-test would reject:
// a mean difference within kRounding of the layer's mean is agreement.
#include <cmath>
#include <cstddef>
#include <vector>

#include <doctest/doctest.h>

#include "film/film.h"
#include "statistics.h"

namespace lightpath::test {

// One channel of one layer, pixel by pixel: the samples of a per-pixel test.
inline std::vector<double> channelValues(const Film& film, std::size_t layer, int c) {
    std::vector<double> values;
    for (int y = 0; y < film.height(); ++y)
        for (int x = 0; x < film.width(); ++x) values.push_back(film.at(layer, x, y)[c]);
    return values;
}

inline double meanOf(const std::vector<double>& values) {
    double sum = 0.0;
    for (double v : values) sum += v;
    return sum / double(values.size());
}

inline constexpr double kRounding = 1e-5;

inline void checkPairedAgreement(const Film& a, const Film& b, double pValue) {
    REQUIRE(a.layerNames() == b.layerNames());
    int controls = 0;
    for (std::size_t layer = 0; layer < a.layerCount(); ++layer) {
        for (int c = 0; c < 3; ++c) {
            const std::vector<double> x = channelValues(a, layer, c), y = channelValues(b, layer, c);
            std::vector<double> difference(x.size()), wrong(x.size());
            for (std::size_t i = 0; i < x.size(); ++i) {
                difference[i] = x[i] - y[i];
                wrong[i] = x[i] - 1.05 * y[i];
            }
            CAPTURE(a.layerNames()[layer]);
            CAPTURE(c);
            CAPTURE(meanOf(x));
            CAPTURE(meanOf(y));
            const double mean = meanOf(difference), size = std::abs(meanOf(y));
            if (!(std::abs(mean) <= kRounding * size)) CHECK(studentTTest(difference, 0.0) > pValue);
            if (meanOf(y) > 1e-3) {
                CHECK(studentTTest(wrong, 0.0) < pValue);
                ++controls;
            }
        }
    }
    CHECK(controls >= 6);  // beauty and at least one AOV in every channel carried the controls
}

}  // namespace lightpath::test
