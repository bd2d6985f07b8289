#pragma once
#include <cstdint>
#include <limits>

#include "math/types.h"

namespace lightpath {

inline constexpr std::uint32_t kNoPrimitive = std::numeric_limits<std::uint32_t>::max();

// r(t) = origin + t * direction for t in (tMin, tMax). Directions are unit length.
struct Ray {
    Vec3 origin{0.0f};
    Vec3 direction{0.0f, 0.0f, 1.0f};
    float tMin = 0.0f;
    float tMax = std::numeric_limits<float>::infinity();
    // A primitive this ray never hits: the lecture's "treat your own primitive differently".
    std::uint32_t ignoredPrimitive = kNoPrimitive;

    Vec3 at(float t) const { return origin + t * direction; }
};

}  // namespace lightpath
