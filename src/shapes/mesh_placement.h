#pragma once
// scale, then rotate_y, then translate: how a scene places a mesh file ([[meshes]], [[gltf]]) as
// the file describes it, resized about its own origin, turned about the vertical axis and moved.
#include <cmath>

#include "math/types.h"
#include "schema/parameter_values.h"

namespace lightpath {

struct MeshPlacement {
    Vec3 scale{1.0f};
    float rotateY = 0.0f;  // radians
    Vec3 translate{0.0f};

    Vec3 point(Vec3 p) const {
        p *= scale;
        const float c = std::cos(rotateY), s = std::sin(rotateY);
        return Vec3(c * p.x + s * p.z, p.y, -s * p.x + c * p.z) + translate;
    }
    // Normals take the inverse transpose: divide by the scale, rotate like points.
    Vec3 normal(Vec3 n) const {
        if (n == Vec3(0.0f)) return n;
        n /= scale;
        const float c = std::cos(rotateY), s = std::sin(rotateY);
        return glm::normalize(Vec3(c * n.x + s * n.z, n.y, -s * n.x + c * n.z));
    }
    // A unit direction (a light's, a camera's) as the placed points see it: scaled and rotated.
    Vec3 direction(Vec3 d) const {
        d *= scale;
        const float c = std::cos(rotateY), s = std::sin(rotateY);
        return glm::normalize(Vec3(c * d.x + s * d.z, d.y, -s * d.x + c * d.z));
    }
};

inline MeshPlacement placementOf(const ParameterValues& values) {
    return {values.vec3("scale"), glm::radians(values.number("rotate_y")), values.vec3("translate")};
}

}  // namespace lightpath
