#include "accel/scene_geometry.h"

#include <algorithm>
#include <limits>
#include <bit>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <type_traits>
#include <utility>

#include "accel/bvh_traversal.h"
#include "geometry/builtin_shapes.h"
#include "geometry/intersect.h"
#include "sampling/warp.h"
#include "util/hot_path.h"
#include "util/parallel_chunks.h"
#ifdef LIGHTPATH_HAS_EMBREE
#include "accel/embree_accelerator.h"
#endif

namespace lightpath {
namespace {

// Primitive tests round: a hit they report may lie a few ulps outside the exact shape, so boxes
// grow by a margin far above that rounding (2^-16 relative) and traversal never drops such a hit.
Bounds padded(Bounds b) {
    const Vec3 magnitude = glm::max(glm::abs(b.lo), glm::abs(b.hi));
    const Vec3 margin = (magnitude + (b.hi - b.lo)) * 0x1p-16f;
    b.lo -= margin;
    b.hi += margin;
    return b;
}

Bounds triangleBounds(const Triangle& t) {
    Bounds b;
    b.grow(t.a);
    b.grow(t.b);
    b.grow(t.c);
    return padded(b);
}

}  // namespace

bool embreeAvailable() {
#ifdef LIGHTPATH_HAS_EMBREE
    return true;
#else
    return false;
#endif
}

SceneGeometry::SceneGeometry(std::vector<Sphere> spheres, std::vector<Plane> planes,
                             std::vector<Triangle> triangles, NumericsOptions numerics, Accelerator accelerator,
                             std::vector<TriangleNormals> vertexNormals, unsigned buildThreads,
                             std::vector<ShapeRecord> shapes, std::vector<TriangleUvs> triangleUvs,
                             std::vector<TriangleTangents> triangleTangents,
                             std::vector<std::shared_ptr<const SurfaceCoverage>> objectCoverage,
                             std::vector<TriangleColors> triangleColors)
    : triangles_(std::move(triangles)), vertexNormals_(std::move(vertexNormals)), triangleUvs_(std::move(triangleUvs)),
      triangleTangents_(std::move(triangleTangents)),
      triangleColors_(std::move(triangleColors)),
      coverage_(std::any_of(objectCoverage.begin(), objectCoverage.end(), [](const auto& c) { return c != nullptr; })
                    ? std::move(objectCoverage)
                    : std::vector<std::shared_ptr<const SurfaceCoverage>>{}),
      cutouts_(!coverage_.empty()),
      plainAnyHit_(!cutouts_ && accelerator != Accelerator::BruteForce),
      numerics_(numerics),
      accelerator_(accelerator) {
    if (!vertexNormals_.empty() && vertexNormals_.size() != triangles_.size())
        throw std::invalid_argument("vertex normals: expected one entry per triangle");
    if (!triangleUvs_.empty() && triangleUvs_.size() != triangles_.size())
        throw std::invalid_argument("texture coordinates: expected one entry per triangle");
    if (!triangleTangents_.empty() && triangleTangents_.size() != triangles_.size())
        throw std::invalid_argument("tangents: expected one entry per triangle");
    if (!triangleColors_.empty() && triangleColors_.size() != triangles_.size())
        throw std::invalid_argument("vertex colours: expected one entry per triangle");
    shapes_.reserve(spheres.size() + planes.size() + shapes.size());
    for (const Sphere& sphere : spheres) shapes_.push_back(sphereRecord(sphere));
    for (const Plane& plane : planes) shapes_.push_back(planeRecord(plane));
    shapes_.insert(shapes_.end(), shapes.begin(), shapes.end());
    // Planes are packed two at once from two on: a single plane costs more in a pack (its ray
    // set-up, the second call) than through the table (callgrind, bunny: +6.7 M instructions).
    const auto firstPlane = static_cast<std::uint32_t>(spheres.size());
    const auto planeEnd = firstPlane + static_cast<std::uint32_t>(planes.size() >= 2 ? planes.size() : 0);
    if (planes.size() >= 2) planePacks_ = packPlanes(planes, firstPlane);
    // The BVH's shapes: the bounded records, in id order (so its tree is as when spheres and the
    // other kinds had arrays of their own).
    std::vector<std::uint32_t> bounded;
    for (std::uint32_t id = 0; id < shapes_.size(); ++id) {
        if (shapes_[id].ops->bounded) bounded.push_back(id);
        else if (id < firstPlane || id >= planeEnd) unbounded_.push_back(id);
    }
    shapesInBvh_ = !bounded.empty();
    geometricNormals_.resize(triangles_.size());
    const auto computeNormals = [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) geometricNormals_[i] = triangleNormal(triangles_[i]);
    };
    if (accelerator_ == Accelerator::BruteForce) {
        computeNormals(0, triangles_.size());
        return;
    }
    if (accelerator_ == Accelerator::Embree && !embreeAvailable())
        throw std::invalid_argument("this lightpath was built without Embree (CMake option LIGHTPATH_EMBREE)");
    const auto started = std::chrono::steady_clock::now();
    // The boxes are computed by the build's threads as it reads them (no list of them all), and
    // the leaves' triangle blocks filled on as many: on one thread they would cap its scaling.
    // The BVH's primitives: the bounded shapes, then (Bvh only) triangles.
    const std::uint32_t firstTriangle = this->firstTriangle();
    const auto analytic = static_cast<std::uint32_t>(bounded.size());
    const std::size_t primitiveCount = analytic + (accelerator_ == Accelerator::Bvh ? triangles_.size() : 0);
    bvh_ = Bvh(
        primitiveCount,
        [&](std::size_t begin, std::size_t end, BvhPrimitive* out) {
            for (std::size_t i = begin; i < end; ++i) {
                const auto index = static_cast<std::uint32_t>(i);
                if (index < analytic) {
                    const ShapeRecord& shape = shapes_[bounded[index]];
                    *out++ = BvhPrimitive{padded(shape.ops->bounds(shape)), bounded[index]};
                } else {
                    *out++ = BvhPrimitive{triangleBounds(triangles_[index - analytic]),
                                          firstTriangle + index - analytic};
                }
            }
        },
        buildThreads);
    const unsigned threads = threadsOrAll(buildThreads);
    constexpr std::size_t kGrain = 16384;
    parallelChunks(triangles_.size(), kGrain, threads, computeNormals);
    if (accelerator_ == Accelerator::Bvh) {
        const auto ids = bvh_.slotIds();
        leafTriangles_.resize(ids.size() / kBvhLeafSize);
        parallelChunks(leafTriangles_.size(), kGrain / kBvhLeafSize, threads, [&](std::size_t begin, std::size_t end) {
            for (std::size_t slot = begin * kBvhLeafSize; slot < end * kBvhLeafSize; ++slot) {
                TrianglePack& pack = leafTriangles_[slot / kBvhLeafSize];
                const auto lane = static_cast<int>(slot % kBvhLeafSize);
                if (ids[slot] != kBvhEmptySlot && ids[slot] >= firstTriangle)
                    pack.set(lane, triangles_[ids[slot] - firstTriangle]);
                else
                    pack.clear(lane);  // padding or a shape record: never tested as a triangle
            }
        });
    }
#ifdef LIGHTPATH_HAS_EMBREE
    if (accelerator_ == Accelerator::Embree && !triangles_.empty())
        embree_ = std::make_shared<const EmbreeScene>(triangles_);
#endif
    stats_.buildSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
#ifdef LIGHTPATH_HAS_EMBREE
    if (embree_) stats_.buildSeconds = bvh_.stats().buildSeconds + embree_->buildSeconds();
#endif
    stats_.nodes = bvh_.stats().nodes;
    stats_.nodeBytes = bvh_.stats().nodeBytes;
}

