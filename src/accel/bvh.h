#pragma once
// An 8-wide bounding volume hierarchy over any primitives that have a bounding box. Built as a
// binary tree with the surface area heuristic (MacDonald and Booth 1990) evaluated on centroid
// bins (Wald 2007), its subtrees on several threads, then collapsed into nodes of eight children
// whose boxes one ray tests at once with SIMD (Wald, Benthin and Boulos 2008; Ernst and Greiner
// 2008; Embree's BVH8), with AVX2 where the processor has it (simd_path.h). Traversal visits
// children front to back for the closest hit and exits early for any hit. The BVH only finds
// candidates: the caller's test decides hits, so results are exactly those of testing every
// primitive.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <span>
#include <vector>

#include "accel/simd.h"
#include "accel/simd_path.h"
#include "geometry/bounds.h"
#include "math/ray.h"
#include "math/types.h"

namespace lightpath {

// What the builder needs of a primitive: its box and the id the caller's test understands.
struct BvhPrimitive {
    Bounds bounds;
    std::uint32_t id = 0;
};

// Children per node: one AVX register of boxes' planes (two SSE2 registers on the baseline path).
inline constexpr int kBvhWidth = 8;
// A leaf holds at most this many primitives, in one block of as many slots, tested four at once
// (triangle_pack.h): fewer, fuller leaves than eight would leave.
inline constexpr std::uint32_t kBvhLeafSize = 4;
// The id of a padding slot: a leaf's block holds fewer primitives than slots.
inline constexpr std::uint32_t kBvhEmptySlot = std::numeric_limits<std::uint32_t>::max();

// A child reference: an interior node's index, or (kLeafFlag set) a leaf: its block index in
// bits 0-28 and its primitive count - 1 in bits 29-30. Its primitives are in slots
// kBvhLeafSize * block + [0, count).
struct BvhChild {
    static constexpr std::uint32_t kLeafFlag = 1u << 31;
    static constexpr std::uint32_t kBlockMask = (1u << 29) - 1;
    // An unused lane (its box is empty, never entered), and the root of an empty tree: a block
    // index no tree reaches (Bvh limits the primitive count).
    static constexpr std::uint32_t kEmpty = std::numeric_limits<std::uint32_t>::max();

    static std::uint32_t leaf(std::uint32_t block, std::uint32_t count) {
        return kLeafFlag | ((count - 1) << 29) | block;
    }
    static bool isLeaf(std::uint32_t child) { return (child & kLeafFlag) != 0; }
    static std::uint32_t firstSlot(std::uint32_t child) { return kBvhLeafSize * (child & kBlockMask); }
    static std::uint32_t count(std::uint32_t child) { return ((child >> 29) & 3u) + 1; }
};

// Eight children's boxes as planes[side][axis][lane] (side 0 = lo, 1 = hi), so one load fetches
// one plane of all eight boxes. An unused lane has lo = +inf and hi = -inf.
struct alignas(64) BvhNode {
    alignas(32) float planes[2][3][kBvhWidth];
    std::uint32_t children[kBvhWidth];

    Bounds childBounds(int lane) const {
        return {{planes[0][0][lane], planes[0][1][lane], planes[0][2][lane]},
                {planes[1][0][lane], planes[1][1][lane], planes[1][2][lane]}};
    }
};
static_assert(sizeof(BvhNode) == 256, "a node is four 64-byte cache lines");

struct BvhStats {
    double buildSeconds = 0.0;
    std::size_t nodes = 0;
    std::size_t nodeBytes = 0;
    std::size_t primitives = 0;
    std::size_t leaves = 0;
};

class Bvh {
public:
    Bvh() = default;
    // Builds on `threads` threads (0: all the hardware has). The tree is the same for any count.
    explicit Bvh(std::vector<BvhPrimitive> primitives, unsigned threads = 0);
    // Writes the boxes (and ids) of primitives [begin, end) to out[0, end - begin); the build
    // calls it from its threads at once, on disjoint ranges.
    using PrimitiveSource = std::function<void(std::size_t begin, std::size_t end, BvhPrimitive* out)>;
    // The same tree from `count` primitives that `source` describes, without a list of them all.
    Bvh(std::size_t count, const PrimitiveSource& source, unsigned threads = 0);

    bool empty() const { return root_ == kNoRoot; }
    const BvhStats& stats() const { return stats_; }
    simd::Path simdPath() const { return path_; }
    std::span<const BvhNode> nodes() const { return nodes_; }
    // The root: a node index, or a leaf when there are at most kBvhLeafSize primitives.
    std::uint32_t root() const { return root_; }
    // One id per slot, kBvhEmptySlot for padding; the caller may keep its own per-slot data in
    // the same order, so a leaf's primitives are read from one block of adjacent memory.
    std::span<const std::uint32_t> slotIds() const { return ids_; }

    // Defined in accel/bvh_traversal.h, which the one caller includes (it is compiled twice, once
    // for AVX2).
    // Calls test(firstSlot, count) for every leaf whose box the ray may enter before `tLimit`,
    // nearer boxes first. `tLimit` is read again after each call, so the test shrinks it as it
    // finds nearer hits and farther subtrees are skipped.
    template <typename Test>
    void closest(const Ray& ray, const float& tLimit, Test test) const;

    // True as soon as test(firstSlot, count) is true for a leaf; false when none is.
    template <typename Test>
    bool any(const Ray& ray, Test test) const;

private:
    static constexpr std::uint32_t kNoRoot = BvhChild::kEmpty;

    std::vector<BvhNode> nodes_;
    std::vector<std::uint32_t> ids_;
    std::uint32_t root_ = kNoRoot;
    simd::Path path_ = simd::Path::Baseline;  // the traversal's SIMD path, chosen at build time
    BvhStats stats_;
};

namespace bvh_detail {

// gamma(3) = 3u / (1 - 3u), u = 2^-24: the slab test's far distance grown by 1 + 2 gamma(3)
// never rejects a box the exact ray passes through (Ize 2013; pbrt-v4 Bounds3::IntersectP).
// Folding it into the inverse direction keeps the count of roundings, so the bound still holds.
inline constexpr float kFarPadding = 1.0f + 2.0f * (3.0f * 0x1p-24f) / (1.0f - 3.0f * 0x1p-24f);
// The closest-hit limit t is itself rounded, and a box's entry distance is computed by another
// formula than a primitive's t; a box is skipped only when it starts clearly beyond the limit.
inline constexpr float kLimitSlack = 1.0f + 0x1p-10f;

// The deepest binary tree the builder makes is 64 SAH levels and then halving of at most 2^32
// primitives: 96 levels. A wide node spans at least one of them and pushes at most 7 children.
inline constexpr int kStackSize = (kBvhWidth - 1) * 96 + 1;

struct Pending {
    std::uint32_t child;
    float entry;
};

}  // namespace bvh_detail
}  // namespace lightpath
