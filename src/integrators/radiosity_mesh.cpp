#include "integrators/radiosity_mesh.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

#include "math/random.h"
#include "sampling/warp.h"
#include "shapes/sphere.h"

namespace lightpath {
namespace {

// No primitive is cut finer than this per edge: a huge triangle at a tiny patch size would
// otherwise overflow the counts (the integrator's patch limit refuses such meshes anyway).
constexpr double kMaxSubdivisions = 1 << 15;

std::uint32_t triangleSubdivisions(const Vec3& a, const Vec3& b, const Vec3& c, float patchSize) {
    const double longest = std::max({glm::length(b - a), glm::length(c - b), glm::length(a - c)});
    return static_cast<std::uint32_t>(std::clamp(std::ceil(longest / patchSize), 1.0, kMaxSubdivisions));
}

bool hasArea(const Vec3& a, const Vec3& b, const Vec3& c) {
    const float area2 = glm::length(glm::cross(b - a, c - a));
    return std::isfinite(area2) && area2 > 0.0f;
}

// Sub-triangle layout of an n x n triangle grid: row j (0..n-1) holds the lower triangles
// (i, j) for i < n - j at even offsets and the upper ones (i < n - j - 1) at odd offsets.
std::uint32_t rowStart(std::uint32_t n, std::uint32_t j) { return j * (2 * n - j); }

}  // namespace

SphereCells sphereCells(float radius, float patchSize) {
    const double bands = std::clamp(std::ceil(2.0 * radius / patchSize), 2.0, kMaxSubdivisions);
    const double sectors = std::clamp(std::ceil(2.0 * kPi * radius / patchSize), 4.0, kMaxSubdivisions);
    return {static_cast<std::uint32_t>(bands), static_cast<std::uint32_t>(sectors)};
}

Vec3 sphereDirection(float z, float phi) {
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    return {r * std::cos(phi), r * std::sin(phi), z};
}

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

std::array<Triangle, 2> clipPlane(const Scene& scene, const Plane& plane) {
    Vec3 lo{std::numeric_limits<float>::max()}, hi{-std::numeric_limits<float>::max()};
    const auto grow = [&](const Vec3& p) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    };
    for (const Sphere& s : scene.spheres) {
        grow(s.center - Vec3{s.radius});
        grow(s.center + Vec3{s.radius});
    }
    for (const ShapeRecord& s : scene.shapes) {
        const Bounds box = s.ops->bounds(s);
        grow(box.lo);
        grow(box.hi);
    }
    for (const Triangle& t : scene.triangles) {
        grow(t.a);
        grow(t.b);
        grow(t.c);
    }
    for (const LightSlot& l : scene.lights) grow(l->position());
    grow(scene.camera.eye);
    grow(plane.point);
    const Vec3 margin{std::max(0.5f * glm::length(hi - lo), 1.0f)};
    lo -= margin;
    hi += margin;

    // The box's corners projected onto the plane, in a basis (s, t) with s x t = normal.
    const Frame frame(plane.normal);
    float sMin = std::numeric_limits<float>::max(), sMax = -sMin, tMin = sMin, tMax = -sMin;
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3 p{corner & 1 ? hi.x : lo.x, corner & 2 ? hi.y : lo.y, corner & 4 ? hi.z : lo.z};
        const Vec3 d = p - plane.point;
        sMin = std::min(sMin, glm::dot(d, frame.s));
        sMax = std::max(sMax, glm::dot(d, frame.s));
        tMin = std::min(tMin, glm::dot(d, frame.t));
        tMax = std::max(tMax, glm::dot(d, frame.t));
    }
    const auto at = [&](float s, float t) { return plane.point + s * frame.s + t * frame.t; };
    const Vec3 a = at(sMin, tMin), b = at(sMax, tMin), c = at(sMax, tMax), d = at(sMin, tMax);
    return {Triangle{a, b, c, plane.object}, Triangle{a, c, d, plane.object}};
}

std::size_t RadiosityMesh::countPatches(const Scene& scene, const SceneGeometry& geometry, float patchSize) {
    std::size_t count = 0;
    const auto addTriangle = [&](const Triangle& t) {
        if (!hasArea(t.a, t.b, t.c)) return;
        const std::size_t n = triangleSubdivisions(t.a, t.b, t.c, patchSize);
        count += n * n;
    };
    std::vector<Triangle> pieces;
    for (const ShapeRecord& shape : geometry.shapes()) {
        if (shape.ops == &kSphereOps) {
            const SphereCells cells = sphereCells(sphereOf(shape).radius, patchSize);
            count += std::size_t{cells.bands} * cells.sectors;
            continue;
        }
        if (!shape.ops->bounded) {
            for (const Triangle& t : clipPlane(scene, planeOf(shape))) addTriangle(t);
            continue;
        }
        pieces.clear();
        shape.ops->tessellate(shape, patchSize, pieces);
        for (const Triangle& t : pieces) addTriangle(t);
    }
    for (const Triangle& t : geometry.triangles()) addTriangle(t);
    return count;
}

