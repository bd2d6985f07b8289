#include "integrators/radiosity_mesh.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <unordered_map>
#include <unordered_set>

#include "geometry/spawn_ray.h"
#include "math/random.h"
#include "sampling/sampler.h"
#include "sampling/warp.h"
#include "util/parallel_chunks.h"

namespace lightpath {
namespace {

// No primitive is cut finer than this per edge: a huge triangle at a tiny patch size would
// otherwise overflow the counts (the integrator's patch limit refuses such meshes anyway).
constexpr double kMaxSubdivisions = 1 << 15;

double longestEdge(const Vec3& a, const Vec3& b, const Vec3& c) {
    return std::max({glm::length(b - a), glm::length(c - b), glm::length(a - c)});
}

std::uint32_t subdivisions(double longest, float patchSize) {
    return static_cast<std::uint32_t>(std::clamp(std::ceil(longest / patchSize), 1.0, kMaxSubdivisions));
}

std::uint32_t triangleSubdivisions(const Vec3& a, const Vec3& b, const Vec3& c, float patchSize) {
    return subdivisions(longestEdge(a, b, c), patchSize);
}

bool hasArea(const Vec3& a, const Vec3& b, const Vec3& c) {
    const float area2 = glm::length(glm::cross(b - a, c - a));
    return std::isfinite(area2) && area2 > 0.0f;
}

// Sub-triangle layout of an n x n triangle grid: row j (0..n-1) holds the lower triangles
// (i, j) for i < n - j at even offsets and the upper ones (i < n - j - 1) at odd offsets.
std::uint32_t rowStart(std::uint32_t n, std::uint32_t j) { return j * (2 * n - j); }

// The region an unbounded shape is tessellated over (ShapeOps::tessellateRegion): the bounds of
// every bounded shape, every triangle, every light's position and the eye.
Bounds sceneRegion(const Scene& scene, const SceneGeometry& geometry) {
    Bounds region;
    for (const ShapeRecord& s : geometry.shapes())
        if (s.ops->bounded) region.grow(s.ops->bounds(s));
    for (const Triangle& t : geometry.triangles()) {
        region.grow(t.a);
        region.grow(t.b);
        region.grow(t.c);
    }
    for (const LightSlot& l : scene.lights) region.grow(l->position());
    region.grow(scene.camera.eye);
    return region;
}

// A triangle to mesh and the patch size to cut it at.
struct Piece {
    Triangle triangle;
    float patchSize;
};

// An unbounded surface's light beyond the scene still reaches the scene (issue 27: a floor plane
// clipped to the scene lost 8-25% of the second to fourth bounce). Its rectangle over the scene is
// surrounded by rings (RadiosityOptions::planeRings, 3), each kRingGrowth times wider than the one inside and cut into
// patches kRingCoarsening times coarser: each ring costs about a quarter of the patches inside it.
// The light the plane sends back decays fast with distance d (a point light lights it as h/d^3 and
// a receiver at height h sees an element at d under a form factor ~ h/d^3: the contribution from
// beyond the radius R ~ 1/R^4, below 1e-6 of the inner rectangle's beyond 64 times its size), and a
// uniform light (the sky) makes the far plane uniform: a hit beyond the last ring takes the value
// of the ring's nearest patch (RadiosityMesh::lookup).
constexpr float kRingGrowth = 4.0f;
constexpr float kRingCoarsening = 8.0f;

// The rings around an unbounded kind's region, each as four strips of two triangles. The rings
// are built around a parallelogram (a, b, c), (a, c, d), which is what the only unbounded kind's
// tessellateRegion makes (shapes/plane.cpp); a kind meshing its region otherwise would lose the
// light beyond it again, silently, so it is refused here until rings are built for its form.
void requireParallelogram(const std::vector<Triangle>& inner) {
    if (inner.size() != 2 || inner[1].a != inner[0].a || inner[1].b != inner[0].c)
        throw std::logic_error("radiosity: an unbounded shape's region is not meshed as a parallelogram of two "
                               "triangles, the only form its rings and cuts are built for (RadiosityMesh, addRings)");
}

void addRings(const std::vector<Triangle>& inner, float patchSize, int rings, std::vector<Piece>& out) {
    if (rings == 0 || inner.empty()) return;
    requireParallelogram(inner);
    const Vec3 a = inner[0].a, b = inner[0].b, d = inner[1].c;
    const Vec3 centre = 0.5f * (b + d), halfS = 0.5f * (b - a), halfT = 0.5f * (d - a);
    const std::uint32_t object = inner[0].object;
    const auto at = [&](float s, float t) { return centre + s * halfS + t * halfT; };
    const auto rectangle = [&](float s0, float s1, float t0, float t1, float size) {
        out.push_back({{at(s0, t0), at(s1, t0), at(s1, t1), object}, size});
        out.push_back({{at(s0, t0), at(s1, t1), at(s0, t1), object}, size});
    };
    float in = 1.0f, size = patchSize;
    for (int ring = 0; ring < rings; ++ring) {
        const float outer = in * kRingGrowth;
        size *= kRingCoarsening;
        rectangle(-outer, outer, -outer, -in, size);  // the strips below and above the inner rectangle
        rectangle(-outer, outer, in, outer, size);
        rectangle(-outer, -in, -in, in, size);        // and left and right of it
        rectangle(in, outer, -in, in, size);
        in = outer;
    }
}

// Issue 27: an unbounded shape's rectangle reaches past the scene, so where a wall stands on a
// floor plane the floor's patches ran under the wall's foot: each averaged the room's light with
// the dark outside and spread it outside (the lecture room's floor and walls 2-5% low at bounce 4).
// The rectangle is cut along every line where another surface meets its plane, so no patch
// straddles one: the edges of triangles lying in the plane (a wall's foot) and the lines where
// the other unbounded shapes' planes cross it. Each line is cut across the whole rectangle (the
// pieces stay convex); at most kMaxContactLines of them, the longest contacts first, so a mesh
// resting on the plane with a flat base of many edges does not shatter it.
constexpr std::size_t kMaxContactLines = 16;
// A triangle's edge lies in the plane when both ends are within this fraction of the region's
// diagonal of it; an edge shorter than kMinContactFraction of the diagonal is no contact line.
constexpr float kContactTolerance = 1e-5f;
constexpr float kMinContactFraction = 1e-2f;

struct ContactLine {
    Vec3 point, direction;
    float length;  // of the contact (a plane's crossing: the region's diagonal)
};

// The plane of an unbounded shape's region parallelogram (addRings' form): a point and unit normal.
struct PlaneOf {
    Vec3 point, normal;
};

PlaneOf planeOf(const std::vector<Triangle>& inner) {
    return {inner[0].a, glm::normalize(glm::cross(inner[0].b - inner[0].a, inner[0].c - inner[0].a))};
}

std::vector<ContactLine> contactLines(const SceneGeometry& geometry, const ShapeRecord& shape, const PlaneOf& plane,
                                      const Bounds& region) {
    const float diagonal = glm::length(region.hi - region.lo);
    const float tolerance = kContactTolerance * diagonal;
    std::vector<ContactLine> lines;
    const auto distance = [&](const Vec3& p) { return std::fabs(glm::dot(p - plane.point, plane.normal)); };
    for (const Triangle& t : geometry.triangles()) {
        if (t.object == shape.object) continue;
        const std::array<Vec3, 3> corners{t.a, t.b, t.c};
        for (int e = 0; e < 3; ++e) {
            const Vec3 p = corners[e], q = corners[(e + 1) % 3];
            const float length = glm::length(q - p);
            if (distance(p) <= tolerance && distance(q) <= tolerance && length >= kMinContactFraction * diagonal)
                lines.push_back({p, (q - p) / length, length});
        }
    }
    std::vector<Triangle> scratch;
    for (const ShapeRecord& other : geometry.shapes()) {
        if (&other == &shape || other.ops->bounded || !other.ops->tessellateRegion) continue;
        scratch.clear();
        other.ops->tessellateRegion(other, region, scratch);
        if (scratch.empty()) continue;
        const PlaneOf o = planeOf(scratch);
        const Vec3 direction = glm::cross(plane.normal, o.normal);
        const float sine = glm::length(direction);
        if (sine < 1e-3f) continue;  // parallel planes never meet
        // The point of both planes nearest the region's centre (Goldman, Graphics Gems 1990).
        const Vec3 u = direction / sine;
        const float h1 = glm::dot(plane.normal, plane.point), h2 = glm::dot(o.normal, o.point);
        const float c = glm::dot(plane.normal, o.normal), det = 1.0f - c * c;
        const Vec3 onBoth = ((h1 - c * h2) / det) * plane.normal + ((h2 - c * h1) / det) * o.normal;
        const Vec3 centre = region.centroid();
        lines.push_back({onBoth + glm::dot(centre - onBoth, u) * u, u, diagonal});
    }
    std::stable_sort(lines.begin(), lines.end(), [](const ContactLine& a, const ContactLine& b) { return a.length > b.length; });
    if (lines.size() > kMaxContactLines) lines.resize(kMaxContactLines);
    return lines;
}

// A convex polygon in a parallelogram's coordinates (s, t), split by the line through p with normal n
// into the parts on either side (Sutherland and Hodgman 1974, both halves); false if the line
// misses it (a corner within kSide of the line lies on it).
using Polygon = std::vector<Vec2>;

bool splitPolygon(const Polygon& polygon, Vec2 p, Vec2 n, Polygon& negative, Polygon& positive) {
    constexpr float kSide = 1e-6f;
    std::vector<float> side(polygon.size());
    bool below = false, above = false;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        side[i] = glm::dot(polygon[i] - p, n);
        below |= side[i] < -kSide;
        above |= side[i] > kSide;
    }
    if (!(below && above)) return false;
    negative.clear();
    positive.clear();
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const std::size_t j = (i + 1) % polygon.size();
        if (side[i] <= kSide) negative.push_back(polygon[i]);
        if (side[i] >= -kSide) positive.push_back(polygon[i]);
        if ((side[i] < -kSide && side[j] > kSide) || (side[i] > kSide && side[j] < -kSide)) {
            const Vec2 crossing = polygon[i] + (side[i] / (side[i] - side[j])) * (polygon[j] - polygon[i]);
            negative.push_back(crossing);
            positive.push_back(crossing);
        }
    }
    return true;
}

