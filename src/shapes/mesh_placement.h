#pragma once
// scale, then rotate_y, then translate: how a scene places a mesh file ([[meshes]], [[gltf]]) as
// the file describes it, resized about its own origin, turned about the vertical axis and moved.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

#include "geometry/shapes.h"
#include "math/types.h"
#include "scene/scene_loader.h"
#include "schema/format.h"
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
    TriangleNormals normals(const TriangleNormals& n) const { return {normal(n.a), normal(n.b), normal(n.c)}; }
    // Tangents are directions along the surface: they turn as points do; the sign w stays.
    Vec4 tangent(const Vec4& t) const { return t == Vec4(0.0f) ? t : Vec4(direction(Vec3(t)), t.w); }
    TriangleTangents tangents(const TriangleTangents& t) const { return {tangent(t.a), tangent(t.b), tangent(t.c)}; }
};

inline MeshPlacement placementOf(const ParameterValues& values) {
    return {values.vec3("scale"), glm::radians(values.number("rotate_y")), values.vec3("translate")};
}

// Triangle `index` (from 0) of a mesh file, placed and given `object`. The limit of the file's own
// numbers holds for its vertices where they end up: beyond it, an error at the key `file`.
inline Triangle placeTriangle(const MeshPlacement& placement, const Triangle& t, std::uint32_t object,
                              const ParameterValues& values, const std::filesystem::path& file, std::size_t index) {
    const Triangle placed{placement.point(t.a), placement.point(t.b), placement.point(t.c), object};
    for (const Vec3& corner : {placed.a, placed.b, placed.c}) {
        if (!(glm::all(glm::lessThanEqual(glm::abs(corner), Vec3(kMaxMagnitude))))) {
            values.fail("file", file.string() + ": triangle " + std::to_string(index + 1) + " has a corner at " +
                                    formatVec3(corner) + " once placed; expected coordinates " +
                                    std::string(kMagnitudeRange));
        }
    }
    return placed;
}

}  // namespace lightpath
