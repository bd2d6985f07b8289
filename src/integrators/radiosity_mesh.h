#pragma once
// Radiosity's patches (Cohen and Wallace 1993, ch. 8): every surface of the scene split into small
// elements of about one patch size. Triangles are subdivided uniformly into n^2 sub-triangles
// (n = ceil(longest edge / size)); spheres into equal-area cells of constant cos(theta) and phi
// bands (Archimedes: bands of equal height have equal area); infinite planes are first clipped to
// a rectangle over the scene's bounds; registered kinds (geometry/shape.h) are first tessellated.
// Each patch has two sides, each its own unknown.
//
// The mesh also answers the display's question: which patch, and which of its vertices with what
// weights, lies under a hit point (Gouraud interpolation of vertex radiosities).
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "accel/scene_geometry.h"
#include "geometry/surface_hit.h"
#include "math/types.h"
#include "scene/scene.h"

namespace lightpath {

struct RadiosityPatch {
    ShapeKind shape = ShapeKind::Triangle;  // the primitive it lies on
    std::uint32_t primitive = 0;            // scene-wide id of that primitive
    std::uint32_t object = 0;
    // Triangles (and clipped planes): the corners, unit normal of the source primitive's winding.
    Vec3 a{0.0f}, b{0.0f}, c{0.0f}, normal{0.0f};
    // Sphere cells: z = cos(theta) in [z1, z0] (z0 > z1), phi in [phi0, phi1), in the sphere's frame.
    float z0 = 0.0f, z1 = 0.0f, phi0 = 0.0f, phi1 = 0.0f;
    float area = 0.0f;
    // Vertices for Gouraud interpolation: a, b, c for triangles; (z0,phi0), (z0,phi1), (z1,phi0),
    // (z1,phi1) for sphere cells.
    std::array<std::uint32_t, 4> vertices{};
    int vertexCount = 3;
};

// A point on a patch: where it is and the patch's outward (front-side) normal there.
struct PatchPoint {
    Vec3 point{0.0f};
    Vec3 normal{0.0f};
};

// What lies under a hit point.
struct PatchLookup {
    std::uint32_t patch = 0;
    std::array<float, 4> weights{};  // of the patch's vertices, summing to 1
};

class RadiosityMesh {
public:
    // Splits every surface into patches of about `patchSize` scene units.
    RadiosityMesh(const Scene& scene, const SceneGeometry& geometry, float patchSize);

    // How many patches `patchSize` would make (without building them): for a patch budget.
    static std::size_t countPatches(const Scene& scene, const SceneGeometry& geometry, float patchSize);
    // The patch size whose mesh has at most `budget` patches and is finest among such sizes.
    static float patchSizeForBudget(const Scene& scene, const SceneGeometry& geometry, std::size_t budget);

    const std::vector<RadiosityPatch>& patches() const { return patches_; }
    std::size_t vertexCount() const { return vertexCount_; }
    float patchSize() const { return patchSize_; }

    // A point uniformly by area on patch `patch`, from u in [0,1)^2.
    PatchPoint samplePoint(std::uint32_t patch, Vec2 u) const;
    // The patch under `hit`, or nullopt (a clipped plane's hit outside its rectangle).
    std::optional<PatchLookup> lookup(const SurfaceHit& hit) const;

private:
    // One primitive's share of the patches: a triangle's n x n grid or a sphere's bands x sectors.
    struct Source {
        ShapeKind shape;
        std::uint32_t primitive;
        std::uint32_t firstPatch;
        std::uint32_t n = 0;                 // triangle: subdivisions per edge
        std::uint32_t bands = 0, sectors = 0;  // sphere
        Vec3 a{0.0f}, b{0.0f}, c{0.0f};      // triangle corners
    };

    struct VertexWelder;
    void addTriangle(ShapeKind shape, std::uint32_t primitive, std::uint32_t object, const Vec3& a, const Vec3& b,
                     const Vec3& c, VertexWelder& welder);
    void addSphere(std::uint32_t sphereIndex);
    // strict: nullopt for a point outside the source's triangle (when its primitive has several).
    std::optional<PatchLookup> lookupTriangle(const Source& source, const Vec3& point, bool strict = true) const;
    PatchLookup lookupSphere(const Source& source, const Vec3& point) const;

    const SceneGeometry& geometry_;
    float patchSize_;
    std::vector<RadiosityPatch> patches_;
    std::vector<Source> sources_;
    // sources_[sourceStart_[id] .. sourceStart_[id + 1]) lie on scene-wide primitive id.
    std::vector<std::uint32_t> sourceStart_;
    std::size_t vertexCount_ = 0;
};

// How a sphere is cut into cells: `bands` bands of equal height (so of equal area, Archimedes),
// each of `sectors` sectors, about one patch size wide at the equator. Cell (ring, sector) spans
// z = cos(theta) from 1 - 2 ring/bands down to 1 - 2 (ring+1)/bands and phi from
// 2 pi sector/sectors to 2 pi (sector+1)/sectors, in the frame of the world's axes.
struct SphereCells {
    std::uint32_t bands = 0, sectors = 0;
};
SphereCells sphereCells(float radius, float patchSize);
// The unit normal of a sphere at z = cos(theta) and azimuth phi (its point is centre + radius n).
Vec3 sphereDirection(float z, float phi);

// The rectangle an infinite plane is clipped to: two triangles over the scene's bounds (every
// sphere, triangle, point light and the eye), grown by half their diagonal on every side.
std::array<Triangle, 2> clipPlane(const Scene& scene, const Plane& plane);

}  // namespace lightpath