// A piece longer than kMaxPieceAspect times its width is cut across into near-square parts: a
// triangle is subdivided n x n by its longest edge, so a long thin strip (the rectangle beyond a
// wall) would be cut into slivers, several times the elements its area needs.
constexpr float kMaxPieceAspect = 1.5f;

// The parallelogram (a, b, c), (a, c, d) cut along `lines` into convex pieces, each fanned into
// triangles wound as the parallelogram (so with its normal). Worked in its coordinates (s, t):
// p = a + s (b - a) + t (d - a), the unit square.
void cutAlongLines(const std::vector<Triangle>& inner, const std::vector<ContactLine>& lines, float patchSize,
                   std::vector<Piece>& out) {
    const Vec3 a = inner[0].a, e1 = inner[0].b - inner[0].a, e2 = inner[1].c - inner[0].a;
    const float d00 = glm::dot(e1, e1), d01 = glm::dot(e1, e2), d11 = glm::dot(e2, e2);
    const float denominator = d00 * d11 - d01 * d01;
    const auto local = [&](const Vec3& v) {  // a vector's (s, t), least squares
        const float d20 = glm::dot(v, e1), d21 = glm::dot(v, e2);
        return Vec2{(d11 * d20 - d01 * d21) / denominator, (d00 * d21 - d01 * d20) / denominator};
    };
    std::vector<Polygon> pieces{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}}, next;
    Polygon negative, positive;
    for (const ContactLine& line : lines) {
        const Vec2 p = local(line.point - a), d = local(line.direction);
        const Vec2 n = glm::normalize(Vec2{-d.y, d.x});
        next.clear();
        for (const Polygon& polygon : pieces) {
            if (splitPolygon(polygon, p, n, negative, positive)) {
                next.push_back(negative);
                next.push_back(positive);
            } else {
                next.push_back(polygon);
            }
        }
        pieces.swap(next);
    }
    // Long pieces cut across their longer axis (s or t, in scene units) into near-square parts.
    const float lengthS = std::sqrt(d00), lengthT = std::sqrt(d11);
    next.clear();
    for (Polygon& polygon : pieces) {
        Vec2 lo{1.0f}, hi{0.0f};
        for (const Vec2& v : polygon) {
            lo = glm::min(lo, v);
            hi = glm::max(hi, v);
        }
        const float extentS = (hi.x - lo.x) * lengthS, extentT = (hi.y - lo.y) * lengthT;
        const bool alongS = extentS >= extentT;
        const float ratio = alongS ? extentS / std::max(extentT, 1e-30f) : extentT / std::max(extentS, 1e-30f);
        const int parts = ratio > kMaxPieceAspect ? static_cast<int>(std::lround(ratio)) : 1;
        const Vec2 n = alongS ? Vec2{1, 0} : Vec2{0, 1};
        for (int k = 1; k < parts; ++k) {
            const float f = float(k) / float(parts);
            const Vec2 p = lo + f * (hi - lo);
            if (!splitPolygon(polygon, p, n, negative, positive)) continue;
            next.push_back(negative);
            polygon = positive;
        }
        next.push_back(std::move(polygon));
    }
    pieces.swap(next);
    const std::uint32_t object = inner[0].object;
    const auto at = [&](const Vec2& st) { return a + st.x * e1 + st.y * e2; };
    for (const Polygon& polygon : pieces)
        for (std::size_t i = 1; i + 1 < polygon.size(); ++i)
            out.push_back({{at(polygon[0]), at(polygon[i]), at(polygon[i + 1]), object}, patchSize});
}

