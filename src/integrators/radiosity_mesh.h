#pragma once
// Radiosity's patches (Cohen and Wallace 1993, ch. 8): every surface of the scene split into small
// elements of about one patch size. Triangles are subdivided uniformly into n^2 sub-triangles
// (n = ceil(longest edge / size)). A record of the shape table (geometry/shape.h) is asked, never
// named: a kind with a patch grid is cut into its cells (the sphere's equal-area latitude-longitude
// cells); any other is first tessellated, a bounded kind whole (`tessellate`), an unbounded one over
// the scene's bounds (`tessellateRegion`: the plane's rectangle, cut along the lines where other
// surfaces meet it) and three coarser rings around it reaching 64 times as far (what lies beyond
// takes the outermost ring's value), and its triangles subdivided.
// Triangles no larger than the patch size are not subdivided but clustered (in the spirit of
// Smits, Arvo and Greenberg 1994, restricted to near-coplanar groups): the patches of one object
// whose centroids share a cell of half the patch size and whose normals share a direction bucket (a
// cone of about 25 degrees) form one cluster, solved as one element, so a dense mesh costs about
// 4 (its area / patch size^2) elements rather than one per triangle. A cluster gathers the light
// arriving over all its members (sample points by area, each with its member's normal), which is
// exact for its area mean; what varies inside the cell and the cone is averaged away. Every other
// patch is a cluster of one. Each cluster has two sides, each its own unknown. Buried triangles
// (RadiosityMesh::buriedTriangles: inside another object or behind a plane, where no light comes)
// never share a cluster with exposed ones, whose light they would dilute.
//
// Refinement (RadiosityMesh::split): a triangle patch solved on its own can be cut into four at its
// edges' midpoints, again and again, where the solve's error estimate asks (Hanrahan, Salzman and
// Aupperle 1991, in spirit): each triangle of a source's grid is the root of a quadtree of patches.
// Clusters are cut too (RadiosityMesh::splitClusters; Smits, Arvo and Greenberg 1994 refine a
// cluster into its children): a cluster's cell is the node of an octree (its depth, shrunk to the
// smallest cell holding its members' centroids), and a cut makes each occupied eighth of the cell a
// cluster of its own, down to single triangles (which split() may then cut into four). The solve's
// estimate for a cluster is its parts' own (radiosity.cpp, clustersToRefine). Patches, vertices and
// the Gouraud display are untouched by a cluster cut: only which cluster each member solves with.
//
// The mesh also answers the display's question: which patch, and which of its vertices with what
// weights, lies under a hit point (Gouraud interpolation of vertex radiosities).
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "accel/scene_geometry.h"
#include "integrators/coplanar_triangle_index.h"
#include "geometry/shape.h"
#include "geometry/surface_hit.h"
#include "math/types.h"
#include "scene/scene.h"

namespace lightpath {

struct RadiosityPatch {
    std::uint32_t primitive = 0;  // scene-wide id of the primitive it lies on
    std::uint32_t object = 0;
    // A triangle (of a mesh or a tessellation): the corners, unit normal of their winding.
    Vec3 a{0.0f}, b{0.0f}, c{0.0f}, normal{0.0f};
    // A cell of its kind's patch grid (vertexCount 4): which one; `source` is where its grid is.
    std::uint32_t row = 0, column = 0, source = 0;
    float area = 0.0f;
    // Vertices for Gouraud interpolation: a, b, c for triangles; the corners (row, column),
    // (row, column + 1), (row + 1, column), (row + 1, column + 1) for grid cells.
    std::array<std::uint32_t, 4> vertices{};
    int vertexCount = 3;
    std::uint32_t cluster = 0;  // the cluster (solved element) it belongs to
    std::uint32_t level = 0;    // how many times split() cut its way down to it
};

// Patches solved as one: members_[firstMember .. firstMember + memberCount) of the mesh.
struct RadiosityCluster {
    std::uint32_t object = 0;
    std::uint32_t firstMember = 0;
    std::uint32_t memberCount = 0;
    float area = 0.0f;
    // Its cell's depth in the octree of cluster cells: side kClusterCell * patchSize / 2^depth, the
    // smallest cell holding all its members' centroids (RadiosityMesh::splitClusters cuts it into
    // the cell's eighths).
    std::uint32_t depth = 0;
};

// A point on a patch: where it is and the patch's outward (front-side) normal there.
struct PatchPoint {
    Vec3 point{0.0f};
    Vec3 normal{0.0f};
    std::uint32_t patch = 0;  // the patch it lies on
};

// What lies under a hit point.
struct PatchLookup {
    std::uint32_t patch = 0;
    std::array<float, 4> weights{};  // of the patch's vertices, summing to 1
};

class RadiosityMesh {
public:
    // A cluster's cell, as a fraction of the patch size (radiosity_mesh.cpp says why half).
    static constexpr double kClusterCell = 0.5;
    // Cells no deeper than this (2^-24 of the first cell): members whose centroids share such a
    // cell stay one cluster.
    static constexpr std::uint32_t kMaxClusterDepth = 24;

