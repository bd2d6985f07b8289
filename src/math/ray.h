#pragma once
#include <limits>

#include "math/types.h"

namespace lightpath {

// r(t) = origin + t * direction for t in (0, tMax). Directions are unit length.
struct Ray {
    Vec3 origin{0.0f};
    Vec3 direction{0.0f, 0.0f, 1.0f};
    float tMax = std::numeric_limits<float>::infinity();

    Vec3 at(float t) const { return origin + t * direction; }
};

}  // namespace lightpath
