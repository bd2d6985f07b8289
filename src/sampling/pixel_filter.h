#pragma once
// The pixel reconstruction filter, applied by filter importance sampling (Ernst, Stamminger and
// Greiner, "Filter Importance Sampling", IEEE Symposium on Interactive Ray Tracing 2006; as in
// pbrt-v4 sec. 8.8 and Cycles): a pixel's camera rays are placed around its centre with density
// proportional to the filter, so every sample has weight 1, a pixel is the plain mean of its own
// samples, and nothing is splatted into neighbours. Only non-negative filters qualify. Each filter
// is separable, f(x, y) = f(x) f(y), and sampled per axis:
//   box              1 on [-0.5, 0.5]: the pixel's square (the default)
//   tent             1 - |x| on [-1, 1]
//   gaussian         exp(-x^2 / (2 sigma^2)), sigma = 0.5, cut at |x| = 1.5 (pbrt-v4's default)
//   blackman-harris  the four-term Blackman-Harris window over [-1.5, 1.5]: what Cycles'
//                    default "Blackman-Harris, 1.5 px" filters with
// Sampling inverts the filter's integral tabulated at kFilterTableSize points per half, linear
// between them: the filter rendered is the piecewise-constant one of those bins (box is exact).
#include <array>
#include <string_view>

#include "math/types.h"

namespace lightpath {

enum class PixelFilterKind { Box, Tent, Gaussian, BlackmanHarris };

// "box", "tent", "gaussian", "blackman-harris"; false for another name.
bool parsePixelFilterKind(std::string_view name, PixelFilterKind& kind);
const char* pixelFilterName(PixelFilterKind kind);

inline constexpr int kFilterTableSize = 64;

class PixelFilter {
public:
    explicit PixelFilter(PixelFilterKind kind = PixelFilterKind::Box);

    PixelFilterKind kind() const { return kind_; }
    // Half the support's width, in pixels.
    float radius() const { return radius_; }
    // The filter's 1D profile at offset x (unnormalised), as written above.
    float evaluate(float x) const;
    // A uniform point of [0,1)^2 mapped to an offset from the pixel centre distributed as the
    // filter; monotone per axis, so stratified and low-discrepancy points stay so.
    Vec2 sample(Vec2 u) const;
    // The density sample() draws an offset with, per axis and together: the tabulated filter,
    // normalised. Light tracing splats a film position into each pixel with this weight, so its
    // estimate of a pixel is the same filtered integral the pixel's own samples estimate.
    float density(float x) const;
    float density(Vec2 offset) const { return density(offset.x) * density(offset.y); }

private:
    float sample1D(float u) const;

    PixelFilterKind kind_;
    float radius_;
    std::array<float, kFilterTableSize + 1> cdf_{};  // of |x| over [0, radius], cdf_[0] = 0, last = 1
};

}  // namespace lightpath