SceneGeometry::~SceneGeometry() = default;

float SceneGeometry::intersectPrimitive(const Ray& ray, std::uint32_t id) const {
    if (id == ray.ignoredPrimitive) return kNoHit;
    if (id < shapes_.size()) return shapes_[id].ops->intersect(ray, shapes_[id], ray.tMin, numerics_);
    id -= static_cast<std::uint32_t>(shapes_.size());
    const Triangle& t = triangles_[id];
    return numerics_.triangle == TriangleTest::Watertight ? intersectTriangle(ray, t, ray.tMin)
                                                          : intersectTriangleMollerTrumbore(ray, t, ray.tMin);
}

std::uint32_t SceneGeometry::ignoredTriangle(const Ray& ray) const {
    const std::uint32_t firstTriangle = this->firstTriangle();
    return ray.ignoredPrimitive != kNoPrimitive && ray.ignoredPrimitive >= firstTriangle
               ? ray.ignoredPrimitive - firstTriangle
               : kNoPrimitive;
}

// Inlined into the leaf test each traversal loop calls: a call per leaf costs a fifth of the test.
template <typename Keep>
[[gnu::always_inline]] inline void SceneGeometry::intersectLeaf(const Ray& ray, const PackedRay& packed, std::uint32_t firstSlot,
                                  std::uint32_t count, Keep keep) const {
    const std::uint32_t* ids = bvh_.slotIds().data() + firstSlot;
    int triangleLanes = (1 << count) - 1;
    const auto unknownEdges = [] { return Vec4(0.0f); };
    if (shapesInBvh_ || leafTriangles_.empty()) {
        // Shape records (with Embree, only they) share the BVH with triangles: test them one by one.
        const std::uint32_t firstTriangle = this->firstTriangle();
        for (std::uint32_t lane = 0; lane < count; ++lane) {
            if (ids[lane] >= firstTriangle && !leafTriangles_.empty()) continue;
            triangleLanes &= ~(1 << lane);
            keep(intersectPrimitive(ray, ids[lane]), ids[lane], unknownEdges);
        }
    }
    if (ray.ignoredPrimitive != kNoPrimitive) {
        for (std::uint32_t lane = 0; lane < count; ++lane)
            if (ids[lane] == ray.ignoredPrimitive) triangleLanes &= ~(1 << lane);
    }
    if (triangleLanes == 0) return;
    const TrianglePack& pack = leafTriangles_[firstSlot / kBvhLeafSize];
    if (numerics_.triangle == TriangleTest::Watertight) {
        const PackHits found = watertightHits(pack, triangleLanes, packed, ray.tMin, ray.tMax);
        for (int lanes = found.hits; lanes != 0; lanes &= lanes - 1) {
            const int lane = simd::firstLane(lanes);
            keep(found.t[lane], ids[lane], [&] { return found.edges(lane); });
        }
        for (int lanes = found.onEdge; lanes != 0; lanes &= lanes - 1) {
            const int lane = simd::firstLane(lanes);
            // The scalar test divides (in its double-precision edge case): a divisor of 1 keeps them.
            Vec3 weights{0.0f};
            const float t = intersectTriangle(ray, packed.sheared, pack.triangle(lane), ray.tMin, &weights);
            keep(t, ids[lane], [&] { return Vec4(weights, 1.0f); });
        }
    } else {
        for (int lanes = triangleLanes; lanes != 0; lanes &= lanes - 1) {
            const int lane = simd::firstLane(lanes);
            keep(intersectTriangleMollerTrumbore(ray, pack.triangle(lane), ray.tMin), ids[lane], unknownEdges);
        }
    }
}

