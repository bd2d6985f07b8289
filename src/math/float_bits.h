#pragma once
// The neighbouring floats of x by integer arithmetic on its bits: the same results as
// std::nextafter(x, +inf) and std::nextafter(x, -inf), without a call into libm. IEEE 754 orders
// floats of one sign like their bit patterns, so a step away from zero adds one to the pattern
// and a step towards zero subtracts one.
#include <bit>
#include <cstdint>
#include <limits>

namespace lightpath {

inline float nextFloatUp(float x) {
    if (!(x < std::numeric_limits<float>::infinity())) return x;  // +inf, NaN
    if (x == 0.0f) return std::numeric_limits<float>::denorm_min();  // from +0 and from -0
    const auto bits = std::bit_cast<std::uint32_t>(x);
    return std::bit_cast<float>(x > 0.0f ? bits + 1u : bits - 1u);
}

inline float nextFloatDown(float x) { return -nextFloatUp(-x); }  // negation is exact, the order mirrored

}  // namespace lightpath
