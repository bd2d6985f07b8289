#pragma once
// The random numbers of one pixel sample, drawn in a fixed order of dimensions: deterministic per
// (pixel, sample index, seed), so images do not depend on threads or tile order.
#include <cstdint>

#include "math/random.h"
#include "math/types.h"

namespace lightpath {

class Sampler {
public:
    Sampler(int x, int y, int sampleIndex, std::uint64_t seed)
        : rng_(pixelSampleRng(x, y, sampleIndex, seed)), key_(mixBits(rng_.nextUint() ^ (std::uint64_t{rng_.nextUint()} << 32))) {}

    // An independent stream for one vertex of a branching path, keyed by the path that leads to
    // it: its numbers do not depend on which other branches were traced (or skipped) before it.
    Pcg32 streamFor(std::uint64_t pathKey) const { return Pcg32(mixBits(key_ ^ pathKey), pathKey); }

    float next1D() { return rng_.nextFloat(); }
    Vec2 next2D() {
        const float u = rng_.nextFloat();
        return {u, rng_.nextFloat()};
    }

private:
    Pcg32 rng_;
    std::uint64_t key_;
};

}  // namespace lightpath