bool SceneGeometry::covered(const Ray& ray, const SurfaceHit& hit) const {
    const SurfaceCoverage* coverage = hit.object < coverage_.size() ? coverage_[hit.object].get() : nullptr;
    return coverage == nullptr ||
           coverage->covers(uvAt(hit.primitive, hit.point, hit.normal), vertexAlphaAt(hit),
                            coverageSample(ray, hit.primitive, glm::dot(hit.normal, ray.direction) < 0.0f));
}

bool SceneGeometry::covers(const Ray& ray, float t, std::uint32_t id, const Vec3* barycentrics) const {
    return !cutouts_ || covered(ray, describeHit(ray, t, id, barycentrics));
}

std::optional<SurfaceHit> SceneGeometry::intersectCovered(Ray ray) const {
    for (;;) {
        std::optional<SurfaceHit> hit = intersectSurface(ray);
        if (!hit || covered(ray, *hit)) return hit;
        // On past the hole, one float beyond it: every accelerator (Embree's t >= tnear too)
        // then finds the next surface, and the loop ends, as t only grows.
        ray.tMin = std::nextafter(hit->t, std::numeric_limits<float>::infinity());
    }
}

LIGHTPATH_HOT_PATH
std::optional<SurfaceHit> SceneGeometry::intersectSurface(const Ray& ray) const {
    if (accelerator_ == Accelerator::BruteForce) {
        const std::optional<PrimitiveHit> found = closestBruteForce(ray);
        if (!found) return std::nullopt;
        return describeHit(ray, found->t, found->primitive);
    }
    const PackedRay packed(ray);
    Vec4 edges{0.0f};
    std::optional<PrimitiveHit> found = closestAccelerated(ray, packed, &edges);
    if (!planePacks_.empty()) found = withPlanes(ray, found);
    if (!found) return std::nullopt;
    return describeHit(ray, found->t, found->primitive, nullptr, &edges, &packed.sheared);
}

