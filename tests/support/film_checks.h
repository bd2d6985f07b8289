#pragma once
// What every render promises of its film (docs/design.md): the AOVs and `rest` sum to the beauty,
// and no value is NaN, infinite or negative. One reading for the suites that check it.
#include <algorithm>
#include <cmath>
#include <string>

#include "film/film.h"

namespace lightpath::test {

// The largest |sum of layers 1.. - beauty| over pixels and channels, in units of the tolerance
// 1e-5 |beauty| + 1e-7 (float rounding of the sums): at most 1 passes.
inline double worstSumError(const Film& film) {
    double worst = 0.0;
    for (int y = 0; y < film.height(); ++y) {
        for (int x = 0; x < film.width(); ++x) {
            Rgb sum{0.0f};
            for (std::size_t l = 1; l < film.layerCount(); ++l) sum += film.at(l, x, y);
            const Rgb beauty = film.at(0, x, y);
            for (int c = 0; c < 3; ++c) {
                const double error = std::fabs(double(sum[c]) - double(beauty[c]));
                worst = std::max(worst, error / (1e-5 * std::fabs(double(beauty[c])) + 1e-7));
            }
        }
    }
    return worst;
}

// Every value of every layer finite and >= 0.
inline bool finiteNonNegative(const Film& film) {
    return std::all_of(film.interleaved().begin(), film.interleaved().end(), [](const Rgb& v) {
        return std::isfinite(v.r) && std::isfinite(v.g) && std::isfinite(v.b) && v.r >= 0.0f && v.g >= 0.0f && v.b >= 0.0f;
    });
}

// The index of the layer named `name` (layerCount() when there is none).
inline std::size_t layerOf(const Film& film, const std::string& name) {
    const auto& names = film.layerNames();
    return static_cast<std::size_t>(std::find(names.begin(), names.end(), name) - names.begin());
}

inline double layerSum(const Film& film, std::size_t layer) {
    double sum = 0.0;
    for (const Rgb& v : film.layer(layer)) sum += double(v.r) + double(v.g) + double(v.b);
    return sum;
}

// The largest relative difference of the mean luminance of `a` and `b` over blocks of `side` x
// `side` pixels, among the blocks where `b` holds light.
inline double worstBlockError(const Film& a, const Film& b, int side) {
    double worst = 0.0;
    for (int by = 0; by + side <= a.height(); by += side) {
        for (int bx = 0; bx + side <= a.width(); bx += side) {
            double sa = 0.0, sb = 0.0;
            for (int y = by; y < by + side; ++y)
                for (int x = bx; x < bx + side; ++x) {
                    const Rgb va = a.at(0, x, y), vb = b.at(0, x, y);
                    sa += double(va.r + va.g + va.b);
                    sb += double(vb.r + vb.g + vb.b);
                }
            if (sb > 1e-3 * side * side) worst = std::max(worst, std::fabs(sa - sb) / sb);
        }
    }
    return worst;
}

inline Film scaled(Film film, float factor) {
    for (int y = 0; y < film.height(); ++y)
        for (int x = 0; x < film.width(); ++x) film.at(0, x, y) *= factor;
    return film;
}

}  // namespace lightpath::test