// The triangles a record without a patch grid is meshed as (geometry/shape.h): its tessellation,
// or an unbounded kind's over `region`, cut along where the scene meets it (with `contacts`: the
// scene's geometry; nullptr leaves it whole), and the rings around it (none if it has no
// tessellateRegion).
void tessellateRecord(const ShapeRecord& shape, float patchSize, int rings, const Bounds& region,
                      const SceneGeometry* contacts, std::vector<Triangle>& scratch, std::vector<Piece>& out) {
    scratch.clear();
    out.clear();
    if (shape.ops->bounded) {
        if (shape.ops->tessellate) shape.ops->tessellate(shape, patchSize, scratch);
    } else if (shape.ops->tessellateRegion) {
        shape.ops->tessellateRegion(shape, region, scratch);
    }
    if (!shape.ops->bounded && contacts != nullptr && !scratch.empty()) {
        requireParallelogram(scratch);
        cutAlongLines(scratch, contactLines(*contacts, shape, planeOf(scratch), region), patchSize, out);
    } else {
        for (const Triangle& t : scratch) out.push_back({t, patchSize});
    }
    if (!shape.ops->bounded) addRings(scratch, patchSize, rings, out);
}

// Which cluster a triangle no larger than the patch size joins: its object, the cell of side
// `patchSize` holding its centroid, and a bucket of normal directions (the dominant axis and its
// sign, the other two components over it cut in thirds: cones of about 25 degrees).
struct ClusterKey {
    std::uint32_t object;
    std::int64_t x, y, z;
    std::uint32_t direction;
    bool buried;  // buried and exposed triangles never share a cluster (isBuried)
    bool operator==(const ClusterKey&) const = default;
};

struct ClusterKeyHash {
    std::size_t operator()(const ClusterKey& k) const {
        std::uint64_t h = mixBits(k.object ^ (std::uint64_t(k.direction) << 32) ^ (std::uint64_t(k.buried) << 63));
        for (std::int64_t v : {k.x, k.y, k.z}) h = mixBits(h ^ static_cast<std::uint64_t>(v));
        return static_cast<std::size_t>(h);
    }
};

// The direction bucket of a triangle's normal (ClusterKey::direction).
std::uint32_t directionBucket(const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 n = glm::normalize(glm::cross(b - a, c - a));
    const Vec3 m = glm::abs(n);
    const int axis = m.x >= m.y && m.x >= m.z ? 0 : (m.y >= m.z ? 1 : 2);
    const float major = n[axis];
    const auto third = [&](float v) { return static_cast<std::uint32_t>(std::clamp((v / std::abs(major) + 1.0f) * 1.5f, 0.0f, 2.0f)); };
    return ((std::uint32_t(axis) * 2 + (major < 0.0f ? 1u : 0u)) * 3 + third(n[(axis + 1) % 3])) * 3 + third(n[(axis + 2) % 3]);
}

Vec3 centroidOf(const Vec3& a, const Vec3& b, const Vec3& c) { return (a + b + c) / 3.0f; }

// RadiosityMesh::kClusterCell: at the whole patch size a cluster of a curved mesh spans light that
// varies across it (the lecture room's bunny, 1.05 high, in cells of 0.96: its ED{4,}L 0.805 of
// the path tracer's, its lowest regions 0.39); at half, 0.904 and 0.61, for a first mesh of the
// same budget (the walls' patches 1.00 rather than 0.96, refined as before).
ClusterKey clusterKey(std::uint32_t object, const Vec3& centroid, std::uint32_t direction, float patchSize, bool buried) {
    const auto cell = [&](float v) { return static_cast<std::int64_t>(std::floor(double(v) / (RadiosityMesh::kClusterCell * patchSize))); };
    return {object, cell(centroid.x), cell(centroid.y), cell(centroid.z), direction, buried};
}

ClusterKey clusterKey(std::uint32_t object, const Vec3& a, const Vec3& b, const Vec3& c, float patchSize, bool buried) {
    return clusterKey(object, centroidOf(a, b, c), directionBucket(a, b, c), patchSize, buried);
}

// Issue 27: a mesh sunk into a floor plane or into another object has triangles where no light
// comes; clustered with the exposed triangles beside them, they dilute each cluster's radiosity
// (tests/render/test_radiosity.cpp: a box half sunk into a plane, 0.83 / 0.70 of the path tracer
// at bounces 1 / 2 before, 0.99 / 0.98 now). A cluster stands for members that receive about the
// same light (Smits, Arvo and Greenberg 1994 group elements whose transport one value can carry);
// a buried triangle receives none, so buried and exposed triangles are never clustered together
// (each keeps its own clusters: nothing is dropped, and a buried cluster simply stays dark).
// A triangle is buried when, along kBurialDirections from its centroid, the surfaces of other
// objects met first show their back (the ray travels along their normal) more often than their
// front: it lies inside a closed object whose normals point out, or on the back of a plane. Its own
// object's surfaces are passed through (up to kBurialCrossings of them), so a closed mesh's own
// inside does not count. A scene whose surfaces face the other way misjudges whole regions alike,
// and a region judged alike keeps the clusters it had: only clusters that mix the two are split.
constexpr int kBurialCrossings = 16;
constexpr float kDiagonal = 0.57735027f;  // 1 / sqrt(3)
constexpr std::array<Vec3, 14> kBurialDirections{{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1},
                                                  {kDiagonal, kDiagonal, kDiagonal}, {kDiagonal, kDiagonal, -kDiagonal},
                                                  {kDiagonal, -kDiagonal, kDiagonal}, {kDiagonal, -kDiagonal, -kDiagonal},
                                                  {-kDiagonal, kDiagonal, kDiagonal}, {-kDiagonal, kDiagonal, -kDiagonal},
                                                  {-kDiagonal, -kDiagonal, kDiagonal}, {-kDiagonal, -kDiagonal, -kDiagonal}}};