std::optional<PrimitiveHit> SceneGeometry::closestPrimitive(const Ray& ray) const {
    if (cutouts_) {
        const std::optional<SurfaceHit> hit = intersectCovered(ray);
        if (!hit) return std::nullopt;
        return PrimitiveHit{hit->t, hit->primitive};
    }
    if (accelerator_ == Accelerator::BruteForce) return closestBruteForce(ray);
    const std::optional<PrimitiveHit> found = closestAccelerated(ray, PackedRay(ray));
    return planePacks_.empty() ? found : withPlanes(ray, found);
}

LIGHTPATH_HOT_PATH
std::optional<PrimitiveHit> SceneGeometry::closestAccelerated(const Ray& ray, const PackedRay& packed,
                                                              Vec4* edges) const {
    // Compiled twice: without `edges` (closestPrimitive, the ray sets) the loop is as it was
    // before the hand-off; a run-time test per kept hit cost them 1-2% (callgrind, ray_cost).
    const auto search = [&](auto wantEdges) -> std::optional<PrimitiveHit> {
        // The brute-force answer is the smallest t, ties to the smallest id (a later primitive
        // must be strictly nearer). Candidates arrive in another order here, so each is tested
        // against a limit one ulp beyond the best t, and an equal t wins only with a smaller id.
        PrimitiveHit best{ray.tMax, kNoPrimitive};
        Ray probe = ray;
        const auto keep = [&](float t, std::uint32_t id, const auto& edgesOf) {
            if (t == kNoHit) return;
            if (t < best.t || (t == best.t && id < best.primitive)) {
                best = {t, id};
                if constexpr (decltype(wantEdges)::value) *edges = edgesOf();
                // The next float up: for a positive t, its bit pattern plus one.
                probe.tMax = t > 0.0f ? std::bit_cast<float>(std::bit_cast<std::uint32_t>(t) + 1u)
                                      : std::nextafter(t, std::numeric_limits<float>::infinity());
            }
        };
        bvh_.closest(ray, best.t,
                     [&](std::uint32_t first, std::uint32_t count) { intersectLeaf(probe, packed, first, count, keep); });
        for (const std::uint32_t id : unbounded_) keep(intersectPrimitive(probe, id), id, [] { return Vec4(0.0f); });
#ifdef LIGHTPATH_HAS_EMBREE
        if (embree_) {
            const std::uint32_t firstTriangle = this->firstTriangle();
            const std::uint32_t ignored = ignoredTriangle(ray);
            float t = 0.0f;
            std::uint32_t index = 0;
            if (embree_->intersect(ray, best.t, ignored, t, index) && t < best.t) {
                best = {t, firstTriangle + index};
                if constexpr (decltype(wantEdges)::value) *edges = Vec4(0.0f);
            }
        }
#endif
        if (best.primitive == kNoPrimitive) return std::nullopt;
        return best;
    };
    return edges != nullptr ? search(std::true_type{}) : search(std::false_type{});
}

