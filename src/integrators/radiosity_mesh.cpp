#include "integrators/radiosity_mesh.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

#include "math/random.h"
#include "sampling/warp.h"

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

// The triangles a record without a patch grid is meshed as (geometry/shape.h): its tessellation,
// or an unbounded kind's over `region` (none if it has no tessellateRegion).
void tessellateRecord(const ShapeRecord& shape, float patchSize, const Bounds& region, std::vector<Triangle>& out) {
    out.clear();
    if (shape.ops->bounded) {
        if (shape.ops->tessellate) shape.ops->tessellate(shape, patchSize, out);
    } else if (shape.ops->tessellateRegion) {
        shape.ops->tessellateRegion(shape, region, out);
    }
}

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

std::size_t RadiosityMesh::countPatches(const Scene& scene, const SceneGeometry& geometry, float patchSize) {
    std::size_t count = 0;
    const auto addTriangle = [&](const Triangle& t) {
        if (!hasArea(t.a, t.b, t.c)) return;
        const std::size_t n = triangleSubdivisions(t.a, t.b, t.c, patchSize);
        count += n * n;
    };
    const Bounds region = sceneRegion(scene, geometry);
    std::vector<Triangle> pieces;
    for (const ShapeRecord& shape : geometry.shapes()) {
        if (shape.ops->patchGrid) {
            const PatchGrid grid = shape.ops->patchGrid->cells(shape, patchSize);
            count += std::size_t{grid.rows} * grid.columns;
            continue;
        }
        tessellateRecord(shape, patchSize, region, pieces);
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
    // A kind with a patch grid is cut into its cells; every other kind's patches are its
    // tessellation's triangles (over the scene's region, if unbounded), each subdivided as a
    // triangle.
    const Bounds region = sceneRegion(scene, geometry);
    std::vector<Triangle> pieces;
    for (std::uint32_t i = 0; i < geometry.shapes().size(); ++i) {
        begin(geometry.shapeId(i));
        const ShapeRecord& shape = geometry.shapes()[i];
        if (shape.ops->patchGrid) {
            addGrid(i);
            continue;
        }
        tessellateRecord(shape, patchSize, region, pieces);
        for (const Triangle& t : pieces) addTriangle(&shape, geometry.shapeId(i), shape.object, t.a, t.b, t.c, welder);
    }
    for (std::uint32_t i = 0; i < geometry.triangles().size(); ++i) {
        begin(geometry.triangleId(i));
        const Triangle& t = geometry.triangles()[i];
        addTriangle(nullptr, geometry.triangleId(i), t.object, t.a, t.b, t.c, welder);
    }
    sourceStart_.back() = static_cast<std::uint32_t>(sources_.size());
}

void RadiosityMesh::addTriangle(const ShapeRecord* record, std::uint32_t primitive, std::uint32_t object,
                                const Vec3& a, const Vec3& b, const Vec3& c, VertexWelder& welder) {
    if (!hasArea(a, b, c)) return;
    const std::uint32_t n = triangleSubdivisions(a, b, c, patchSize_);
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

void RadiosityMesh::addGrid(std::uint32_t shapeIndex) {
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
        }
    }
}

PatchPoint RadiosityMesh::samplePoint(std::uint32_t patch, Vec2 u) const {
    const RadiosityPatch& p = patches_[patch];
    if (p.vertexCount == 3) {
        const Vec3 b = sampleUniformTriangle(u);
        return {b.x * p.a + b.y * p.b + b.z * p.c, p.normal};
    }
    const Source& source = sources_[p.source];
    const AreaSample s = source.record->ops->patchGrid->sampleCell(*source.record, source.grid, p.row, p.column, u);
    return {s.point, s.normal};
}

std::optional<PatchLookup> RadiosityMesh::lookup(const SurfaceHit& hit) const {
    if (hit.primitive + 1 >= sourceStart_.size()) return std::nullopt;
    const std::uint32_t first = sourceStart_[hit.primitive], last = sourceStart_[hit.primitive + 1];
    if (first == last) return std::nullopt;
    if (sources_[first].grid.rows != 0) return lookupCell(sources_[first], hit.point);
    // One of a tessellation's triangles holds the point; the only triangle of a primitive takes
    // it even if the point rounds outside.
    const bool several = last - first > 1;
    for (std::uint32_t s = first; s < last; ++s)
        if (auto found = lookupTriangle(sources_[s], hit.point, several)) return found;
    // A curved outline's hit may lie just outside its tessellation (between a chord and the
    // arc): the nearest piece's patch, its coordinates clamped onto it. An unbounded shape's hit
    // outside the region its triangles cover has none.
    const ShapeRecord* record = sources_[first].record;
    if (!several || (record && !record->ops->bounded)) return std::nullopt;
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

PatchLookup RadiosityMesh::lookupCell(const Source& source, const Vec3& point) const {
    const GridPoint at = source.record->ops->patchGrid->locate(*source.record, source.grid, point);
    const float fr = at.fraction.x, fc = at.fraction.y;
    PatchLookup found;
    found.patch = source.firstPatch + at.row * source.grid.columns + at.column;
    found.weights = {(1.0f - fr) * (1.0f - fc), (1.0f - fr) * fc, fr * (1.0f - fc), fr * fc};
    return found;
}

}  // namespace lightpath
