#pragma once
// The primitives of the lectures. Each carries the index of the scene object it belongs to;
// geometry knows nothing of materials or light paths.
#include <cstdint>

#include "math/types.h"

namespace lightpath {

struct Sphere {
    Vec3 center{0.0f};
    float radius = 1.0f;
    std::uint32_t object = 0;
};

// An infinite plane through `point` with unit `normal`.
struct Plane {
    Vec3 point{0.0f};
    Vec3 normal{0.0f, 1.0f, 0.0f};
    std::uint32_t object = 0;
};

struct Triangle {
    Vec3 a{0.0f}, b{0.0f}, c{0.0f};
    std::uint32_t object = 0;
};

// The unit normals at a triangle's corners (a mesh's vertex normals), for smooth shading; all
// zero for a flat triangle.
struct TriangleNormals {
    Vec3 a{0.0f}, b{0.0f}, c{0.0f};
};

}  // namespace lightpath
