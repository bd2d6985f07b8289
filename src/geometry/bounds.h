#pragma once
// An axis-aligned box: what the BVH builds over and what a shape reports of itself (shape.h).
#include <limits>

#include "math/types.h"

namespace lightpath {

struct Bounds {
    Vec3 lo{std::numeric_limits<float>::infinity()};
    Vec3 hi{-std::numeric_limits<float>::infinity()};

    void grow(const Vec3& p) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    void grow(const Bounds& b) {
        lo = glm::min(lo, b.lo);
        hi = glm::max(hi, b.hi);
    }
    bool empty() const { return lo.x > hi.x; }
    Vec3 centroid() const { return 0.5f * (lo + hi); }
    float halfArea() const {
        if (empty()) return 0.0f;
        const Vec3 d = hi - lo;
        return d.x * d.y + d.y * d.z + d.z * d.x;
    }
};

}  // namespace lightpath
