#pragma once
// A shape kind as a type (issue #30): what the accelerator, the lights, radiosity and the
// rasteriser ask of one primitive, answered by a table of functions the kind's own file defines
// (src/shapes/, e.g. shapes/disk.cpp). A primitive is a ShapeRecord: its kind's table and a few
// floats only that kind reads, so a new kind needs no new container anywhere. Spheres and planes
// are records of this table too (shapes/sphere.cpp, shapes/plane.cpp); only triangles keep their
// own array and fast paths (triangle packs, SIMD, Embree). A record's test is one indirect call
// (for spheres +0.11% instructions of a render, callgrind).
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
};

}  // namespace lightpath
