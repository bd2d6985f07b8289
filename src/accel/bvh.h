#pragma once
// A bounding volume hierarchy over any primitives that have a bounding box: built with the
// surface area heuristic (MacDonald and Booth 1990) evaluated on centroid bins (Wald 2007),
// flattened depth-first into 32-byte nodes, traversed front to back for the closest hit and
// with an early exit for any hit. The BVH only finds candidates: the caller's test decides hits,
// so results are exactly those of testing every primitive.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

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

// Interior: `offset` is the second child (the first follows the node); leaf: `offset` is the
// first of `count` entries of primitiveIds(). `axis` is the split axis, for ordered traversal.
struct BvhNode {
    Vec3 lo;
    Vec3 hi;
    std::uint32_t offset = 0;
    std::uint16_t count = 0;
    std::uint8_t axis = 0;
    std::uint8_t pad = 0;
};
static_assert(sizeof(BvhNode) == 32, "two nodes per 64-byte cache line");
static_assert(offsetof(BvhNode, hi) == 3 * sizeof(float), "the six box planes are contiguous floats");

struct BvhStats {
    double buildSeconds = 0.0;
    std::size_t nodes = 0;
    std::size_t nodeBytes = 0;
    std::size_t primitives = 0;
};

class Bvh {
public:
    Bvh() = default;
    explicit Bvh(std::vector<BvhPrimitive> primitives);

    bool empty() const { return nodes_.empty(); }
    const BvhStats& stats() const { return stats_; }
    std::span<const BvhNode> nodes() const { return nodes_; }
    std::span<const std::uint32_t> primitiveIds() const { return ids_; }

    // Calls test(slot) for every primitive whose leaf box the ray may enter before `tLimit`,
    // nearer boxes first; primitiveIds()[slot] is its id, and the caller may keep its data in
    // slot order too, so a leaf's primitives are read from adjacent memory. `tLimit` is read again
    // after each call, so the test shrinks it as it finds nearer hits and farther subtrees are
    // skipped.
    template <typename Test>
    void closest(const Ray& ray, const float& tLimit, Test test) const;

    // True as soon as test(slot) is true for a candidate; false when none is.
    template <typename Test>
    bool any(const Ray& ray, Test test) const;

private:
    std::vector<BvhNode> nodes_;
    std::vector<std::uint32_t> ids_;
    BvhStats stats_;
};

namespace bvh_detail {

// gamma(3) = 3u / (1 - 3u), u = 2^-24: the slab test's far distance grown by 1 + 2 gamma(3)
// never rejects a box the exact ray passes through (Ize 2013; pbrt-v4 Bounds3::IntersectP).
inline constexpr float kFarPadding = 1.0f + 2.0f * (3.0f * 0x1p-24f) / (1.0f - 3.0f * 0x1p-24f);
// The closest-hit limit t is itself rounded, and a box's entry distance is computed by another
// formula than a primitive's t; a box is skipped only when it starts clearly beyond the limit.
inline constexpr float kLimitSlack = 1.0f + 0x1p-10f;

struct RaySetup {
    Vec3 origin;
    Vec3 inverse;
    int negative[3];
    int nearIndex[3], farIndex[3];  // into a node's floats lo.x lo.y lo.z hi.x hi.y hi.z

    explicit RaySetup(const Ray& ray) : origin(ray.origin), inverse(1.0f / ray.direction) {
        // 1/±0 is ±inf; a zero component then yields ±inf (or NaN on a slab plane), handled below.
        for (int a = 0; a < 3; ++a) {
            negative[a] = std::signbit(ray.direction[a]) ? 1 : 0;
            nearIndex[a] = negative[a] ? 3 + a : a;
            farIndex[a] = negative[a] ? a : 3 + a;
        }
    }

