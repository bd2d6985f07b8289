#pragma once
// The primitives of the lectures. Each carries the index of the scene object it belongs to;
// geometry knows nothing of materials or light paths.
#include <cstdint>
#include <limits>
#include <numbers>

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

// The texture coordinates at a triangle's corners (a mesh's `vt`); `given` false: the triangle
// has none and is parametrised by its plane (SceneGeometry::surfaceParameters).
struct TriangleUvs {
    Vec2 a{0.0f}, b{0.0f}, c{0.0f};
    bool given = false;
};

// The tangents at a triangle's corners as a mesh gives them (glTF's TANGENT, 3.7.2.1): xyz the
// unit tangent, w the bitangent's sign (bitangent = w cross(normal, tangent)); all zero: none.
struct TriangleTangents {
    Vec4 a{0.0f}, b{0.0f}, c{0.0f};
};

// The colours at a triangle's corners (glTF's COLOR_0, linear RGB), which multiply its material's
// base colour, and their alphas (COLOR_0's fourth component), which multiply its alpha; white and
// 1 where a mesh has none.
struct TriangleColors {
    Rgb a{1.0f}, b{1.0f}, c{1.0f};
    Vec3 alpha{1.0f};  // at a, b, c
};

// A surface point's texture coordinates and the surface's derivatives along them (pbrt-v4's
// dpdu, dpdv): what turns a footprint on the surface into one in texture space.
struct SurfaceParameters {
    Vec2 uv{0.0f};
    Vec3 dpdu{0.0f};
    Vec3 dpdv{0.0f};
    // A mesh's tangent there (TriangleTangents interpolated), the normal map's frame in place of
    // dpdu and dpdv; zero where the mesh gives none.
    Vec4 tangent{0.0f};
};

// The smallest emitting area a light samples: below the smallest normal float, the density 1/A
// per unit area overflows (or has lost its digits), so such an emitter is only seen where a ray
// hits it. The scene loader warns about emitters below it; LightSet never samples them.
inline constexpr double kMinSampledEmitterArea = std::numeric_limits<float>::min();

// Surface areas in double: a float sphere's r^2 underflows below r = 1e-19, and a sliver
// triangle's cross product squared below edges of 1e-19 (its area would be lost, not small).
inline double surfaceArea(const Sphere& s) {
    const double r = s.radius;
    return 4.0 * std::numbers::pi * r * r;
}
inline double surfaceArea(const Triangle& t) {
    const glm::dvec3 e1 = glm::dvec3(t.b) - glm::dvec3(t.a), e2 = glm::dvec3(t.c) - glm::dvec3(t.a);
    return 0.5 * glm::length(glm::cross(e1, e2));
}

}  // namespace lightpath