bool isBuried(const SceneGeometry& geometry, std::uint32_t primitive, const Triangle& t) {
    SurfaceHit start;
    start.point = centroidOf(t.a, t.b, t.c);
    start.normal = start.shadingNormal = glm::normalize(glm::cross(t.b - t.a, t.c - t.a));
    start.object = t.object;
    start.primitive = primitive;
    int back = 0, front = 0;
    for (const Vec3& direction : kBurialDirections) {
        Ray ray = spawnRay(start, direction, geometry.numerics());
        for (int crossing = 0; crossing < kBurialCrossings; ++crossing) {
            const auto hit = geometry.intersect(ray);
            if (!hit) break;
            if (hit->object != t.object) {
                ++(glm::dot(hit->normal, direction) > 0.0f ? back : front);
                break;
            }
            ray = spawnRay(*hit, direction, geometry.numerics());
        }
    }
    return back > front;
}

// How many clusters a patch size makes, for the budget's bisection, which asks at some 60 sizes:
// what does not depend on the size (the region, each triangle's longest edge, centroid and
// normal bucket) is computed once, and the key set's buckets are kept from one size to the next.
class ClusterCounter {
public:
    ClusterCounter(const Scene& scene, const SceneGeometry& geometry, int planeRings, std::span<const std::uint8_t> buried,
                   bool cutPlanes)
        : geometry_(geometry), planeRings_(planeRings), cutPlanes_(cutPlanes), region_(sceneRegion(scene, geometry)) {
        for (std::size_t i = 0; i < geometry.triangles().size(); ++i) {
            const Triangle& t = geometry.triangles()[i];
            if (hasArea(t.a, t.b, t.c))
                triangles_.push_back({longestEdge(t.a, t.b, t.c), centroidOf(t.a, t.b, t.c), t.object,
                                      directionBucket(t.a, t.b, t.c), !buried.empty() && buried[i] != 0});
        }
    }

    std::size_t count(float patchSize) {
        count_ = 0;
        keys_.clear();
        for (const ShapeRecord& shape : geometry_.shapes()) {
            if (shape.ops->patchGrid) {
                const PatchGrid grid = shape.ops->patchGrid->cells(shape, patchSize);
                count_ += std::size_t{grid.rows} * grid.columns;
                continue;
            }
            tessellateRecord(shape, patchSize, planeRings_, region_, cutPlanes_ ? &geometry_ : nullptr, scratch_, pieces_);
            for (const Piece& p : pieces_) {
                const Triangle& t = p.triangle;
                if (!hasArea(t.a, t.b, t.c)) continue;
                add(subdivisions(longestEdge(t.a, t.b, t.c), p.patchSize), shape.object, centroidOf(t.a, t.b, t.c),
                    directionBucket(t.a, t.b, t.c), patchSize, false);
            }
        }
        for (const Counted& t : triangles_)
            add(subdivisions(t.longest, patchSize), t.object, t.centroid, t.direction, patchSize, t.buried);
        return count_;
    }

private:
    struct Counted {
        double longest;
        Vec3 centroid;
        std::uint32_t object, direction;
        bool buried;
    };

    // A triangle cut n x n makes n^2 patches; one not cut joins its cluster (or starts it).
    void add(std::size_t n, std::uint32_t object, const Vec3& centroid, std::uint32_t direction, float patchSize,
             bool buried) {
        if (n == 1) {
            if (keys_.insert(clusterKey(object, centroid, direction, patchSize, buried)).second) ++count_;
        } else {
            count_ += n * n;
        }
    }

    const SceneGeometry& geometry_;
    int planeRings_;
    bool cutPlanes_;
    Bounds region_;
    std::vector<Counted> triangles_;  // the triangle array's, those with area
    std::unordered_set<ClusterKey, ClusterKeyHash> keys_;
    std::vector<Triangle> scratch_;
    std::vector<Piece> pieces_;
    std::size_t count_ = 0;
};

}  // namespace

// Joins the grid vertices that neighbouring triangles of one object and orientation share, so
// a vertex's radiosity averages the patches around it across triangle edges (a quad's diagonal).
struct RadiosityMesh::VertexWelder {
    struct Key {
        std::uint32_t object;
        std::int64_t x, y, z;
        std::int32_t nx, ny, nz;
        bool operator==(const Key&) const = default;
    };
    struct Hash {
        std::size_t operator()(const Key& k) const {
            std::uint64_t h = k.object;
            for (std::int64_t v : {k.x, k.y, k.z, std::int64_t{k.nx}, std::int64_t{k.ny}, std::int64_t{k.nz}})
                h = mixBits(h ^ static_cast<std::uint64_t>(v));
            return static_cast<std::size_t>(h);
        }
    };
    float step;  // positions closer than about this weld
    std::unordered_map<Key, std::uint32_t, Hash> ids;
    std::size_t& count;

    std::uint32_t vertex(std::uint32_t object, const Vec3& p, const Vec3& normal) {
        const auto q = [&](float v) { return static_cast<std::int64_t>(std::llround(double(v) / step)); };
        const auto qn = [](float v) { return static_cast<std::int32_t>(std::lround(v * 64.0f)); };
        const Key key{object, q(p.x), q(p.y), q(p.z), qn(normal.x), qn(normal.y), qn(normal.z)};
        const auto [it, added] = ids.try_emplace(key, static_cast<std::uint32_t>(count));
        if (added) ++count;
        return it->second;
    }
};

RadiosityMesh::VertexPatches RadiosityMesh::patchesAroundVertices() const {
    VertexPatches around;
    around.start.assign(vertexCount_ + 1, 0);
    for (const RadiosityPatch& p : patches_)
        for (int v = 0; v < p.vertexCount; ++v) ++around.start[p.vertices[v] + 1];
    for (std::size_t v = 0; v < vertexCount_; ++v) around.start[v + 1] += around.start[v];
    around.patches.resize(around.start.back());
    std::vector<std::uint32_t> fill(around.start.begin(), around.start.end() - 1);
    for (std::uint32_t q = 0; q < patches_.size(); ++q)
        for (int v = 0; v < patches_[q].vertexCount; ++v) around.patches[fill[patches_[q].vertices[v]]++] = q;
    return around;
}

std::size_t RadiosityMesh::countClusters(const Scene& scene, const SceneGeometry& geometry, float patchSize, int planeRings,
                                         std::span<const std::uint8_t> buried, bool cutPlanes) {
    return ClusterCounter(scene, geometry, planeRings, buried, cutPlanes).count(patchSize);
}

