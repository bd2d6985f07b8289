#include "sampling/pixel_filter.h"

#include <algorithm>
#include <cmath>

namespace lightpath {
namespace {

constexpr float kGaussianSigma = 0.5f;
constexpr float kGaussianRadius = 1.5f;
constexpr float kBlackmanHarrisRadius = 1.5f;

float filterRadius(PixelFilterKind kind) {
    switch (kind) {
        case PixelFilterKind::Box: return 0.5f;
        case PixelFilterKind::Tent: return 1.0f;
        case PixelFilterKind::Gaussian: return kGaussianRadius;
        case PixelFilterKind::BlackmanHarris: return kBlackmanHarrisRadius;
    }
    return 0.5f;
}

}  // namespace

bool parsePixelFilterKind(std::string_view name, PixelFilterKind& kind) {
    if (name == "box") kind = PixelFilterKind::Box;
    else if (name == "tent") kind = PixelFilterKind::Tent;
    else if (name == "gaussian") kind = PixelFilterKind::Gaussian;
    else if (name == "blackman-harris") kind = PixelFilterKind::BlackmanHarris;
    else return false;
    return true;
}

const char* pixelFilterName(PixelFilterKind kind) {
    switch (kind) {
        case PixelFilterKind::Box: return "box";
        case PixelFilterKind::Tent: return "tent";
        case PixelFilterKind::Gaussian: return "gaussian";
        case PixelFilterKind::BlackmanHarris: return "blackman-harris";
    }
    return "";
}

PixelFilter::PixelFilter(PixelFilterKind kind) : kind_(kind), radius_(filterRadius(kind)) {
    // The integral of |x|'s profile over [0, radius], bin by bin (midpoint rule), normalised.
    const float width = radius_ / kFilterTableSize;
    double sum = 0.0;
    for (int i = 0; i < kFilterTableSize; ++i) {
        sum += std::max(0.0f, evaluate((static_cast<float>(i) + 0.5f) * width));
        cdf_[static_cast<std::size_t>(i) + 1] = static_cast<float>(sum);
    }
    for (float& c : cdf_) c = static_cast<float>(c / sum);
    cdf_.back() = 1.0f;
}

float PixelFilter::evaluate(float x) const {
    const float a = std::fabs(x);
    if (a > radius_) return 0.0f;
    switch (kind_) {
        case PixelFilterKind::Box: return 1.0f;
        case PixelFilterKind::Tent: return 1.0f - a;
        case PixelFilterKind::Gaussian: return std::exp(-a * a / (2.0f * kGaussianSigma * kGaussianSigma));
        case PixelFilterKind::BlackmanHarris: {
            // The window's phase runs 0 .. 2 pi across [-radius, radius], peaking (1) at the centre.
            const float phase = 2.0f * kPi * (x / (2.0f * radius_) + 0.5f);
            return 0.35875f - 0.48829f * std::cos(phase) + 0.14128f * std::cos(2.0f * phase) -
                   0.01168f * std::cos(3.0f * phase);
        }
    }
    return 0.0f;
}

float PixelFilter::sample1D(float u) const {
    if (kind_ == PixelFilterKind::Box) return u - 0.5f;
    // u below 1/2 maps to the negative half, mirrored, so the map stays monotone in u.
    const bool negative = u < 0.5f;
    const float v = negative ? 1.0f - 2.0f * u : 2.0f * u - 1.0f;
    const auto upper = std::upper_bound(cdf_.begin() + 1, cdf_.end(), v);
    const auto bin = std::min<std::ptrdiff_t>(upper - cdf_.begin() - 1, kFilterTableSize - 1);
    const float lo = cdf_[static_cast<std::size_t>(bin)], hi = cdf_[static_cast<std::size_t>(bin) + 1];
    const float within = hi > lo ? std::clamp((v - lo) / (hi - lo), 0.0f, 1.0f) : 0.5f;
    const float x = (static_cast<float>(bin) + within) * (radius_ / kFilterTableSize);
    return negative ? -x : x;
}

float PixelFilter::density(float x) const {
    const float a = std::fabs(x);
    if (kind_ == PixelFilterKind::Box) return a <= 0.5f ? 1.0f : 0.0f;
    if (a >= radius_) return 0.0f;
    // sample1D is linear within each bin: uniform there, with the bin's share of |x|'s mass,
    // split evenly between the two signs.
    const float width = radius_ / kFilterTableSize;
    const auto bin = static_cast<std::size_t>(std::min(static_cast<int>(a / width), kFilterTableSize - 1));
    return 0.5f * (cdf_[bin + 1] - cdf_[bin]) / width;
}

Vec2 PixelFilter::sample(Vec2 u) const { return {sample1D(u.x), sample1D(u.y)}; }

}  // namespace lightpath