    // Splits every surface into patches of about `patchSize` scene units and clusters the smaller ones.
    // `buried`: per triangle of the geometry's triangle array, whether it is buried (buriedTriangles);
    // empty: none is (the tests' control). cutPlanes: an unbounded shape's rectangle is cut along the
    // lines where the scene's other surfaces meet it (radiosity_mesh.cpp, contactLines); false: whole.
    RadiosityMesh(const Scene& scene, const SceneGeometry& geometry, float patchSize, int planeRings,
                  std::span<const std::uint8_t> buried = {}, bool cutPlanes = true);
    ~RadiosityMesh();
    RadiosityMesh(const RadiosityMesh&) = delete;
    RadiosityMesh& operator=(const RadiosityMesh&) = delete;

    // How many clusters (solved elements) `patchSize` would make (without building them): for a budget.
    static std::size_t countClusters(const Scene& scene, const SceneGeometry& geometry, float patchSize, int planeRings,
                                     std::span<const std::uint8_t> buried = {}, bool cutPlanes = true);
    // The patch size whose mesh has at most `budget` clusters and is finest among such sizes.
    static float patchSizeForBudget(const Scene& scene, const SceneGeometry& geometry, std::size_t budget,
                                    int planeRings, std::span<const std::uint8_t> buried = {}, bool cutPlanes = true);
    // Per triangle of the triangle array, 1 where it is buried: inside another object or behind an
    // unbounded one, judged by rays from its centroid (radiosity_mesh.cpp, isBuried).
    static std::vector<std::uint8_t> buriedTriangles(const SceneGeometry& geometry, int threads);

    const std::vector<RadiosityPatch>& patches() const { return patches_; }
    const std::vector<RadiosityCluster>& clusters() const { return clusters_; }
    // The ids of the patches cluster `c` solves as one.
    std::span<const std::uint32_t> membersOf(const RadiosityCluster& c) const {
        return {members_.data() + c.firstMember, c.memberCount};
    }
    std::size_t vertexCount() const { return vertexCount_; }
    float patchSize() const { return patchSize_; }

    // The patches around each vertex, in patch order: those of vertex v are
    // patches[start[v] .. start[v + 1]) (compressed rows).
    struct VertexPatches {
        std::vector<std::uint32_t> start, patches;
    };
    VertexPatches patchesAroundVertices() const;

    // A point uniformly by area on patch `patch`, from u in [0,1)^2.
    PatchPoint samplePoint(std::uint32_t patch, Vec2 u) const;
    // A point uniformly by area over the members of cluster `cluster` (u.x picks the member and is
    // reused inside it, so a stratified pattern stays stratified).
    PatchPoint sampleClusterPoint(std::uint32_t cluster, Vec2 u) const;
    // Whether split() can cut `patch`: a triangle that is a cluster of its own.
    bool splittable(std::uint32_t patch) const;
    // Whether splitClusters() can cut `cluster`: it has members in more than one eighth of its cell.
    bool clusterSplittable(std::uint32_t cluster) const;
    // The eighth of its cluster's cell (0..7) that holds the centroid of member `patch`: which part
    // of the cluster splitClusters() puts it in.
    std::uint32_t clusterPart(std::uint32_t patch) const;
    // How many clusters splitClusters() makes of `cluster` (its occupied eighths).
    std::uint32_t clusterParts(std::uint32_t cluster) const;
    // Cuts each of `clusters` (clusterSplittable, distinct) into the eighths of its cell: the members
    // in each occupied eighth become a cluster, the first keeping the cluster's id, the others
    // appended to clusters(); each part's cell is then shrunk to its members (depth). Patches and
    // vertices are unchanged: the members' `cluster` says which part they solve with.
    void splitClusters(std::span<const std::uint32_t> clusters);
    // Cuts each of `patches` (splittable, distinct) into four at its edges' midpoints: the patch
    // keeps its id and cluster as the corner child at its first vertex, the three others are
    // appended to patches() and each becomes a new cluster appended to clusters(); new vertices
    // are welded with their neighbours' (a neighbour not cut leaves a T-junction).
    void split(std::span<const std::uint32_t> patches);
    // The patch under `hit`, or nullopt (an unbounded shape's hit outside its tessellated region).
    std::optional<PatchLookup> lookup(const SurfaceHit& hit) const;

private:
    // One primitive's share of the patches: a triangle's n x n grid or a kind's grid cells. A
    // primitive has one source, or one per triangle of its tessellation.
    struct Source {
        const ShapeRecord* record;  // nullptr: a triangle of the triangle array
        std::uint32_t primitive;
        std::uint32_t firstNode;     // its grid's patches are nodes firstNode, firstNode + 1, ...
        std::uint32_t n = 0;         // triangle: subdivisions per edge
        PatchGrid grid{};            // grid cells: rows x columns (rows 0 for a triangle)
        Vec3 a{0.0f}, b{0.0f}, c{0.0f};  // triangle corners
    };