std::optional<PrimitiveHit> SceneGeometry::closestBruteForce(const Ray& ray) const {
    // The lecture's loop: test every primitive, keep the smallest t.
    Ray closest = ray;
    std::uint32_t found = kNoPrimitive;
    const auto count = static_cast<std::uint32_t>(primitiveCount());
    for (std::uint32_t id = 0; id < count; ++id) {
        const float t = intersectPrimitive(closest, id);
        if (t == kNoHit) continue;
        closest.tMax = t;
        found = id;
    }
    if (found == kNoPrimitive) return std::nullopt;
    return PrimitiveHit{closest.tMax, found};
}

// The planes apart from the closest-hit search and out of line: inside it, their code (idle in a
// scene without planes) changed GCC's inlining of the search and cost a mesh scene's rays 1% more
// (callgrind, cornell-original).
LIGHTPATH_HOT_PATH
PrimitiveHit SceneGeometry::nearestPlane(const Ray& ray) const {
    PrimitiveHit best{kNoHit, kNoPrimitive};
    for (const PlanePack& pack : planePacks_) {
        float t[2];
        for (int lanes = planeHits(pack, ray, t); lanes != 0; lanes &= lanes - 1) {
            const int lane = simd::firstLane(lanes);
            // Ids grow with the lanes: a later equal t never wins.
            if (best.primitive == kNoPrimitive || t[lane] < best.t) best = {t[lane], pack.ids[lane]};
        }
    }
    return best;
}

LIGHTPATH_HOT_PATH
std::optional<PrimitiveHit> SceneGeometry::withPlanes(const Ray& ray, std::optional<PrimitiveHit> found) const {
    // The planes' nearest within the limit the search would have tested them against, one ulp
    // beyond its hit; the smaller (t, id) of the two is the search's answer over all primitives
    // (its keep takes the smallest in whatever order candidates come).
    Ray probe = ray;
    if (found) {
        const float t = found->t;  // the next float up, as the search's keep computes it
        probe.tMax = t > 0.0f ? std::bit_cast<float>(std::bit_cast<std::uint32_t>(t) + 1u)
                              : std::nextafter(t, std::numeric_limits<float>::infinity());
    }
    const PrimitiveHit plane = nearestPlane(probe);
    if (plane.primitive == kNoPrimitive) return found;
    if (!found || plane.t < found->t || (plane.t == found->t && plane.primitive < found->primitive)) return plane;
    return found;
}

LIGHTPATH_HOT_PATH
bool SceneGeometry::anyPlane(const Ray& ray) const {
    for (const PlanePack& pack : planePacks_) {
        float t[2];
        if (planeHits(pack, ray, t) != 0) return true;
    }
    return false;
}