std::vector<std::uint8_t> RadiosityMesh::buriedTriangles(const SceneGeometry& geometry, int threads) {
    const auto& triangles = geometry.triangles();
    std::vector<std::uint8_t> buried(triangles.size(), 0);
    parallelChunks(triangles.size(), 1024, threadsOrAll(threads), [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i)
            if (hasArea(triangles[i].a, triangles[i].b, triangles[i].c))
                buried[i] = isBuried(geometry, geometry.triangleId(std::uint32_t(i)), triangles[i]) ? 1 : 0;
    });
    return buried;
}

float RadiosityMesh::patchSizeForBudget(const Scene& scene, const SceneGeometry& geometry, std::size_t budget,
                                        int planeRings, std::span<const std::uint8_t> buried, bool cutPlanes) {
    // The count falls as the size grows: bisect log(size) between a size too fine and one coarse
    // enough to leave one patch per triangle (the least any mesh can have).
    ClusterCounter counter(scene, geometry, planeRings, buried, cutPlanes);
    double fine = 1e-6, coarse = 1e6;
    for (int i = 0; i < 60; ++i) {
        const double middle = std::sqrt(fine * coarse);
        (counter.count(static_cast<float>(middle)) <= budget ? coarse : fine) = middle;
    }
    return static_cast<float>(coarse);
}

RadiosityMesh::~RadiosityMesh() = default;

RadiosityMesh::RadiosityMesh(const Scene& scene, const SceneGeometry& geometry, float patchSize, int planeRings,
                             std::span<const std::uint8_t> buried, bool cutPlanes)
    : geometry_(geometry),
      welder_(std::make_unique<VertexWelder>(VertexWelder{std::max(patchSize * 1e-3f, 1e-6f), {}, vertexCount_})),
      patchSize_(patchSize),
      planeRings_(planeRings) {
    VertexWelder& welder = *welder_;
    sourceStart_.assign(geometry.primitiveCount() + 1, 0);
    const auto begin = [&](std::uint32_t id) { sourceStart_[id] = static_cast<std::uint32_t>(sources_.size()); };
    // A kind with a patch grid is cut into its cells; every other kind's patches are its
    // tessellation's triangles (over the scene's region, if unbounded), each subdivided as a
    // triangle.
    const Bounds region = sceneRegion(scene, geometry);
    std::vector<Triangle> scratch;
    std::vector<Piece> pieces;
    std::vector<Clustering> clustering;
    for (std::uint32_t i = 0; i < geometry.shapes().size(); ++i) {
        begin(geometry.shapeId(i));
        const ShapeRecord& shape = geometry.shapes()[i];
        if (shape.ops->patchGrid) {
            addGrid(i, clustering);
            continue;
        }
        tessellateRecord(shape, patchSize, planeRings, region, cutPlanes ? &geometry : nullptr, scratch, pieces);
        for (const Piece& p : pieces)
            addTriangle(&shape, geometry.shapeId(i), shape.object, p.triangle.a, p.triangle.b, p.triangle.c, p.patchSize,
                        false, welder, clustering);
    }
    for (std::uint32_t i = 0; i < geometry.triangles().size(); ++i) {
        begin(geometry.triangleId(i));
        const Triangle& t = geometry.triangles()[i];
        addTriangle(nullptr, geometry.triangleId(i), t.object, t.a, t.b, t.c, patchSize, !buried.empty() && buried[i] != 0,
                    welder, clustering);
    }
    sourceStart_.back() = static_cast<std::uint32_t>(sources_.size());
    indexSources();
    buildClusters(clustering);
    // Every patch is a root: node i holds patch i (node 0 is never a child, so firstChild 0 is "none").
    nodes_.resize(patches_.size());
    leafNode_.resize(patches_.size());
    for (std::uint32_t i = 0; i < patches_.size(); ++i) {
        nodes_[i].patch = i;
        leafNode_[i] = i;
    }
}

bool RadiosityMesh::splittable(std::uint32_t patch) const {
    const RadiosityPatch& p = patches_[patch];
    return p.vertexCount == 3 && clusters_[p.cluster].memberCount == 1;
}

void RadiosityMesh::split(std::span<const std::uint32_t> cut) {
    for (std::uint32_t id : cut) {
        if (!splittable(id)) throw std::logic_error("radiosity: split() asked to cut a patch that is not a lone triangle");
        const RadiosityPatch parent = patches_[id];
        const Vec3 ab = 0.5f * (parent.a + parent.b), bc = 0.5f * (parent.b + parent.c), ca = 0.5f * (parent.c + parent.a);
        const std::uint32_t vab = welder_->vertex(parent.object, ab, parent.normal);
        const std::uint32_t vbc = welder_->vertex(parent.object, bc, parent.normal);
        const std::uint32_t vca = welder_->vertex(parent.object, ca, parent.normal);
        const std::uint32_t va = parent.vertices[0], vb = parent.vertices[1], vc = parent.vertices[2];
        // The corners' children, then the middle one (bc, ca, ab), whose winding keeps the normal.
        const std::array<std::array<Vec3, 3>, 4> corners{{{parent.a, ab, ca}, {ab, parent.b, bc}, {ca, bc, parent.c}, {bc, ca, ab}}};
        const std::array<std::array<std::uint32_t, 3>, 4> ids{{{va, vab, vca}, {vab, vb, vbc}, {vca, vbc, vc}, {vbc, vca, vab}}};
        const std::uint32_t node = leafNode_[id];
        const auto firstChild = static_cast<std::uint32_t>(nodes_.size());
        nodes_[node].firstChild = firstChild;
        for (int k = 0; k < 4; ++k) {
            RadiosityPatch child = parent;
            child.a = corners[k][0];
            child.b = corners[k][1];
            child.c = corners[k][2];
            child.vertices = {ids[k][0], ids[k][1], ids[k][2], 0};
            child.area = 0.25f * parent.area;
            child.level = parent.level + 1;
            std::uint32_t patch = id;
            if (k > 0) {
                patch = static_cast<std::uint32_t>(patches_.size());
                child.cluster = static_cast<std::uint32_t>(clusters_.size());
                clusters_.push_back({parent.object, static_cast<std::uint32_t>(members_.size()), 1, child.area});
                members_.push_back(patch);
                memberCdf_.push_back(1.0f);
                patches_.push_back(child);
                leafNode_.push_back(0);
            } else {
                patches_[id] = child;
                clusters_[parent.cluster].area = child.area;
            }
            nodes_.push_back({patch, 0});
            leafNode_[patch] = firstChild + std::uint32_t(k);
        }
    }
}

