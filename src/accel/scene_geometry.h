#pragma once
#include <memory>
#include <optional>
#include <vector>

#include "accel/bvh.h"
#include "accel/plane_pack.h"
#include "accel/triangle_pack.h"
#include "geometry/coverage.h"
#include "geometry/intersect.h"
#include "geometry/numerics.h"
#include "geometry/shape.h"
#include "geometry/shapes.h"
#include "geometry/surface_hit.h"
#include "math/ray.h"
#include "util/default_init_allocator.h"

namespace lightpath {

// All primitives of a scene and the two queries a tracer asks of them: the closest hit along a
// ray, and whether anything blocks a segment (any hit, for shadow rays). Primitives have one
// scene-wide id: the shape table's records (shape.h) first (spheres, planes, then the other
// kinds), then triangles.
// How closest-hit and any-hit queries find their candidates.
enum class Accelerator {
    BruteForce,  // the lecture's loop over every primitive
    Bvh,         // our BVH over the bounded shapes and triangles (src/accel/bvh.h); unbounded (planes) apart
    Embree,      // Embree for the triangles (when built with LIGHTPATH_EMBREE), our BVH for the rest
};

// What building the acceleration structure cost.
struct AcceleratorStats {
    double buildSeconds = 0.0;
    std::size_t nodes = 0;
    std::size_t nodeBytes = 0;
};

// The nearest hit as an accelerator reports it, before describeHit: t and the scene-wide id.
struct PrimitiveHit {
    float t = 0.0f;
    std::uint32_t primitive = kNoPrimitive;
};

class EmbreeScene;

// True when this build includes the Embree backend.
bool embreeAvailable();

class SceneGeometry {
public:
    SceneGeometry(std::vector<Sphere> spheres, std::vector<Plane> planes, std::vector<Triangle> triangles,
                  NumericsOptions numerics = {}, Accelerator accelerator = Accelerator::BruteForce,
                  std::vector<TriangleNormals> vertexNormals = {}, unsigned buildThreads = 0,
                  std::vector<ShapeRecord> shapes = {}, std::vector<TriangleUvs> triangleUvs = {},
                  std::vector<TriangleTangents> triangleTangents = {},
                  std::vector<std::shared_ptr<const SurfaceCoverage>> objectCoverage = {},
                  std::vector<TriangleColors> triangleColors = {});
    // `spheres` and `planes` become the table's first records (geometry/builtin_shapes.h), in
    // that order, before `shapes`. `objectCoverage`: empty, or per object id a cut-out (null: none;
    // geometry/coverage.h), which every query below then looks through.
    // Throws std::invalid_argument for Accelerator::Embree in a build without Embree.
    // buildThreads: how many threads build our BVH (0: all); the tree is the same for any count.
    ~SceneGeometry();
    SceneGeometry(SceneGeometry&&) noexcept = default;
    SceneGeometry& operator=(SceneGeometry&&) noexcept = default;
    SceneGeometry(const SceneGeometry&) = default;
    SceneGeometry& operator=(const SceneGeometry&) = default;

    // Closest hit: smallest t, and among equal t the smallest id, whatever the accelerator
    // (Embree: its own triangle test decides, so rare ties and edge hits may differ).
    std::optional<PrimitiveHit> closestPrimitive(const Ray& ray) const;

    // Inline: a scene without cut-outs calls the search itself, as it did before they were.
    std::optional<SurfaceHit> intersect(const Ray& ray) const {
        return cutouts_ ? intersectCovered(ray) : intersectSurface(ray);
    }
    bool occluded(const Ray& ray) const;
    // Whether a ray meets primitive `id` where `ray` hits it at `t` (a triangle's point at
    // `barycentrics` when given, as describeHit), or passes through a cut-out there: a
    // rasteriser's fragment test. True for every surface without one.
    bool covers(const Ray& ray, float t, std::uint32_t id, const Vec3* barycentrics = nullptr) const;
    bool hasCutouts() const { return cutouts_; }

    // t of the nearest hit of primitive `id` in (ray.tMin, ray.tMax), or kNoHit, with this
    // geometry's numerics.
    float intersectPrimitive(const Ray& ray, std::uint32_t id) const;
    // The hit of `ray` at `t` on primitive `id`: the one description of a surface point every
    // visibility method shares. A triangle's point and smooth normal come from `barycentrics`
    // (weights of a, b, c) when given — a rasteriser's interpolated coordinates — else from
    // intersecting the triangle again.
    SurfaceHit describeHit(const Ray& ray, float t, std::uint32_t id, const Vec3* barycentrics = nullptr) const;

    // The texture coordinates of a hit and dpdu, dpdv there: a kind's `parametrise`, a triangle's
    // corner uvs interpolated, else (a triangle without uvs, a kind without one) metres along the
    // tangent frame of its normal (sampling/warp.h's Frame), from the world's origin; a triangle's
    // corner tangents interpolated where its mesh gives them.
    SurfaceParameters surfaceParameters(const SurfaceHit& hit) const;
    // The texture coordinates surfaceParameters gives a point on primitive `id` (geometric normal
    // `normal`); a triangle's from `barycentrics` (weights of a, b, c) when given, as a point
    // sampled on it has them, else from the point.
    Vec2 uvAt(std::uint32_t id, const Vec3& point, const Vec3& normal, const Vec3* barycentrics = nullptr) const;
    // The vertex colour at a hit (glTF's COLOR_0): a triangle's corner colours interpolated, else white.
    Rgb vertexColorAt(const SurfaceHit& hit) const;
    // Its alpha there (COLOR_0's fourth component, interpolated), else 1: what cut-outs multiply.
    float vertexAlphaAt(const SurfaceHit& hit) const;

