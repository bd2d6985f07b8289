#pragma once
// A 4-wide bounding volume hierarchy over any primitives that have a bounding box. Built as a
// binary tree with the surface area heuristic (MacDonald and Booth 1990) evaluated on centroid
// bins (Wald 2007), its subtrees on several threads, then collapsed into nodes of four children
// whose boxes one ray tests at once with SIMD (Wald, Benthin and Boulos 2008; Ernst and Greiner
// 2008). Traversal visits children front to back for the closest hit and exits early for any hit.
// The BVH only finds candidates: the caller's test decides hits, so results are exactly those of
// testing every primitive.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "accel/simd.h"
#include "math/ray.h"
#include "math/types.h"

namespace lightpath {

struct Bounds {
    Vec3 lo{std::numeric_limits<float>::infinity()};
    Vec3 hi{-std::numeric_limits<float>::infinity()};

    void grow(const Vec3& p) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    void grow(const Bounds& b) {
        lo = glm::min(lo, b.lo);
        hi = glm::max(hi, b.hi);
    }
    bool empty() const { return lo.x > hi.x; }
    Vec3 centroid() const { return 0.5f * (lo + hi); }
    float halfArea() const {
        if (empty()) return 0.0f;
        const Vec3 d = hi - lo;
        return d.x * d.y + d.y * d.z + d.z * d.x;
    }
};

// What the builder needs of a primitive: its box and the id the caller's test understands.
struct BvhPrimitive {
    Bounds bounds;
    std::uint32_t id = 0;
};

inline constexpr int kBvhWidth = 4;
// A leaf holds at most this many primitives, in one block of kBvhWidth slots.
inline constexpr std::uint32_t kBvhMaxLeafSize = kBvhWidth;
// The id of a padding slot: a leaf's block holds fewer primitives than slots.
inline constexpr std::uint32_t kBvhEmptySlot = std::numeric_limits<std::uint32_t>::max();

// A child reference: an interior node's index, or (kLeafFlag set) a leaf: its block index in
// bits 0-28 and its primitive count - 1 in bits 29-30. Its primitives are in slots
// kBvhWidth * block + [0, count).
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
    static std::uint32_t firstSlot(std::uint32_t child) { return kBvhWidth * (child & kBlockMask); }
    static std::uint32_t count(std::uint32_t child) { return ((child >> 29) & 3u) + 1; }
};

// Four children's boxes as planes[side][axis][lane] (side 0 = lo, 1 = hi), so one load fetches
// one plane of all four boxes. An unused lane has lo = +inf and hi = -inf.
struct alignas(64) BvhNode {
    alignas(16) float planes[2][3][kBvhWidth];
    std::uint32_t children[kBvhWidth];

    Bounds childBounds(int lane) const {
        return {{planes[0][0][lane], planes[0][1][lane], planes[0][2][lane]},
                {planes[1][0][lane], planes[1][1][lane], planes[1][2][lane]}};
    }
};
static_assert(sizeof(BvhNode) == 128, "a node is two 64-byte cache lines");

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

    bool empty() const { return root_ == kNoRoot; }
    const BvhStats& stats() const { return stats_; }
    std::span<const BvhNode> nodes() const { return nodes_; }
    // The root: a node index, or a leaf when there are at most kBvhMaxLeafSize primitives.
    std::uint32_t root() const { return root_; }
    // One id per slot, kBvhEmptySlot for padding; the caller may keep its own per-slot data in
    // the same order, so a leaf's primitives are read from one block of adjacent memory.
    std::span<const std::uint32_t> slotIds() const { return ids_; }

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
// primitives: 96 levels. A wide node spans at least one of them and pushes at most 3 children.
inline constexpr int kStackSize = 3 * 96 + 1;

struct Pending {
    std::uint32_t child;
    float entry;
};

struct RaySetup {
    simd::Float4 origin[3];
    simd::Float4 inverse[3];
    simd::Float4 farInverse[3];  // inverse grown by kFarPadding: the padding costs no multiply per node
    simd::Float4 tMin;
    int nearSide[3];  // which of a node's planes[side] a ray enters an axis' slab through

    explicit RaySetup(const Ray& ray) : tMin(ray.tMin) {
        // 1/±0 is ±inf; a zero component then yields ±inf (or NaN on a slab plane), handled below.
        for (int a = 0; a < 3; ++a) {
            origin[a] = simd::Float4(ray.origin[a]);
            inverse[a] = simd::Float4(1.0f / ray.direction[a]);
            farInverse[a] = simd::Float4(1.0f / ray.direction[a] * kFarPadding);
            nearSide[a] = std::signbit(ray.direction[a]) ? 1 : 0;
        }
    }

