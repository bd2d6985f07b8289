#pragma once
// Where a pinhole camera's pixel looks, written out here from the model (vertical field of view
// fixed, horizontal from the aspect ratio), not read from src/scene/camera.cpp: the reference the
// closed-form render tests trace by hand.
#include <cmath>

#include <glm/glm.hpp>

#include "scene/camera.h"

namespace lightpath::test {

// The direction through the centre of pixel (i, j), in double precision.
inline glm::dvec3 pixelDirection(const CameraDescription& c, int i, int j) {
    const glm::dvec3 forward = glm::normalize(glm::dvec3(c.lookAt) - glm::dvec3(c.eye));
    const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(c.up)));
    const glm::dvec3 up = glm::cross(right, forward);
    const double halfHeight = std::tan(glm::radians(double(c.verticalFovDegrees)) / 2.0);
    const double aspect = double(c.width) / double(c.height);
    const double u = (2.0 * (i + 0.5) / c.width - 1.0) * aspect * halfHeight;
    const double v = (1.0 - 2.0 * (j + 0.5) / c.height) * halfHeight;
    return glm::normalize(forward + u * right + v * up);
}

}  // namespace lightpath::test
