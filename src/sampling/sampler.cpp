#include "sampling/sampler.h"

#include <cmath>

#include "util/hot_path.h"

namespace lightpath {
namespace {

float toUnitFloat(std::uint32_t bits) { return static_cast<float>(bits >> 8) * 0x1p-24f; }

// Inline, with the bytes swapped in one instruction: seven reversals per vertex sampler's
// next1D and next2D (callgrind: a call of 11 instructions each before).
[[gnu::always_inline]] inline std::uint32_t reverseBits(std::uint32_t x) {
    x = __builtin_bswap32(x);
    x = ((x & 0x0f0f0f0fu) << 4) | ((x & 0xf0f0f0f0u) >> 4);
    x = ((x & 0x33333333u) << 2) | ((x & 0xccccccccu) >> 2);
    return ((x & 0x55555555u) << 1) | ((x & 0xaaaaaaaau) >> 1);
}

// reverseBits of a and b at once, in the two halves of one 64-bit word: the same steps, each
// applied to both (next2D's two dimensions): one byte swap and three steps for the pair.
[[gnu::always_inline]] inline void reverseBitsPair(std::uint32_t& a, std::uint32_t& b) {
    std::uint64_t x = __builtin_bswap64((std::uint64_t{a} << 32) | b);  // bytes of a now low, of b high
    x = ((x & 0x0f0f0f0f0f0f0f0full) << 4) | ((x & 0xf0f0f0f0f0f0f0f0ull) >> 4);
    x = ((x & 0x3333333333333333ull) << 2) | ((x & 0xccccccccccccccccull) >> 2);
    x = ((x & 0x5555555555555555ull) << 1) | ((x & 0xaaaaaaaaaaaaaaaaull) >> 1);
    a = static_cast<std::uint32_t>(x);
    b = static_cast<std::uint32_t>(x >> 32);
}

// A hash in which each bit depends only on the bits below it (Laine and Karras 2011; Burley 2020,
// listing 2); applied to reversed bits it permutes each binary digit given the digits before it:
// Owen's nested uniform scrambling (Burley 2020, sec. 3). Its result is still reversed.
[[gnu::always_inline]] inline std::uint32_t laineKarras(std::uint32_t reversed, std::uint32_t seed) {
    std::uint32_t x = reversed + seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return x;
}

// Owen's scrambling of a value given with its bits reversed; the result in the usual order.
[[gnu::always_inline]] inline std::uint32_t owenScrambleReversed(std::uint32_t reversed, std::uint32_t seed) {
    return reverseBits(laineKarras(reversed, seed));
}

// Sobol's first two dimensions with their bits reversed (digit m at bit m), as the scrambling
// takes them. The first is van der Corput's: the index itself.
std::uint32_t sobolDimension0Reversed(std::uint32_t index) { return index; }
std::uint32_t sobolDimension1Reversed(std::uint32_t index) {
    // Output digit m (weight 2^-(m+1)) is the sum mod 2 of index bits k with C(k, m) odd, i.e.
    // (Lucas) with k's bits a superset of m's: a superset-sum transform over the five bits of the
    // digit position, one shift-and-mask step per bit, instead of a loop over the index's bits.
    std::uint32_t digits = index;
    digits ^= (digits >> 1) & 0x55555555u;
    digits ^= (digits >> 2) & 0x33333333u;
    digits ^= (digits >> 4) & 0x0f0f0f0fu;
    digits ^= (digits >> 8) & 0x00ff00ffu;
    digits ^= (digits >> 16) & 0x0000ffffu;
    return digits;
}

// A bijection of [0, count) chosen by `seed`: xor-shift-multiply rounds on the smallest
// power-of-two range holding count, walking the cycle until the value falls inside.
std::uint32_t permute(std::uint32_t i, std::uint32_t count, std::uint64_t seed) {
    std::uint32_t mask = count - 1;
    for (int s = 1; s < 32; s <<= 1) mask |= mask >> s;
    const auto key = static_cast<std::uint32_t>(seed), key2 = static_cast<std::uint32_t>(seed >> 32);
    do {
        i ^= key & mask;
        i = (i * 0x2c1b3c6du) & mask;  // odd multipliers are bijections modulo a power of two
        i ^= i >> 3;
        i ^= key2 & mask;
        i = (i * 0x297a2d39u) & mask;
        i ^= i >> 5;
        i = (i * 0x3b9ac9fbu) & mask;
        i ^= i >> 2;
    } while (i >= count);
    return i;
}

// The side of a square grid of `count` cells, or 0 when count is not a square.
std::uint32_t squareSide(std::uint32_t count) {
    const auto side = static_cast<std::uint32_t>(std::lround(std::sqrt(static_cast<double>(count))));
    return side * side == count ? side : 0;
}

}  // namespace

std::uint32_t sobolDimension1(std::uint32_t index) { return reverseBits(sobolDimension1Reversed(index)); }

bool parseSamplerKind(std::string_view name, SamplerKind& kind) {
    if (name == "independent") kind = SamplerKind::Independent;
    else if (name == "stratified") kind = SamplerKind::Stratified;
    else if (name == "sobol") kind = SamplerKind::Sobol;
    else return false;
    return true;
}

const char* samplerName(SamplerKind kind) {
    switch (kind) {
        case SamplerKind::Independent: return "independent";
        case SamplerKind::Stratified: return "stratified";
        case SamplerKind::Sobol: return "sobol";
    }
    return "";
}

LIGHTPATH_HOT_PATH
Sampler::Sampler(SamplerKind kind, std::uint64_t seed, int sampleIndex, int samplesPerPixel)
    : kind_(kind), seed_(seed), index_(static_cast<std::uint32_t>(sampleIndex)),
      count_(static_cast<std::uint32_t>(samplesPerPixel)),
      gridSide_(kind == SamplerKind::Stratified ? squareSide(count_) : 0),
      reversedIndex_(kind == SamplerKind::Sobol ? reverseBits(index_) : 0),
      rng_(usesRng() ? Pcg32(mixBits(seed), mixBits(seed ^ static_cast<std::uint64_t>(sampleIndex))) : Pcg32::unseeded()) {}

LIGHTPATH_HOT_PATH
Sampler Sampler::forPixel(SamplerKind kind, int x, int y, int sampleIndex, int samplesPerPixel, std::uint64_t seed) {
    const std::uint64_t pixel = (static_cast<std::uint64_t>(static_cast<std::uint32_t>(y)) << 32) | static_cast<std::uint32_t>(x);
    return Sampler(kind, mixBits(pixel ^ mixBits(seed)), sampleIndex, samplesPerPixel);
}

LIGHTPATH_HOT_PATH
float Sampler::next1D() {
    const std::uint64_t seed = dimensionSeed();
    switch (kind_) {
        case SamplerKind::Independent: break;
        case SamplerKind::Stratified:
            return (static_cast<float>(permute(index_, count_, seed)) + rng_.nextFloat()) / static_cast<float>(count_);
        case SamplerKind::Sobol: {
            const std::uint32_t shuffled = owenScrambleReversed(reversedIndex_, static_cast<std::uint32_t>(seed));
            return toUnitFloat(owenScrambleReversed(sobolDimension0Reversed(shuffled), static_cast<std::uint32_t>(seed >> 32)));
        }
    }
    return rng_.nextFloat();
}

LIGHTPATH_HOT_PATH
void Sampler::skip2D() {
    ++dimension_;
    if (!usesRng()) return;
    rng_.nextUint();  // next2D draws two numbers for either kind that uses the generator
    rng_.nextUint();
}

LIGHTPATH_HOT_PATH
void Sampler::skip1D() {
    ++dimension_;
    if (usesRng()) rng_.nextUint();  // next1D draws one number for either kind that uses the generator
}

LIGHTPATH_HOT_PATH
Vec2 Sampler::next2D() {
    const std::uint64_t seed = dimensionSeed();
    switch (kind_) {
        case SamplerKind::Independent: break;
        case SamplerKind::Stratified: {
            if (const std::uint32_t side = gridSide_; side != 0) {
                const std::uint32_t cell = permute(index_, count_, seed);
                const float u = rng_.nextFloat(), v = rng_.nextFloat();
                return {(static_cast<float>(cell % side) + u) / static_cast<float>(side),
                        (static_cast<float>(cell / side) + v) / static_cast<float>(side)};
            }
            const float u = rng_.nextFloat(), v = rng_.nextFloat();
            return {(static_cast<float>(permute(index_, count_, seed)) + u) / static_cast<float>(count_),
                    (static_cast<float>(permute(index_, count_, mixBits(seed))) + v) / static_cast<float>(count_)};
        }
        case SamplerKind::Sobol: {
            const auto scrambleSeed = static_cast<std::uint32_t>(seed >> 32);
            const std::uint32_t shuffled = owenScrambleReversed(reversedIndex_, static_cast<std::uint32_t>(seed));
            std::uint32_t u = laineKarras(sobolDimension0Reversed(shuffled), scrambleSeed);
            std::uint32_t v = laineKarras(sobolDimension1Reversed(shuffled), scrambleSeed ^ 0x5bd1e995u);
            reverseBitsPair(u, v);  // owenScrambleReversed's last step, for both
            return {toUnitFloat(u), toUnitFloat(v)};
        }
    }
    const float u = rng_.nextFloat();
    return {u, rng_.nextFloat()};
}

}  // namespace lightpath
