#pragma once
// The random numbers of one pixel sample, drawn in a fixed order of dimensions: deterministic per
// (pixel, sample index, seed), so images do not depend on threads or tile order.
#include <cstdint>

#include "math/random.h"
#include "math/types.h"

namespace lightpath {

class Sampler {
public:
    Sampler(int x, int y, int sampleIndex, std::uint64_t seed) : rng_(pixelSampleRng(x, y, sampleIndex, seed)) {}

    float next1D() { return rng_.nextFloat(); }
    Vec2 next2D() {
        const float u = rng_.nextFloat();
        return {u, rng_.nextFloat()};
    }

private:
    Pcg32 rng_;
};

}  // namespace lightpath