LIGHTPATH_HOT_PATH
bool SceneGeometry::occluded(const Ray& ray) const {
    if (!plainAnyHit_) {
        // An any-hit query cannot stop at a cut-out's first hit: it may be a hole.
        if (cutouts_) return intersectCovered(ray).has_value();
        return occludedBruteForce(ray);
    }
    const auto blocks = [&](std::uint32_t id) { return intersectPrimitive(ray, id) != kNoHit; };
    if (!planePacks_.empty() && anyPlane(ray)) return true;
    for (const std::uint32_t id : unbounded_)
        if (blocks(id)) return true;
#ifdef LIGHTPATH_HAS_EMBREE
    if (embree_) {
        if (embree_->occluded(ray, ignoredTriangle(ray))) return true;
    }
#endif
    const PackedRay packed(ray);
    // Inlined into the any-hit loop (callgrind: 1224 -> 1093 instructions per bunny shadow ray);
    // the closest-hit loop keeps its leaf test out of line, where inlining cost 7% more.
    return bvh_.any(ray, [&](std::uint32_t first, std::uint32_t count) __attribute__((always_inline)) {
        bool blocked = false;
        intersectLeaf(ray, packed, first, count,
                      [&](float t, std::uint32_t, const auto&) { blocked = blocked || t != kNoHit; });
        return blocked;
    });
}

bool SceneGeometry::occludedBruteForce(const Ray& ray) const {
    const auto count = static_cast<std::uint32_t>(primitiveCount());
    for (std::uint32_t id = 0; id < count; ++id)
        if (intersectPrimitive(ray, id) != kNoHit) return true;
    return false;
}

LIGHTPATH_HOT_PATH
SurfaceHit SceneGeometry::describeHit(const Ray& ray, float t, std::uint32_t id, const Vec3* barycentrics) const {
    return describeHit(ray, t, id, barycentrics, nullptr, nullptr);
}

LIGHTPATH_HOT_PATH
SurfaceHit SceneGeometry::describeHit(const Ray& ray, float t, std::uint32_t id, const Vec3* barycentrics,
                                      const Vec4* edges, const WatertightRay* sheared) const {
    SurfaceHit hit;
    hit.t = t;
    hit.point = ray.at(t);
    hit.primitive = id;
    if (id < shapes_.size()) {
        const ShapeRecord& shape = shapes_[id];
        hit.shape = shape.ops;
        hit.object = shape.object;
        shape.ops->describe(shape, hit);
        return hit;
    }
    id -= static_cast<std::uint32_t>(shapes_.size());
    const Triangle& tri = triangles_[id];
    hit.shape = nullptr;
    hit.normal = geometricNormals_[id];
    hit.shadingNormal = hit.normal;
    hit.object = tri.object;
    Vec3 weights{0.0f};
    bool weighted = true;
    if (barycentrics != nullptr) weights = *barycentrics;
    else if (edges != nullptr && edges->w != 0.0f) weights = Vec3(*edges) / edges->w;
    else if (sheared != nullptr) weighted = intersectTriangle(ray, *sheared, tri, ray.tMin, &weights) != kNoHit;
    else weighted = intersectTriangle(ray, tri, ray.tMin, &weights) != kNoHit;
    if (weighted) {
        hit.point = weights.x * tri.a + weights.y * tri.b + weights.z * tri.c;
        if (!vertexNormals_.empty()) {
            const TriangleNormals& n = vertexNormals_[id];
            const Vec3 smooth = weights.x * n.a + weights.y * n.b + weights.z * n.c;
            const float length = glm::length(smooth);
            // A flat triangle (zero normals) or a degenerate blend keeps the geometric normal.
            if (length > 0.0f && std::isfinite(length)) hit.shadingNormal = smooth / length;
        }
    }
    return hit;
}

namespace {

// Metres along the tangent frame of `normal`: flat shapes' natural coordinates.
SurfaceParameters planarParameters(const Vec3& point, const Vec3& normal) {
    const Frame frame(normal);
    return {Vec2(glm::dot(point, frame.s), glm::dot(point, frame.t)), frame.s, frame.t};
}

// The barycentric weights of `p` (on the triangle's plane) for a, b, c.
Vec3 barycentricsOf(const Triangle& tri, const Vec3& p) {
    const Vec3 e1 = tri.b - tri.a, e2 = tri.c - tri.a, d = p - tri.a;
    const float d11 = glm::dot(e1, e1), d12 = glm::dot(e1, e2), d22 = glm::dot(e2, e2);
    const float dp1 = glm::dot(d, e1), dp2 = glm::dot(d, e2);
    const float det = d11 * d22 - d12 * d12;
    if (!(det > 0.0f)) return {1.0f, 0.0f, 0.0f};
    const float wb = (d22 * dp1 - d12 * dp2) / det, wc = (d11 * dp2 - d12 * dp1) / det;
    return {1.0f - wb - wc, wb, wc};
}

}  // namespace

