#include "film/splat_film.h"

#include <algorithm>
#include <cmath>

namespace lightpath {
namespace {

// GCC and clang's 128-bit integer (__extension__: not ISO C++, so -Wpedantic would warn).
__extension__ typedef unsigned __int128 Wide;

// value in units of 2^-fractionBits, rounded to the nearest, as a two's-complement 128-bit
// integer; beyond +-2^126 units it saturates rather than wrapping.
Wide toUnits(float value, int fractionBits) {
    constexpr double kLimit = 0x1p126;
    const double units = std::clamp(std::nearbyint(std::ldexp(double(value), fractionBits)), -kLimit, kLimit);
    const double magnitude = std::fabs(units);
    const Wide wide = static_cast<Wide>(magnitude);
    return units < 0.0 ? Wide{0} - wide : wide;
}

double fromUnits(Wide sum, int fractionBits) {
    const bool negative = (sum >> 127) != 0;
    const Wide magnitude = negative ? Wide{0} - sum : sum;
    // Both halves convert exactly to double up to its precision; their sum is rounded once.
    const double value = std::ldexp(double(std::uint64_t(magnitude >> 64)), 64) + double(std::uint64_t(magnitude));
    return std::ldexp(negative ? -value : value, -fractionBits);
}

}  // namespace

SplatFilm::SplatFilm(int width, int height, std::size_t layers)
    : width_(width), height_(height), layers_(layers),
      sums_(std::make_unique<Sum[]>(valueCount(width, height, layers))) {}

void SplatFilm::add(int x, int y, std::size_t layer, const Rgb& value) {
    const std::size_t i = index(x, y, layer);
    for (int c = 0; c < 3; ++c) {
        if (value[c] == 0.0f) continue;
        const Wide units = toUnits(value[c], kFractionBits);
        Sum& sum = sums_[i + c];
        const std::uint64_t low = std::uint64_t(units), high = std::uint64_t(units >> 64);
        // The carry out of the low word follows from the low word's own value before this add,
        // whatever other threads add in between, so the 128-bit total is exact.
        const std::uint64_t before = sum.low.fetch_add(low, std::memory_order_relaxed);
        const std::uint64_t carry = before + low < before ? 1 : 0;
        if (high + carry != 0) sum.high.fetch_add(high + carry, std::memory_order_relaxed);
    }
}

Rgb SplatFilm::at(int x, int y, std::size_t layer) const {
    const std::size_t i = index(x, y, layer);
    Rgb value;
    for (int c = 0; c < 3; ++c) {
        const Sum& sum = sums_[i + c];
        const Wide total = (Wide(sum.high.load(std::memory_order_relaxed)) << 64) | sum.low.load(std::memory_order_relaxed);
        value[c] = static_cast<float>(fromUnits(total, kFractionBits));
    }
    return value;
}

}  // namespace lightpath