PatchLookup RadiosityMesh::descend(std::uint32_t node, float s, float t) const {
    // (s, t): the point's coordinates along the node's triangle's edges b - a and c - a; each
    // level maps them into the child holding the point (split()'s order).
    while (nodes_[node].firstChild != 0) {
        const std::uint32_t first = nodes_[node].firstChild;
        if (s + t <= 0.5f) {
            node = first;
            s *= 2.0f;
            t *= 2.0f;
        } else if (s >= 0.5f) {
            node = first + 1;
            s = 2.0f * s - 1.0f;
            t *= 2.0f;
        } else if (t >= 0.5f) {
            node = first + 2;
            s *= 2.0f;
            t = 2.0f * t - 1.0f;
        } else {
            node = first + 3;
            s = 1.0f - 2.0f * s;
            t = 1.0f - 2.0f * t;
        }
    }
    s = std::clamp(s, 0.0f, 1.0f);
    t = std::clamp(t, 0.0f, 1.0f - s);
    PatchLookup found;
    found.patch = nodes_[node].patch;
    found.weights = {1.0f - s - t, s, t, 0.0f};
    return found;
}

void RadiosityMesh::buildClusters(const std::vector<Clustering>& clustering) {
    // Cluster ids in the order of each cluster's first patch: a mesh with nothing to cluster has
    // cluster i = patch i.
    std::unordered_map<ClusterKey, std::uint32_t, ClusterKeyHash> ids;
    std::vector<std::uint32_t> memberCount;
    clusters_.clear();
    for (std::uint32_t i = 0; i < patches_.size(); ++i) {
        RadiosityPatch& p = patches_[i];
        std::uint32_t id = static_cast<std::uint32_t>(clusters_.size());
        if (clustering[i] != Clustering::Alone)
            id = ids.try_emplace(clusterKey(p.object, p.a, p.b, p.c, patchSize_, clustering[i] == Clustering::Buried), id)
                     .first->second;
        if (id == clusters_.size()) {
            clusters_.push_back({p.object, 0, 0, 0.0f});
            memberCount.push_back(0);
        }
        p.cluster = id;
        ++memberCount[id];
        clusters_[id].area += p.area;
    }
    std::uint32_t first = 0;
    for (std::uint32_t c = 0; c < clusters_.size(); ++c) {
        clusters_[c].firstMember = first;
        first += memberCount[c];
    }
    members_.assign(patches_.size(), 0);
    memberCdf_.assign(patches_.size(), 0.0f);
    for (std::uint32_t i = 0; i < patches_.size(); ++i) {
        RadiosityCluster& c = clusters_[patches_[i].cluster];
        members_[c.firstMember + c.memberCount++] = i;
    }
    for (std::uint32_t c = 0; c < clusters_.size(); ++c) {
        setMemberCdf(c);
        tightenCluster(c);
    }
}

std::uint32_t RadiosityMesh::octant(std::uint32_t patch, std::uint32_t depth) const {
    // clusterKey's cells halved depth times: the quotient by a power of two rounds as the cell's
    // own, so a cell at depth d is exactly the union of its eighths at d + 1.
    const RadiosityPatch& p = patches_[patch];
    const Vec3 centroid = centroidOf(p.a, p.b, p.c);
    const double side = std::ldexp(kClusterCell * patchSize_, -static_cast<int>(depth));
    std::uint32_t code = 0;
    for (int axis = 0; axis < 3; ++axis)
        code |= static_cast<std::uint32_t>(static_cast<std::int64_t>(std::floor(double(centroid[axis]) / side)) & 1) << axis;
    return code;
}

void RadiosityMesh::tightenCluster(std::uint32_t cluster) {
    RadiosityCluster& c = clusters_[cluster];
    if (c.memberCount < 2) return;
    while (c.depth < kMaxClusterDepth) {
        const std::uint32_t first = octant(members_[c.firstMember], c.depth + 1);
        for (std::uint32_t i = 1; i < c.memberCount; ++i)
            if (octant(members_[c.firstMember + i], c.depth + 1) != first) return;
        ++c.depth;
    }
}

void RadiosityMesh::setMemberCdf(std::uint32_t cluster) {
    const RadiosityCluster& c = clusters_[cluster];
    float areaSoFar = 0.0f;
    for (std::uint32_t i = c.firstMember; i < c.firstMember + c.memberCount; ++i) {
        areaSoFar += patches_[members_[i]].area;
        memberCdf_[i] = areaSoFar / c.area;
    }
    memberCdf_[c.firstMember + c.memberCount - 1] = 1.0f;
}

bool RadiosityMesh::clusterSplittable(std::uint32_t cluster) const {
    const RadiosityCluster& c = clusters_[cluster];
    return c.memberCount > 1 && c.depth < kMaxClusterDepth;  // tightenCluster: then its members span eighths
}

std::uint32_t RadiosityMesh::clusterPart(std::uint32_t patch) const {
    return octant(patch, clusters_[patches_[patch].cluster].depth + 1);
}

std::uint32_t RadiosityMesh::clusterParts(std::uint32_t cluster) const {
    const RadiosityCluster& c = clusters_[cluster];
    std::uint32_t occupied = 0;
    for (std::uint32_t i = 0; i < c.memberCount; ++i) occupied |= 1u << octant(members_[c.firstMember + i], c.depth + 1);
    return static_cast<std::uint32_t>(std::popcount(occupied));
}