    const NumericsOptions& numerics() const { return numerics_; }
    Accelerator accelerator() const { return accelerator_; }
    const AcceleratorStats& acceleratorStats() const { return stats_; }
    const std::vector<Triangle>& triangles() const { return triangles_; }
    // The shape table's records (spheres, planes, then the other kinds), ids 0 .. shapes().size().
    const std::vector<ShapeRecord>& shapes() const { return shapes_; }
    std::size_t primitiveCount() const { return shapes_.size() + triangles_.size(); }

    // The one codec of scene-wide primitive ids: the shape table's records first, then triangles
    // (last, so the accelerator's triangle range is one interval).
    std::uint32_t shapeId(std::uint32_t index) const { return index; }
    std::uint32_t triangleId(std::uint32_t index) const { return firstTriangle() + index; }
    // The record of id `id`, or nullptr for a triangle.
    const ShapeRecord* shapeOf(std::uint32_t id) const { return id < shapes_.size() ? &shapes_[id] : nullptr; }
    // The triangle of id `id`; id must be a triangle's.
    const Triangle& triangleOf(std::uint32_t id) const { return triangles_[id - firstTriangle()]; }

private:
    // The closest hit of any surface, covered or not.
    std::optional<SurfaceHit> intersectSurface(const Ray& ray) const;
    // The closest covered hit: past every cut-out the ray crosses on its way.
    std::optional<SurfaceHit> intersectCovered(Ray ray) const;
    bool covered(const Ray& ray, const SurfaceHit& hit) const;
    // The accelerated closest hit, given the ray's per-ray watertight set-up. With `edges`, also
    // the hit's unnormalised barycentrics as the traversal's triangle test found them (see
    // describeHit), so that intersect() need not test the triangle again.
    std::optional<PrimitiveHit> closestAccelerated(const Ray& ray, const PackedRay& packed,
                                                   Vec4* edges = nullptr) const;
    // A triangle's barycentrics from, in this order: `barycentrics`; `edges`, its edge functions
    // of a, b, c in x, y, z and their sum in w, the weights being xyz / w exactly as
    // intersectTriangle divides them (w = 0 when the traversal did not compute them: Embree's
    // hit, Moller-Trumbore); testing the triangle again, with the ray's `sheared` set-up if given.
    SurfaceHit describeHit(const Ray& ray, float t, std::uint32_t id, const Vec3* barycentrics,
                           const Vec4* edges, const WatertightRay* sheared) const;
    // The planes' nearest hit in (ray.tMin, ray.tMax), ties to the smaller id ({kNoHit,
    // kNoPrimitive}: none), and whether any plane is hit there.
    PrimitiveHit nearestPlane(const Ray& ray) const;
    // `found`, the accelerated search's closest hit among the other primitives, or the planes'
    // nearest where it is nearer (at equal t, where its id is smaller). Called only with planes.
    std::optional<PrimitiveHit> withPlanes(const Ray& ray, std::optional<PrimitiveHit> found) const;
    bool anyPlane(const Ray& ray) const;
    std::optional<PrimitiveHit> closestBruteForce(const Ray& ray) const;
    bool occludedBruteForce(const Ray& ray) const;
    // Calls keep(t, id, edges) for every primitive of the BVH leaf at `firstSlot` that `ray`
    // hits, t as intersectPrimitive gives it and edges() the hit's edge functions (describeHit's
    // `edges`; called only by a keep that wants them); its triangles are read from their leaf-ordered copy and
    // filtered four at once first: the same test on the same numbers, from adjacent memory.
    template <typename Keep>
    void intersectLeaf(const Ray& ray, const PackedRay& packed, std::uint32_t firstSlot, std::uint32_t count,
                       Keep keep) const;
    // The ray's ignored primitive as an index among the triangles (what Embree knows), or kNoPrimitive.
    std::uint32_t ignoredTriangle(const Ray& ray) const;
    std::uint32_t firstTriangle() const { return static_cast<std::uint32_t>(shapes_.size()); }

    std::vector<Triangle> triangles_;
    std::vector<ShapeRecord> shapes_;
    // The records no box holds, tested apart on every ray: the constructor's `planes`, when there
    // are two or more, two at once in packs; the ids of the others (a single plane, other kinds).
    std::vector<PlanePack> planePacks_;
    std::vector<std::uint32_t> unbounded_;
    bool shapesInBvh_ = false;              // some record is in the BVH (bounded)
    // Each triangle's unit geometric normal (triangleNormal), computed once: every hit reads it.
    std::vector<Vec3> geometricNormals_;
    std::vector<TriangleNormals> vertexNormals_;  // empty, or one per triangle
    std::vector<TriangleUvs> triangleUvs_;        // empty, or one per triangle
    std::vector<TriangleTangents> triangleTangents_;  // empty, or one per triangle
    std::vector<TriangleColors> triangleColors_;      // empty, or one per triangle
    // Empty when nothing is cut out, else one per object id (null: covered everywhere).
    std::vector<std::shared_ptr<const SurfaceCoverage>> coverage_;
    bool cutouts_ = false;  // !coverage_.empty(), one byte for the hot paths to test
    // Neither cut-outs nor the lecture's loop: occluded's common case, one test.
    bool plainAnyHit_ = false;
    NumericsOptions numerics_;
    Accelerator accelerator_;
    Bvh bvh_;  // bounded shapes and triangles (Bvh); no triangles (Embree)
    // The triangles of each BVH leaf block (Bvh only); filled on the build's threads, not zeroed first.
    std::vector<TrianglePack, DefaultInitAllocator<TrianglePack>> leafTriangles_;
    std::shared_ptr<const EmbreeScene> embree_;
    AcceleratorStats stats_;
};

}  // namespace lightpath
