#pragma once
// A shape kind as a type (issue #30): what the accelerator, the lights, radiosity and the
// rasteriser ask of one primitive, answered by a table of functions the kind's own file defines
// (src/shapes/, e.g. shapes/disk.cpp). A primitive is a ShapeRecord: its kind's table and a few
// floats only that kind reads, so a new kind needs no new container anywhere. Spheres and planes
// are records of this table too (shapes/sphere.cpp, shapes/plane.cpp); only triangles keep their
// own array and fast paths (triangle packs, SIMD, Embree). A record's test is one indirect call
// (for spheres +0.11% instructions of a render, callgrind).
//
// Radiosity and the rasteriser read only this table, never a kind's name. What they ask:
// - radiosity's patches (integrators/radiosity_mesh.h): a kind's `patchGrid` cells if it has one
//   (the sphere's latitude-longitude cells), else, bounded, its `tessellate` triangles, or,
//   unbounded, its `tessellateRegion` over the scene's bounds (the plane's clipped rectangle);
//   an unbounded kind without one gets no patches (radiosity leaves it black).
// - the rasteriser's coverage (integrators/raster.h): the pixels of a bounded kind's bounding box,
//   every pixel of an unbounded one; each takes the kind's depth under the pixel centre, from
//   `depthAlong` if it has one (the plane's closed form), else from `intersect` along the pixel's
//   ray: ray casting's hit exactly.
#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

#include "geometry/bounds.h"
#include "geometry/numerics.h"
#include "geometry/shapes.h"
#include "geometry/surface_hit.h"
#include "math/ray.h"
#include "math/types.h"

namespace lightpath {

struct ShapeOps;

// One primitive of a registered kind: the numbers that define it, packed as its kind chooses.
struct ShapeRecord {
    static constexpr std::size_t kCapacity = 12;  // floats: a quad's corner and two edges, and room
    const ShapeOps* ops = nullptr;
    std::array<float, kCapacity> data{};
    std::uint32_t object = 0;
};

// A point uniform by area on the surface (density 1 / area) and the unit normal there.
struct AreaSample {
    Vec3 point{0.0f};
    Vec3 normal{0.0f};
};

// A point sampled by the solid angle a shape subtends from a receiver, and that density.
struct SolidAngleSample {
    Vec3 point{0.0f};
    Vec3 normal{0.0f};
    float pdf = 0.0f;  // per steradian; 0: no sample
};

// A kind's natural cells for radiosity (ShapeOps::patchGrid): `rows` x `columns` cells, cell
// (row, column) with the corners (row, column), (row, column + 1), (row + 1, column) and
// (row + 1, column + 1). Corners may be shared (a sphere's poles, its seam at phi = 2 pi): there
// are `corners` distinct ones, numbered 0 .. corners - 1.
struct PatchGrid {
    std::uint32_t rows = 0, columns = 0;
    std::uint32_t corners = 0;
};

// A point's cell in a PatchGrid and where in it: `fraction` in [0, 1]^2 from the corner (row,
// column) towards row + 1 (x) and column + 1 (y), the weights of bilinear (Gouraud) interpolation.
struct GridPoint {
    std::uint32_t row = 0, column = 0;
    Vec2 fraction{0.0f};
};

struct PatchGridOps {
    // The cells of about `patchSize` scene units across.
    PatchGrid (*cells)(const ShapeRecord&, float patchSize) = nullptr;
    // The number of corner (row, column), row in [0, rows], column in [0, columns].
    std::uint32_t (*corner)(const PatchGrid&, std::uint32_t row, std::uint32_t column) = nullptr;
    // A cell's area; the cells' areas sum to ShapeOps::area.
    float (*cellArea)(const ShapeRecord&, const PatchGrid&, std::uint32_t row, std::uint32_t column) = nullptr;
    // A point uniformly by area in a cell from u in [0, 1)^2, and the unit (outward) normal there.
    AreaSample (*sampleCell)(const ShapeRecord&, const PatchGrid&, std::uint32_t row, std::uint32_t column,
                             Vec2 u) = nullptr;
    // The cell a point on the surface lies in.
    GridPoint (*locate)(const ShapeRecord&, const PatchGrid&, const Vec3& point) = nullptr;
};

struct ShapeOps {
    std::string_view name;  // as the scene file names the kind ("disk")
    // Encloses a volume: it is seen, and emits, from both sides of every surface element like a
    // sphere; an open surface (disk, quad) emits on the side of its normal only.
    bool closed = false;
    // A box holding the shape (the accelerator pads it for the rounding of reported hits).
    Bounds (*bounds)(const ShapeRecord&) = nullptr;
    // t of the nearest hit in (tMin, ray.tMax), else kNoHit.
    float (*intersect)(const Ray& ray, const ShapeRecord&, float tMin, const NumericsOptions&) = nullptr;
    // Fills hit.normal and hit.shadingNormal (unit) at hit.point = ray.at(t), which it may snap
    // onto the surface.
    void (*describe)(const ShapeRecord&, SurfaceHit& hit) = nullptr;
    // Surface area in double (see shapes.h's surfaceArea).
    double (*area)(const ShapeRecord&) = nullptr;
    // A point uniformly by area from u in [0, 1)^2.
    AreaSample (*sampleArea)(const ShapeRecord&, Vec2 u) = nullptr;
    // Triangles with corners on the surface and edges of at most about `edgeLength`, wound so that
    // their normal is the surface's: radiosity's patches.
    void (*tessellate)(const ShapeRecord&, float edgeLength, std::vector<Triangle>& out) = nullptr;
    // False for a shape no box holds (a plane): the accelerator tests it apart, on every ray, and
    // its area is infinite, so it is never an area light's shape (seen only where a ray hits it).
    bool bounded = true;
    // Optional (nullptr: area lights sample the kind by area): a point sampled by the solid angle
    // the shape subtends from `receiver` (a sphere's visible cone, pbrt-v4 6.2.4). False where
    // this does not apply from `receiver` (e.g. inside the sphere): then sampling is by area.
    bool (*sampleSolidAngle)(const ShapeRecord&, const Vec3& receiver, Vec2 u, SolidAngleSample& out) = nullptr;
    // sampleSolidAngle's density at `receiver` in `pdf`; false exactly where sampleSolidAngle is.
    bool (*pdfSolidAngle)(const ShapeRecord&, const Vec3& receiver, float& pdf) = nullptr;
    // Optional, for radiosity (nullptr: its patches are the `tessellate` triangles): a kind with a
    // natural parametrisation cuts itself into cells (the sphere's latitude-longitude cells).
    const PatchGridOps* patchGrid = nullptr;
    // Optional, for an unbounded kind (nullptr: radiosity gives it no patches): triangles covering
    // the part of it over `region` (the scene's bounds), wound with its normal (the plane's
    // rectangle).
    void (*tessellateRegion)(const ShapeRecord&, const Bounds& region, std::vector<Triangle>& out) = nullptr;
    // Optional, for the rasteriser (nullptr: `intersect` along the pixel's unit ray): s with
    // eye + s direction the nearest point of the surface, for a direction of any length; not
    // positive or not finite where there is none (the plane's n.(p - eye) / n.direction).
    float (*depthAlong)(const ShapeRecord&, const Vec3& eye, const Vec3& direction) = nullptr;
    // Optional, for textures (nullptr: metres along the tangent frame of the hit's normal,
    // SceneGeometry::surfaceParameters): the kind's natural parametrisation at a point on it
    // (the sphere's longitude and latitude, the plane's frame from its point).
    SurfaceParameters (*parametrise)(const ShapeRecord&, const Vec3& point) = nullptr;
};

}  // namespace lightpath
