#pragma once
#include <string>

#include "math/types.h"

namespace lightpath {

// A point light with the lecture's attenuation 1 / (c0 + c1 d + c2 d^2).
struct PointLight {
    std::string name;
    Vec3 position{0.0f};
    Rgb intensity{1.0f};
    Vec3 attenuation{1.0f, 0.0f, 0.0f};  // (c0, c1, c2); the default is no attenuation

    float attenuationAt(float distance) const {
        return 1.0f / (attenuation.x + distance * (attenuation.y + distance * attenuation.z));
    }
};

}  // namespace lightpath