void RadiosityMesh::splitClusters(std::span<const std::uint32_t> cut) {
    // Hierarchical refinement of clusters (Smits, Arvo and Greenberg 1994 refine a cluster into its
    // children where the transport's error bound asks; here a cluster's children are the occupied
    // eighths of its cell, and the error is the solve's, radiosity.cpp, clustersToRefine). A part's
    // members stay a contiguous range of members_, so nothing else moves.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> coded;  // (eighth, member)
    for (std::uint32_t id : cut) {
        if (!clusterSplittable(id)) throw std::logic_error("radiosity: splitClusters() asked to cut a cluster that is not splittable");
        const RadiosityCluster parent = clusters_[id];
        const std::uint32_t depth = parent.depth + 1;
        coded.clear();
        for (std::uint32_t i = 0; i < parent.memberCount; ++i) {
            const std::uint32_t member = members_[parent.firstMember + i];
            coded.emplace_back(octant(member, depth), member);
        }
        std::stable_sort(coded.begin(), coded.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
        for (std::size_t i = 0; i < coded.size();) {
            std::size_t j = i;
            const auto cluster = i == 0 ? id : static_cast<std::uint32_t>(clusters_.size());
            RadiosityCluster part{parent.object, parent.firstMember + std::uint32_t(i), 0, 0.0f, depth};
            for (; j < coded.size() && coded[j].first == coded[i].first; ++j) {
                members_[parent.firstMember + j] = coded[j].second;
                patches_[coded[j].second].cluster = cluster;
                part.area += patches_[coded[j].second].area;
            }
            part.memberCount = static_cast<std::uint32_t>(j - i);
            if (i == 0) {
                clusters_[id] = part;
            } else {
                clusters_.push_back(part);
            }
            setMemberCdf(cluster);
            tightenCluster(cluster);
            i = j;
        }
    }
}

PatchPoint RadiosityMesh::sampleClusterPoint(std::uint32_t cluster, Vec2 u) const {
    const RadiosityCluster& c = clusters_[cluster];
    if (c.memberCount == 1) return samplePoint(members_[c.firstMember], u);
    const auto begin = memberCdf_.begin() + c.firstMember, end = begin + c.memberCount;
    const auto it = std::min(std::upper_bound(begin, end, u.x), end - 1);
    const float low = it == begin ? 0.0f : *(it - 1);
    const float width = *it - low;
    u.x = width > 0.0f ? std::clamp((u.x - low) / width, 0.0f, kBelowOne) : 0.5f;
    return samplePoint(members_[c.firstMember + std::uint32_t(it - memberCdf_.begin() - c.firstMember)], u);
}

void RadiosityMesh::addTriangle(const ShapeRecord* record, std::uint32_t primitive, std::uint32_t object,
                                const Vec3& a, const Vec3& b, const Vec3& c, float patchSize, bool buried,
                                VertexWelder& welder, std::vector<Clustering>& clustering) {
    if (!hasArea(a, b, c)) return;
    const std::uint32_t n = triangleSubdivisions(a, b, c, patchSize);
    sources_.push_back({record, primitive, static_cast<std::uint32_t>(patches_.size()), n, PatchGrid{}, a, b, c});
    const Vec3 normal = glm::normalize(glm::cross(b - a, c - a));
    const Vec3 du = (b - a) / float(n), dv = (c - a) / float(n);
    const auto gridPoint = [&](std::uint32_t i, std::uint32_t j) { return a + float(i) * du + float(j) * dv; };
    // Grid vertex ids, row by row: (i, j) for i + j <= n.
    std::vector<std::uint32_t> grid;
    std::vector<std::uint32_t> gridRow(n + 2);
    for (std::uint32_t j = 0; j <= n; ++j) {
        gridRow[j] = static_cast<std::uint32_t>(grid.size());
        for (std::uint32_t i = 0; i + j <= n; ++i) grid.push_back(welder.vertex(object, gridPoint(i, j), normal));
    }
    const auto vertexAt = [&](std::uint32_t i, std::uint32_t j) { return grid[gridRow[j] + i]; };
    const float area = 0.5f * glm::length(glm::cross(du, dv));
    for (std::uint32_t j = 0; j < n; ++j) {
        for (std::uint32_t i = 0; i + j < n; ++i) {
            RadiosityPatch lower;
            lower.primitive = primitive;
            lower.object = object;
            lower.a = gridPoint(i, j);
            lower.b = gridPoint(i + 1, j);
            lower.c = gridPoint(i, j + 1);
            lower.normal = normal;
            lower.area = area;
            lower.vertices = {vertexAt(i, j), vertexAt(i + 1, j), vertexAt(i, j + 1), 0};
            patches_.push_back(lower);
            clustering.push_back(n != 1 ? Clustering::Alone : buried ? Clustering::Buried : Clustering::Exposed);
            if (i + j + 1 < n) {
                RadiosityPatch upper = lower;
                upper.a = gridPoint(i + 1, j + 1);
                upper.b = gridPoint(i, j + 1);
                upper.c = gridPoint(i + 1, j);
                upper.vertices = {vertexAt(i + 1, j + 1), vertexAt(i, j + 1), vertexAt(i + 1, j), 0};
                patches_.push_back(upper);
                clustering.push_back(Clustering::Alone);
            }
        }
    }
}

void RadiosityMesh::addGrid(std::uint32_t shapeIndex, std::vector<Clustering>& clustering) {
    const ShapeRecord& shape = geometry_.shapes()[shapeIndex];
    const PatchGridOps& cells = *shape.ops->patchGrid;
    const PatchGrid grid = cells.cells(shape, patchSize_);
    if (grid.rows == 0 || grid.columns == 0) return;
    const auto source = static_cast<std::uint32_t>(sources_.size());
    sources_.push_back({&shape, geometry_.shapeId(shapeIndex), static_cast<std::uint32_t>(patches_.size()), 0, grid,
                        Vec3{0.0f}, Vec3{0.0f}, Vec3{0.0f}});
    // The grid's corners are this mesh's vertices first .. first + grid.corners - 1.
    const auto first = static_cast<std::uint32_t>(vertexCount_);
    vertexCount_ += grid.corners;
    const auto vertexAt = [&](std::uint32_t row, std::uint32_t column) { return first + cells.corner(grid, row, column); };
    for (std::uint32_t row = 0; row < grid.rows; ++row) {
        for (std::uint32_t column = 0; column < grid.columns; ++column) {
            RadiosityPatch p;
            p.primitive = geometry_.shapeId(shapeIndex);
            p.object = shape.object;
            p.row = row;
            p.column = column;
            p.source = source;
            p.area = cells.cellArea(shape, grid, row, column);
            p.vertices = {vertexAt(row, column), vertexAt(row, column + 1), vertexAt(row + 1, column),
                          vertexAt(row + 1, column + 1)};
            p.vertexCount = 4;
            patches_.push_back(p);
            clustering.push_back(Clustering::Alone);
        }
    }
}

PatchPoint RadiosityMesh::samplePoint(std::uint32_t patch, Vec2 u) const {
    const RadiosityPatch& p = patches_[patch];
    if (p.vertexCount == 3) {
        const Vec3 b = sampleUniformTriangle(u);
        return {b.x * p.a + b.y * p.b + b.z * p.c, p.normal, patch};
    }
    const Source& source = sources_[p.source];
    const AreaSample s = source.record->ops->patchGrid->sampleCell(*source.record, source.grid, p.row, p.column, u);
    return {s.point, s.normal, patch};
}

void RadiosityMesh::indexSources() {
    sourceIndexOf_.assign(sourceStart_.size() - 1, 0);
    std::vector<CoplanarTriangleIndex::Corners> corners;
    for (std::size_t id = 0; id + 1 < sourceStart_.size(); ++id) {
        const std::uint32_t first = sourceStart_[id], last = sourceStart_[id + 1];
        if (last - first <= kScannedSources || sources_[first].grid.rows != 0) continue;
        corners.clear();
        for (std::uint32_t s = first; s < last; ++s) corners.push_back({sources_[s].a, sources_[s].b, sources_[s].c});
        // lookupTriangle's slack reaches at most 2e-4 of a triangle's longest edge past it.
        if (auto index = CoplanarTriangleIndex::build(corners, 1e-3f)) {
            sourceIndexes_.push_back(std::move(*index));
            sourceIndexOf_[id] = static_cast<std::uint32_t>(sourceIndexes_.size());
        }
    }
}

std::optional<PatchLookup> RadiosityMesh::lookup(const SurfaceHit& hit) const {
    if (hit.primitive + 1 >= sourceStart_.size()) return std::nullopt;
    const std::uint32_t first = sourceStart_[hit.primitive], last = sourceStart_[hit.primitive + 1];
    if (first == last) return std::nullopt;
    if (sources_[first].grid.rows != 0) return lookupCell(sources_[first], hit.point);
    // One of a tessellation's triangles holds the point; the only triangle of a primitive takes
    // it even if the point rounds outside.
    const bool several = last - first > 1;
    if (const std::uint32_t index = sourceIndexOf_[hit.primitive]; index != 0) {
        // The first source in order that holds the point, as the scan below would find it: the
        // index's candidates include every source that does.
        std::uint32_t best = last;
        std::optional<PatchLookup> found;
        sourceIndexes_[index - 1].forEachCandidate(hit.point, [&](std::uint32_t i) {
            if (first + i >= best) return;
            if (auto f = lookupTriangle(sources_[first + i], hit.point, true)) {
                best = first + i;
                found = f;
            }
        });
        if (found) return found;
    } else {
        for (std::uint32_t s = first; s < last; ++s)
            if (auto found = lookupTriangle(sources_[s], hit.point, several)) return found;
    }
    // A curved outline's hit may lie just outside its tessellation (between a chord and the
    // arc): the nearest piece's patch, its coordinates clamped onto it. An unbounded shape's hit
    // outside the region its triangles cover has none.
    const ShapeRecord* record = sources_[first].record;
    if (!several) return std::nullopt;
    const bool unbounded = record && !record->ops->bounded;
    if (unbounded && planeRings_ == 0) return std::nullopt;  // clipped: nothing beyond the rectangle
    std::uint32_t nearest = first;
    float nearestDistance = std::numeric_limits<float>::infinity();
    for (std::uint32_t s = first; s < last; ++s) {
        const Source& source = sources_[s];
        // An unbounded shape's hit beyond its last ring: the ring's nearest point (addRings).
        const float distance = unbounded ? glm::length(hit.point - closestPoint(source, hit.point))
                                         : glm::length(hit.point - (source.a + source.b + source.c) / 3.0f);
        if (distance < nearestDistance) {
            nearestDistance = distance;
            nearest = s;
        }
    }
    return lookupTriangle(sources_[nearest], unbounded ? closestPoint(sources_[nearest], hit.point) : hit.point, false);
}

std::optional<PatchLookup> RadiosityMesh::lookupTriangle(const Source& source, const Vec3& point, bool strict) const {
    // The point's coordinates (s, t) along the edges b - a and c - a (least squares, so a point
    // slightly off the plane still projects onto it).
    const Vec3 e1 = source.b - source.a, e2 = source.c - source.a, d = point - source.a;
    const double d00 = glm::dot(e1, e1), d01 = glm::dot(e1, e2), d11 = glm::dot(e2, e2);
    const double d20 = glm::dot(d, e1), d21 = glm::dot(d, e2);
    const double denominator = d00 * d11 - d01 * d01;
    if (!(denominator > 0.0)) return std::nullopt;
    double s = (d11 * d20 - d01 * d21) / denominator, t = (d00 * d21 - d01 * d20) / denominator;
    constexpr double kSlack = 1e-4;  // hits on an edge, within roundoff
    if (strict && (s < -kSlack || t < -kSlack || s + t > 1.0 + kSlack)) return std::nullopt;
    s = std::max(s, 0.0);
    t = std::max(t, 0.0);
    if (s + t > 1.0) {
        const double scale = 1.0 / (s + t);
        s *= scale;
        t *= scale;
    }
    const std::uint32_t n = source.n;
    const double gs = s * n, gt = t * n;
    const auto j = static_cast<std::uint32_t>(std::min<double>(std::floor(gt), n - 1));
    const auto i = static_cast<std::uint32_t>(std::min<double>(std::floor(gs), n - 1 - j));
    const auto fs = static_cast<float>(gs - i), ft = static_cast<float>(gt - j);
    PatchLookup found;
    if (fs + ft <= 1.0f || i + j + 1 >= n) {
        found = descend(source.firstNode + rowStart(n, j) + 2 * i, fs, ft);
    } else {
        // The upper triangle (i+1, j+1), (i, j+1), (i+1, j): its own coordinates are 1 - fs, 1 - ft.
        found = descend(source.firstNode + rowStart(n, j) + 2 * i + 1, 1.0f - fs, 1.0f - ft);
    }
    const float sum = found.weights[0] + found.weights[1] + found.weights[2];
    for (float& w : found.weights) w /= sum;
    return found;
}

Vec3 RadiosityMesh::closestPoint(const Source& source, const Vec3& point) {
    // Ericson, Real-Time Collision Detection (2005), 5.1.5: the point's Voronoi region of the triangle.
    const Vec3 a = source.a, b = source.b, c = source.c;
    const Vec3 ab = b - a, ac = c - a, ap = point - a;
    const float d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0.0f && d2 <= 0.0f) return a;
    const Vec3 bp = point - b;
    const float d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0.0f && d4 <= d3) return b;
    const float vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0f && d1 >= 0.0f && d3 <= 0.0f) return a + (d1 / (d1 - d3)) * ab;
    const Vec3 cp = point - c;
    const float d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0.0f && d5 <= d6) return c;
    const float vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0f && d2 >= 0.0f && d6 <= 0.0f) return a + (d2 / (d2 - d6)) * ac;
    const float va = d3 * d6 - d5 * d4;
    if (va <= 0.0f && (d4 - d3) >= 0.0f && (d5 - d6) >= 0.0f) return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
    const float denominator = 1.0f / (va + vb + vc);
    return a + ab * (vb * denominator) + ac * (vc * denominator);
}

PatchLookup RadiosityMesh::lookupCell(const Source& source, const Vec3& point) const {
    const GridPoint at = source.record->ops->patchGrid->locate(*source.record, source.grid, point);
    const float fr = at.fraction.x, fc = at.fraction.y;
    PatchLookup found;
    found.patch = source.firstNode + at.row * source.grid.columns + at.column;
    found.weights = {(1.0f - fr) * (1.0f - fc), (1.0f - fr) * fc, fr * (1.0f - fc), fr * fc};
    return found;
}

}  // namespace lightpath
