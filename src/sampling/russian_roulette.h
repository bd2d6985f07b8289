#pragma once
// Russian roulette on a walk's throughput, shared by the path tracer and both of bdpt's walks.
#include <algorithm>

#include "math/types.h"
#include "sampling/sampler.h"

namespace lightpath {

// Walks of fewer vertices than this are never cut.
inline constexpr int kRouletteVertices = 3;

// False to stop the walk; on going on, the throughput carries 1/q, which keeps the estimate
// unbiased (Arvo and Kirk 1990). q follows the throughput, so dim walks end early.
inline bool survivesRussianRoulette(Rgb& throughput, int vertices, Sampler& sampler) {
    if (vertices < kRouletteVertices) return true;
    const float q = std::min(0.95f, maxComponent(throughput));
    if (sampler.next1D() >= q) return false;
    throughput /= q;
    return true;
}

}  // namespace lightpath