    // The entry distance into the node's box within [tMin, tMax], or +inf when the ray misses it.
    // Written so a NaN slab distance (origin on a slab plane, direction parallel to it) leaves
    // the interval unchanged: the comparisons are false for NaN.
    float enter(const BvhNode& node, float tMin, float tMax) const {
        const float* planes = &node.lo.x;
        float t0 = tMin, t1 = tMax;
        for (int a = 0; a < 3; ++a) {
            const float tNear = (planes[nearIndex[a]] - origin[a]) * inverse[a];
            const float tFar = (planes[farIndex[a]] - origin[a]) * inverse[a] * kFarPadding;
            t0 = tNear > t0 ? tNear : t0;
            t1 = tFar < t1 ? tFar : t1;
        }
        return t0 <= t1 ? t0 : std::numeric_limits<float>::infinity();
    }
};

// The builder keeps the tree at most this deep (bvh.cpp), so traversal needs no heap.
inline constexpr int kStackSize = 128;

struct Pending {
    std::uint32_t node;
    float entry;
};

}  // namespace bvh_detail

// Both children's boxes are tested at their parent: the nearer is visited first, the other is
// pushed with its entry distance and skipped on pop when a hit found since is nearer.
template <typename Test>
void Bvh::closest(const Ray& ray, const float& tLimit, Test test) const {
    if (nodes_.empty()) return;
    const bvh_detail::RaySetup setup(ray);
    const auto limit = [&] { return tLimit * bvh_detail::kLimitSlack; };
    if (setup.enter(nodes_[0], ray.tMin, limit()) == std::numeric_limits<float>::infinity()) return;
    bvh_detail::Pending stack[bvh_detail::kStackSize];
    int top = 0;
    std::uint32_t current = 0;
    for (;;) {
        const BvhNode& node = nodes_[current];
        if (node.count == 0) {
            const float cut = limit();
            const float tFirst = setup.enter(nodes_[current + 1], ray.tMin, cut);
            const float tSecond = setup.enter(nodes_[node.offset], ray.tMin, cut);
            const bool first = tFirst != std::numeric_limits<float>::infinity();
            const bool second = tSecond != std::numeric_limits<float>::infinity();
            if (first && second) {
                if (tFirst <= tSecond) {
                    stack[top++] = {node.offset, tSecond};
                    current = current + 1;
                } else {
                    stack[top++] = {current + 1, tFirst};
                    current = node.offset;
                }
                continue;
            }
            if (first || second) {
                current = first ? current + 1 : node.offset;
                continue;
            }
        } else {
            for (std::uint32_t i = node.offset; i < node.offset + node.count; ++i) test(i);
        }
        for (;;) {
            if (top == 0) return;
            const bvh_detail::Pending next = stack[--top];
            if (next.entry <= limit()) {
                current = next.node;
                break;
            }
        }
    }
}

template <typename Test>
bool Bvh::any(const Ray& ray, Test test) const {
    if (nodes_.empty()) return false;
    const bvh_detail::RaySetup setup(ray);
    const float tMax = ray.tMax * bvh_detail::kLimitSlack;
    if (setup.enter(nodes_[0], ray.tMin, tMax) == std::numeric_limits<float>::infinity()) return false;
    std::uint32_t stack[bvh_detail::kStackSize];
    int top = 0;
    std::uint32_t current = 0;
    for (;;) {
        const BvhNode& node = nodes_[current];
        if (node.count == 0) {
            const bool first = setup.enter(nodes_[current + 1], ray.tMin, tMax) != std::numeric_limits<float>::infinity();
            const bool second = setup.enter(nodes_[node.offset], ray.tMin, tMax) != std::numeric_limits<float>::infinity();
            if (first && second) stack[top++] = node.offset;
            if (first || second) {
                current = first ? current + 1 : node.offset;
                continue;
            }
        } else {
            for (std::uint32_t i = node.offset; i < node.offset + node.count; ++i)
                if (test(i)) return true;
        }
        if (top == 0) return false;
        current = stack[--top];
    }
}

}  // namespace lightpath