    // The lanes whose box the ray enters within [tMin, tMax], and their entry distances. A NaN
    // slab distance (origin on a slab plane, direction parallel to it) leaves the interval as it
    // is: maxKeepSecond / minKeepSecond keep the accumulated bound.
    int enter(const BvhNode& node, simd::Float4 tMax, simd::Float4& entry) const {
        simd::Float4 t0 = tMin, t1 = tMax;
        for (int a = 0; a < 3; ++a) {
            const simd::Float4 nearPlane = simd::Float4::load(node.planes[nearSide[a]][a]);
            const simd::Float4 farPlane = simd::Float4::load(node.planes[1 - nearSide[a]][a]);
            t0 = simd::maxKeepSecond((nearPlane - origin[a]) * inverse[a], t0);
            t1 = simd::minKeepSecond((farPlane - origin[a]) * farInverse[a], t1);
        }
        entry = t0;
        return simd::lessEqual(t0, t1);
    }
};

// The lanes of `mask` (two or more) in out[], farthest entry first; returns how many. Two, the
// common case, take one comparison.
inline int sortFarToNear(const BvhNode& node, int mask, const simd::Float4& entry, Pending out[kBvhWidth]) {
    alignas(16) float t[kBvhWidth];
    entry.store(t);
    const int a = simd::firstLane(mask);
    mask &= mask - 1;
    const int b = simd::firstLane(mask);
    mask &= mask - 1;
    if (t[a] >= t[b]) {
        out[0] = {node.children[a], t[a]};
        out[1] = {node.children[b], t[b]};
    } else {
        out[0] = {node.children[b], t[b]};
        out[1] = {node.children[a], t[a]};
    }
    int n = 2;
    for (; mask != 0; mask &= mask - 1) {
        const int lane = simd::firstLane(mask);
        const Pending p{node.children[lane], t[lane]};
        int i = n++;
        for (; i > 0 && out[i - 1].entry < p.entry; --i) out[i] = out[i - 1];
        out[i] = p;
    }
    return n;
}

}  // namespace bvh_detail

// All four children are tested at their parent; those entered are pushed farthest first with
// their entry distances, the nearest is visited at once, and a popped child is skipped when a
// hit found since is nearer than its entry.
template <typename Test>
void Bvh::closest(const Ray& ray, const float& tLimit, Test test) const {
    if (root_ == kNoRoot) return;
    const bvh_detail::RaySetup setup(ray);
    const auto limit = [&] { return tLimit * bvh_detail::kLimitSlack; };
    bvh_detail::Pending stack[bvh_detail::kStackSize];
    int top = 0;
    std::uint32_t current = root_;
    const BvhNode* nodes = nodes_.data();
    for (;;) {
        if (!BvhChild::isLeaf(current)) {
            const BvhNode& node = nodes[current];
            simd::Float4 entry;
            const int mask = setup.enter(node, simd::Float4(limit()), entry);
            if (mask != 0) {
                if ((mask & (mask - 1)) == 0) {
                    current = node.children[simd::firstLane(mask)];
                    continue;
                }
                bvh_detail::Pending sorted[kBvhWidth];
                const int n = bvh_detail::sortFarToNear(node, mask, entry, sorted);
                for (int i = 0; i < n - 1; ++i) stack[top++] = sorted[i];
                current = sorted[n - 1].child;
                continue;
            }
        } else {
            test(BvhChild::firstSlot(current), BvhChild::count(current));
        }
        for (;;) {
            if (top == 0) return;
            const bvh_detail::Pending next = stack[--top];
            if (next.entry <= limit()) {
                current = next.child;
                break;
            }
        }
    }
}

// Any hit ends the search, and most shadow rays reach their light: their every candidate box is
// visited whatever the order, so children go in lane order, without sorting.
template <typename Test>
bool Bvh::any(const Ray& ray, Test test) const {
    if (root_ == kNoRoot) return false;
    const bvh_detail::RaySetup setup(ray);
    const simd::Float4 tMax(ray.tMax * bvh_detail::kLimitSlack);
    std::uint32_t stack[bvh_detail::kStackSize];
    int top = 0;
    std::uint32_t current = root_;
    const BvhNode* nodes = nodes_.data();
    for (;;) {
        if (!BvhChild::isLeaf(current)) {
            const BvhNode& node = nodes[current];
            simd::Float4 entry;
            int mask = setup.enter(node, tMax, entry);
            if (mask != 0) {
                current = node.children[simd::firstLane(mask)];
                for (mask &= mask - 1; mask != 0; mask &= mask - 1) stack[top++] = node.children[simd::firstLane(mask)];
                continue;
            }
        } else if (test(BvhChild::firstSlot(current), BvhChild::count(current))) {
            return true;
        }
        if (top == 0) return false;
        current = stack[--top];
    }
}

}  // namespace lightpath