SurfaceParameters SceneGeometry::surfaceParameters(const SurfaceHit& hit) const {
    if (hit.primitive < shapes_.size()) {
        const ShapeRecord& shape = shapes_[hit.primitive];
        if (shape.ops->parametrise != nullptr) return shape.ops->parametrise(shape, hit.point);
        return planarParameters(hit.point, hit.normal);
    }
    const std::uint32_t index = hit.primitive - firstTriangle();
    if (triangleUvs_.empty() || !triangleUvs_[index].given) return planarParameters(hit.point, hit.normal);
    const Triangle& tri = triangles_[index];
    const TriangleUvs& uvs = triangleUvs_[index];
    const Vec3 w = barycentricsOf(tri, hit.point);
    SurfaceParameters result;
    result.uv = w.x * uvs.a + w.y * uvs.b + w.z * uvs.c;
    if (!triangleTangents_.empty()) {
        const TriangleTangents& t = triangleTangents_[index];
        result.tangent = w.x * t.a + w.y * t.b + w.z * t.c;
    }
    // dp/du and dp/dv from the corners (pbrt-v4 6.5.3): solve [duv02 duv12] [dpdu dpdv]^T = [dp02 dp12].
    const Vec2 duv02 = uvs.a - uvs.c, duv12 = uvs.b - uvs.c;
    const Vec3 dp02 = tri.a - tri.c, dp12 = tri.b - tri.c;
    const float det = duv02.x * duv12.y - duv02.y * duv12.x;
    if (std::abs(det) < 1e-12f) {
        const SurfaceParameters planar = planarParameters(hit.point, hit.normal);
        result.dpdu = planar.dpdu;
        result.dpdv = planar.dpdv;
        return result;
    }
    result.dpdu = (duv12.y * dp02 - duv02.y * dp12) / det;
    result.dpdv = (duv02.x * dp12 - duv12.x * dp02) / det;
    return result;
}

Rgb SceneGeometry::vertexColorAt(const SurfaceHit& hit) const {
    if (triangleColors_.empty() || hit.primitive < shapes_.size()) return Rgb(1.0f);
    const std::uint32_t index = hit.primitive - firstTriangle();
    const TriangleColors& c = triangleColors_[index];
    const Vec3 w = barycentricsOf(triangles_[index], hit.point);
    return w.x * c.a + w.y * c.b + w.z * c.c;
}

float SceneGeometry::vertexAlphaAt(const SurfaceHit& hit) const {
    if (triangleColors_.empty() || hit.primitive < shapes_.size()) return 1.0f;
    const std::uint32_t index = hit.primitive - firstTriangle();
    return glm::dot(barycentricsOf(triangles_[index], hit.point), triangleColors_[index].alpha);
}

Vec2 SceneGeometry::uvAt(std::uint32_t id, const Vec3& point, const Vec3& normal, const Vec3* barycentrics) const {
    if (id >= shapes_.size() && !triangleUvs_.empty() && triangleUvs_[id - firstTriangle()].given) {
        const std::uint32_t index = id - firstTriangle();
        const TriangleUvs& uvs = triangleUvs_[index];
        const Vec3 w = barycentrics != nullptr ? *barycentrics : barycentricsOf(triangles_[index], point);
        return w.x * uvs.a + w.y * uvs.b + w.z * uvs.c;
    }
    SurfaceHit hit;
    hit.point = point;
    hit.normal = normal;
    hit.primitive = id;
    return surfaceParameters(hit).uv;
}

}  // namespace lightpath
