// toSrgb8's table against IEC 61966-2-1's formula evaluated here in double precision.
#include <doctest/doctest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "io/image_writer.h"

namespace lightpath {
namespace {

// The standard's encoding, 0..255 before rounding.
double referenceCode(double linear) {
    const double v = std::clamp(linear, 0.0, 1.0);
    return 255.0 * (v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055);
}

TEST_CASE("toSrgb8 rounds the sRGB encoding to nearest, across every octave of [0, 1]") {
    int compared = 0;
    // Every 61st float from the smallest positive to 1: all octaves, every bucket of the table.
    for (std::uint32_t bits = 1; bits <= std::bit_cast<std::uint32_t>(1.0f); bits += 61) {
        const float v = std::bit_cast<float>(bits);
        const double exact = referenceCode(v);
        // Within a hair of a rounding boundary double and the table may round either way.
        if (std::abs(exact - std::floor(exact) - 0.5) < 1e-9) continue;
        const int expected = static_cast<int>(std::lround(exact));
        if (toSrgb8(v) != expected) {
            FAIL_CHECK("toSrgb8(" << v << ") = " << int{toSrgb8(v)} << ", expected " << expected);
            break;
        }
        ++compared;
    }
    CHECK(compared > 15'000'000);
}

TEST_CASE("toSrgb8 at the ends and for values a film should not hold") {
    CHECK(toSrgb8(0.0f) == 0);
    CHECK(toSrgb8(-0.0f) == 0);
    CHECK(toSrgb8(-3.0f) == 0);
    CHECK(toSrgb8(1.0f) == 255);
    CHECK(toSrgb8(7.5f) == 255);
    CHECK(toSrgb8(std::numeric_limits<float>::max()) == 255);
    CHECK(toSrgb8(std::numeric_limits<float>::quiet_NaN()) == 0);
    CHECK(toSrgb8(std::numeric_limits<float>::infinity()) == 0);
    CHECK(toSrgb8(-std::numeric_limits<float>::infinity()) == 0);
    // Hand-computed: 0.5 encodes to 187.516 of 255; 0.0015654 is on the linear part, 5.157 of 255;
    // 0.21586 is what 128 of 255 decodes to.
    CHECK(toSrgb8(0.5f) == 188);
    CHECK(toSrgb8(0.0015654f) == 5);
    CHECK(toSrgb8(0.2158605f) == 128);
}

}  // namespace
}  // namespace lightpath
