#pragma once
// Deterministic per-pixel random numbers: a PCG32 generator (O'Neill 2014) seeded by hashing the
// pixel, the sample index and the render seed, so a pixel's samples never depend on which thread
// renders it or in what order.
#include <cstdint>

namespace lightpath {

// SplitMix64's finaliser (Steele et al. 2014): a bijective 64-bit mix.
inline std::uint64_t mixBits(std::uint64_t v) {
    v ^= v >> 31;
    v *= 0x7fb5d329728ea185ull;
    v ^= v >> 27;
    v *= 0x81dadef4bc2dd44dull;
    v ^= v >> 33;
    return v;
}

class Pcg32 {
public:
    Pcg32(std::uint64_t seed, std::uint64_t stream) : increment_((stream << 1u) | 1u) {
        nextUint();
        state_ += seed;
        nextUint();
    }

    // A generator that is never drawn from (a member its owner only sometimes needs): no seeding.
    static Pcg32 unseeded() { return Pcg32(); }

    std::uint32_t nextUint() {
        const std::uint64_t old = state_;
        state_ = old * 6364136223846793005ull + increment_;
        const auto xorShifted = static_cast<std::uint32_t>(((old >> 18u) ^ old) >> 27u);
        const auto rotation = static_cast<std::uint32_t>(old >> 59u);
        return (xorShifted >> rotation) | (xorShifted << ((~rotation + 1u) & 31u));
    }

    // Uniform in [0, 1): the top 24 bits, exactly representable in float.
    float nextFloat() { return static_cast<float>(nextUint() >> 8) * 0x1p-24f; }

private:
    Pcg32() : increment_(1u) {}

    std::uint64_t state_ = 0;
    std::uint64_t increment_;
};

inline Pcg32 pixelSampleRng(int x, int y, int sample, std::uint64_t seed) {
    const std::uint64_t pixel = (static_cast<std::uint64_t>(static_cast<std::uint32_t>(y)) << 32) |
                                static_cast<std::uint32_t>(x);
    return Pcg32(mixBits(pixel ^ mixBits(seed)), mixBits(static_cast<std::uint64_t>(sample)));
}

}  // namespace lightpath