    struct VertexWelder;
    // A quadtree node over the patches: a leaf is patch `patch`; an inner node's children are
    // nodes firstChild .. firstChild + 3 (RadiosityMesh::split's order).
    struct Node {
        std::uint32_t patch = 0;
        std::uint32_t firstChild = 0;  // 0: a leaf (node 0 is never anyone's child)
    };
    // Per patch, whether buildClusters may join it with others: a whole triangle no larger than the
    // patch size may, with the others exposed or buried like it.
    enum class Clustering : std::uint8_t { Alone, Exposed, Buried };
    // Each appends to `clustering`, per patch. buried: the triangle is (buriedTriangles).
    void addTriangle(const ShapeRecord* record, std::uint32_t primitive, std::uint32_t object, const Vec3& a,
                     const Vec3& b, const Vec3& c, float patchSize, bool buried, VertexWelder& welder,
                     std::vector<Clustering>& clustering);
    void addGrid(std::uint32_t shapeIndex, std::vector<Clustering>& clustering);
    void buildClusters(const std::vector<Clustering>& clustering);
    // A primitive with more sources than this gets a CoplanarTriangleIndex for lookup, when they share a plane.
    static constexpr std::uint32_t kScannedSources = 8;
    void indexSources();
    // The eighth (0..7: x, y, z bits) of a cell at depth - 1 that holds `patch`'s centroid, as a cell at `depth`.
    std::uint32_t octant(std::uint32_t patch, std::uint32_t depth) const;
    // Deepens `cluster`'s cell while all its members share one eighth of it.
    void tightenCluster(std::uint32_t cluster);
    // memberCdf_ over `cluster`'s members.
    void setMemberCdf(std::uint32_t cluster);
    // strict: nullopt for a point outside the source's triangle (when its primitive has several).
    std::optional<PatchLookup> lookupTriangle(const Source& source, const Vec3& point, bool strict) const;
    PatchLookup lookupCell(const Source& source, const Vec3& point) const;
    static Vec3 closestPoint(const Source& source, const Vec3& point);

    // Descends from `node` to the leaf holding local coordinates (s, t) of its triangle, with the
    // leaf's vertex weights.
    PatchLookup descend(std::uint32_t node, float s, float t) const;

    const SceneGeometry& geometry_;
    std::unique_ptr<VertexWelder> welder_;
    float patchSize_;
    int planeRings_;
    std::vector<RadiosityPatch> patches_;
    std::vector<RadiosityCluster> clusters_;
    std::vector<std::uint32_t> members_;   // patch ids, cluster by cluster
    std::vector<float> memberCdf_;         // per member: its cluster's area up to and with it, over the cluster's
    std::vector<Source> sources_;
    std::vector<Node> nodes_;              // one root per patch of a source's grid, then split()'s
    std::vector<std::uint32_t> leafNode_;  // per patch: its node
    // sources_[sourceStart_[id] .. sourceStart_[id + 1]) lie on scene-wide primitive id.
    std::vector<std::uint32_t> sourceStart_;
    // Per primitive, 1 + its entry in sourceIndexes_ where it has many coplanar sources (a plane's
    // rectangle and rings), 0 where lookup scans its few sources in order.
    std::vector<std::uint32_t> sourceIndexOf_;
    std::vector<CoplanarTriangleIndex> sourceIndexes_;
    std::size_t vertexCount_ = 0;
};

}  // namespace lightpath