float RadiosityMesh::patchSizeForBudget(const Scene& scene, const SceneGeometry& geometry, std::size_t budget) {
    // The count falls as the size grows: bisect log(size) between a size too fine and one coarse
    // enough to leave one patch per triangle (the least any mesh can have).
    double fine = 1e-6, coarse = 1e6;
    for (int i = 0; i < 60; ++i) {
        const double middle = std::sqrt(fine * coarse);
        (countPatches(scene, geometry, static_cast<float>(middle)) <= budget ? coarse : fine) = middle;
    }
    return static_cast<float>(coarse);
}

RadiosityMesh::RadiosityMesh(const Scene& scene, const SceneGeometry& geometry, float patchSize)
    : geometry_(geometry), patchSize_(patchSize) {
    VertexWelder welder{std::max(patchSize * 1e-3f, 1e-6f), {}, vertexCount_};
    sourceStart_.assign(geometry.primitiveCount() + 1, 0);
    const auto begin = [&](std::uint32_t id) { sourceStart_[id] = static_cast<std::uint32_t>(sources_.size()); };
    // A sphere's patches are latitude-longitude cells, an unbounded shape's (a plane's) the
    // rectangle over the scene's bounds; every other kind's are its tessellation's triangles,
    // each subdivided as a triangle.
    std::vector<Triangle> pieces;
    for (std::uint32_t i = 0; i < geometry.shapes().size(); ++i) {
        begin(geometry.shapeId(i));
        const ShapeRecord& shape = geometry.shapes()[i];
        if (shape.ops == &kSphereOps) {
            addSphere(i);
            continue;
        }
        if (!shape.ops->bounded) {
            for (const Triangle& t : clipPlane(scene, planeOf(shape)))
                addTriangle(ShapeKind::Plane, geometry.shapeId(i), shape.object, t.a, t.b, t.c, welder);
            continue;
        }
        pieces.clear();
        shape.ops->tessellate(shape, patchSize, pieces);
        for (const Triangle& t : pieces)
            addTriangle(ShapeKind::Registered, geometry.shapeId(i), shape.object, t.a, t.b, t.c, welder);
    }
    for (std::uint32_t i = 0; i < geometry.triangles().size(); ++i) {
        begin(geometry.triangleId(i));
        const Triangle& t = geometry.triangles()[i];
        addTriangle(ShapeKind::Triangle, geometry.triangleId(i), t.object, t.a, t.b, t.c, welder);
    }
    sourceStart_.back() = static_cast<std::uint32_t>(sources_.size());
}

void RadiosityMesh::addTriangle(ShapeKind shape, std::uint32_t primitive, std::uint32_t object, const Vec3& a,
                                const Vec3& b, const Vec3& c, VertexWelder& welder) {
    if (!hasArea(a, b, c)) return;
    const std::uint32_t n = triangleSubdivisions(a, b, c, patchSize_);
    sources_.push_back({shape, primitive, static_cast<std::uint32_t>(patches_.size()), n, 0, 0, a, b, c});
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
            lower.shape = shape;
            lower.primitive = primitive;
            lower.object = object;
            lower.a = gridPoint(i, j);
            lower.b = gridPoint(i + 1, j);
            lower.c = gridPoint(i, j + 1);
            lower.normal = normal;
            lower.area = area;
            lower.vertices = {vertexAt(i, j), vertexAt(i + 1, j), vertexAt(i, j + 1), 0};
            patches_.push_back(lower);
            if (i + j + 1 < n) {
                RadiosityPatch upper = lower;
                upper.a = gridPoint(i + 1, j + 1);
                upper.b = gridPoint(i, j + 1);
                upper.c = gridPoint(i + 1, j);
                upper.vertices = {vertexAt(i + 1, j + 1), vertexAt(i, j + 1), vertexAt(i + 1, j), 0};
                patches_.push_back(upper);
            }
        }
    }
}

void RadiosityMesh::addSphere(std::uint32_t sphereIndex) {
    const Sphere sphere = sphereOf(geometry_.shapes()[sphereIndex]);
    const SphereCells cells = sphereCells(sphere.radius, patchSize_);
    const std::uint32_t bands = cells.bands, sectors = cells.sectors;
    sources_.push_back({ShapeKind::Sphere, geometry_.shapeId(sphereIndex), static_cast<std::uint32_t>(patches_.size()),
                        0, bands, sectors, Vec3{0.0f}, Vec3{0.0f}, Vec3{0.0f}});
    // Vertices: the two poles, then rings 1..bands-1 of `sectors` each (phi wraps around).
    const auto first = static_cast<std::uint32_t>(vertexCount_);
    vertexCount_ += 2 + std::size_t{bands - 1} * sectors;
    const auto vertexAt = [&](std::uint32_t ring, std::uint32_t sector) -> std::uint32_t {
        if (ring == 0) return first;
        if (ring == bands) return first + 1;
        return first + 2 + (ring - 1) * sectors + sector % sectors;
    };
    const float area = 4.0f * kPi * sphere.radius * sphere.radius / float(bands * sectors);
    for (std::uint32_t ring = 0; ring < bands; ++ring) {
        for (std::uint32_t sector = 0; sector < sectors; ++sector) {
            RadiosityPatch p;
            p.shape = ShapeKind::Sphere;
            p.primitive = geometry_.shapeId(sphereIndex);
            p.object = sphere.object;
            p.z0 = 1.0f - 2.0f * float(ring) / float(bands);
            p.z1 = 1.0f - 2.0f * float(ring + 1) / float(bands);
            p.phi0 = 2.0f * kPi * float(sector) / float(sectors);
            p.phi1 = 2.0f * kPi * float(sector + 1) / float(sectors);
            p.area = area;
            p.vertices = {vertexAt(ring, sector), vertexAt(ring, sector + 1), vertexAt(ring + 1, sector),
                          vertexAt(ring + 1, sector + 1)};
            p.vertexCount = 4;
            patches_.push_back(p);
        }
    }
}

