#pragma once
#include <cstdint>

#include "math/types.h"

namespace lightpath {

// Registered: a kind of the shape table (geometry/shape.h), which its ShapeOps describe.
enum class ShapeKind : std::uint8_t { Sphere, Plane, Triangle, Registered };

// The closest intersection of a ray with the scene.
struct SurfaceHit {
    float t = 0.0f;
    Vec3 point{0.0f};
    Vec3 normal{0.0f};         // unit geometric normal as the shape defines it (outward for spheres)
    Vec3 shadingNormal{0.0f};  // unit normal for shading: interpolated vertex normals, else `normal`
    std::uint32_t object = 0;
    ShapeKind shape = ShapeKind::Sphere;
    std::uint32_t primitive = 0;  // scene-wide primitive id (SceneGeometry's codec)
};

}  // namespace lightpath
