#pragma once
#include <cstdint>

#include "math/types.h"

namespace lightpath {

struct ShapeOps;

// The closest intersection of a ray with the scene.
struct SurfaceHit {
    float t = 0.0f;
    Vec3 point{0.0f};
    Vec3 normal{0.0f};         // unit geometric normal as the shape defines it (outward for spheres)
    Vec3 shadingNormal{0.0f};  // unit normal for shading: interpolated vertex normals, else `normal`
    std::uint32_t object = 0;
    const ShapeOps* shape = nullptr;  // the kind's table (geometry/shape.h); nullptr for a triangle
    std::uint32_t primitive = 0;  // scene-wide primitive id (SceneGeometry's codec)
};

}  // namespace lightpath