PatchPoint RadiosityMesh::samplePoint(std::uint32_t patch, Vec2 u) const {
    const RadiosityPatch& p = patches_[patch];
    if (p.shape != ShapeKind::Sphere) {
        const Vec3 b = sampleUniformTriangle(u);
        return {b.x * p.a + b.y * p.b + b.z * p.c, p.normal};
    }
    // Uniform in z and phi is uniform by area on the sphere.
    const Sphere sphere = sphereOf(*geometry_.shapeOf(p.primitive));
    const float z = p.z0 + (p.z1 - p.z0) * u.x;
    const float phi = p.phi0 + (p.phi1 - p.phi0) * u.y;
    const Vec3 n = sphereDirection(z, phi);
    return {sphere.center + sphere.radius * n, n};
}

std::optional<PatchLookup> RadiosityMesh::lookup(const SurfaceHit& hit) const {
    if (hit.primitive + 1 >= sourceStart_.size()) return std::nullopt;
    const std::uint32_t first = sourceStart_[hit.primitive], last = sourceStart_[hit.primitive + 1];
    for (std::uint32_t s = first; s < last; ++s) {
        const Source& source = sources_[s];
        if (source.shape == ShapeKind::Sphere) return lookupSphere(source, hit.point);
        if (auto found = lookupTriangle(source, hit.point)) return found;
    }
    // A curved outline's hit may lie just outside its tessellation (between a chord and the
    // arc): the nearest piece's patch, its coordinates clamped onto it.
    if (first == last || sources_[first].shape != ShapeKind::Registered) return std::nullopt;
    std::uint32_t nearest = first;
    float nearestDistance = std::numeric_limits<float>::infinity();
    for (std::uint32_t s = first; s < last; ++s) {
        const Source& source = sources_[s];
        const float distance = glm::length(hit.point - (source.a + source.b + source.c) / 3.0f);
        if (distance < nearestDistance) {
            nearestDistance = distance;
            nearest = s;
        }
    }
    return lookupTriangle(sources_[nearest], hit.point, false);
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
    const bool oneOfMany = source.shape == ShapeKind::Plane || source.shape == ShapeKind::Registered;
    if (strict && oneOfMany && (s < -kSlack || t < -kSlack || s + t > 1.0 + kSlack)) return std::nullopt;
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
        found.patch = source.firstPatch + rowStart(n, j) + 2 * i;
        found.weights = {std::max(0.0f, 1.0f - fs - ft), fs, ft, 0.0f};
    } else {
        // The upper triangle (i+1, j+1), (i, j+1), (i+1, j).
        found.patch = source.firstPatch + rowStart(n, j) + 2 * i + 1;
        found.weights = {fs + ft - 1.0f, 1.0f - fs, 1.0f - ft, 0.0f};
    }
    const float sum = found.weights[0] + found.weights[1] + found.weights[2];
    for (float& w : found.weights) w /= sum;
    return found;
}

PatchLookup RadiosityMesh::lookupSphere(const Source& source, const Vec3& point) const {
    const Sphere sphere = sphereOf(*geometry_.shapeOf(source.primitive));
    const Vec3 n = (point - sphere.center) / sphere.radius;
    const float z = std::clamp(n.z, -1.0f, 1.0f);
    float phi = std::atan2(n.y, n.x);
    if (phi < 0.0f) phi += 2.0f * kPi;
    const float gz = (1.0f - z) * 0.5f * float(source.bands);
    const float gp = phi / (2.0f * kPi) * float(source.sectors);
    const auto ring = std::min(static_cast<std::uint32_t>(std::max(gz, 0.0f)), source.bands - 1);
    const auto sector = std::min(static_cast<std::uint32_t>(std::max(gp, 0.0f)), source.sectors - 1);
    const float fz = std::clamp(gz - float(ring), 0.0f, 1.0f), fp = std::clamp(gp - float(sector), 0.0f, 1.0f);
    PatchLookup found;
    found.patch = source.firstPatch + ring * source.sectors + sector;
    found.weights = {(1.0f - fz) * (1.0f - fp), (1.0f - fz) * fp, fz * (1.0f - fp), fz * fp};
    return found;
}

}  // namespace lightpath
