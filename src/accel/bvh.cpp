#include "accel/bvh.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <stdexcept>

namespace lightpath {
namespace {

constexpr int kBins = 16;
constexpr std::size_t kMaxLeafSize = 4;
// Relative costs of one node visit and one primitive test (pbrt-v4 uses 1/2 : 1).
constexpr float kTraversalCost = 0.5f;
// Below this depth splits follow the SAH; deeper (only in pathological inputs) they halve the
// range, so the depth stays under bvh_detail::kStackSize.
constexpr int kSahDepthLimit = 64;

struct Bin {
    Bounds bounds;
    std::uint32_t count = 0;
};

// A primitive as the builder moves it around: its box, its centroid (computed once) and its id.
struct Item {
    Bounds bounds;
    Vec3 centroid;
    std::uint32_t id;
};

struct Split {
    int axis = -1;
    int bin = 0;  // primitives in bins [0, bin] go left
    float cost = std::numeric_limits<float>::infinity();
};

int binOf(float centroid, float lo, float scale) {
    return std::clamp(static_cast<int>((centroid - lo) * scale), 0, kBins - 1);
}

class Builder {
public:
    explicit Builder(const std::vector<BvhPrimitive>& primitives) {
        primitives_.reserve(primitives.size());
        for (const BvhPrimitive& p : primitives) primitives_.push_back({p.bounds, p.bounds.centroid(), p.id});
    }

    // The ids in leaf order, after build().
    std::vector<std::uint32_t> ids() const {
        std::vector<std::uint32_t> ids;
        ids.reserve(primitives_.size());
        for (const Item& item : primitives_) ids.push_back(item.id);
        return ids;
    }

    std::vector<BvhNode> build() {
        // A binary tree over N primitives has at most 2N - 1 nodes. Reserving them all avoids
        // reallocating (old and new buffers at once at the memory peak); pages never written are
        // never resident, so the unused capacity costs address space only.
        nodes_.reserve(2 * primitives_.size() - 1);
        // Depth-first with an explicit stack: a node's first child is always the next node.
        struct Task {
            std::size_t begin, end;
            std::uint32_t parent;  // whose `offset` names this node when it is a second child
            bool second;
            int depth;
        };
        std::vector<Task> tasks{{0, primitives_.size(), 0, false, 0}};
        while (!tasks.empty()) {
            const Task task = tasks.back();
            tasks.pop_back();
            const auto index = static_cast<std::uint32_t>(nodes_.size());
            if (task.second) nodes_[task.parent].offset = index;
            nodes_.emplace_back();
            const std::size_t middle = split(task.begin, task.end, task.depth, nodes_.back());
            if (middle == task.end) continue;  // a leaf
            tasks.push_back({middle, task.end, index, true, task.depth + 1});
            tasks.push_back({task.begin, middle, index, false, task.depth + 1});
        }
        return std::move(nodes_);
    }

private:
    // Fills `node`'s bounds and either makes it a leaf (returns end) or partitions the range and
    // returns where the second child starts.
    std::size_t split(std::size_t begin, std::size_t end, int depth, BvhNode& node) {
        Bounds bounds, centroids;
        for (std::size_t i = begin; i < end; ++i) {
            bounds.grow(primitives_[i].bounds);
            centroids.grow(primitives_[i].centroid);
        }
        node.lo = bounds.lo;
        node.hi = bounds.hi;
        const std::size_t count = end - begin;
        const auto makeLeaf = [&] {
            node.offset = static_cast<std::uint32_t>(begin);
            node.count = static_cast<std::uint16_t>(count);
            return end;
        };
        if (count == 1) return makeLeaf();

        const Vec3 extent = centroids.hi - centroids.lo;
        const int widest = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
        if (depth < kSahDepthLimit && extent[widest] > 0.0f) {
            const Split best = findSplit(begin, end, centroids);
            const float leafCost = static_cast<float>(count);
            const float splitCost = kTraversalCost + best.cost / bounds.halfArea();
            if (count <= kMaxLeafSize && !(splitCost < leafCost)) return makeLeaf();
            if (best.axis >= 0) {
                const int axis = best.axis;
                const float lo = centroids.lo[axis];
                const float scale = kBins / (centroids.hi[axis] - centroids.lo[axis]);
                const auto mid = std::partition(primitives_.begin() + static_cast<std::ptrdiff_t>(begin),
                                                primitives_.begin() + static_cast<std::ptrdiff_t>(end),
                                                [&](const Item& p) {
                                                    return binOf(p.centroid[axis], lo, scale) <= best.bin;
                                                });
                const auto middle = static_cast<std::size_t>(mid - primitives_.begin());
                if (middle > begin && middle < end) {
                    node.axis = static_cast<std::uint8_t>(axis);
                    return middle;
                }
            }
        }
        if (count <= kMaxLeafSize) return makeLeaf();
        // Coincident centroids, or too deep: halve the range along the widest axis by centroid
        // (ties in index order, so the build is deterministic).
        const std::size_t middle = begin + count / 2;
        std::nth_element(primitives_.begin() + static_cast<std::ptrdiff_t>(begin),
                         primitives_.begin() + static_cast<std::ptrdiff_t>(middle),
                         primitives_.begin() + static_cast<std::ptrdiff_t>(end),
                         [&](const Item& a, const Item& b) {
                             const float ca = a.centroid[widest], cb = b.centroid[widest];
                             return ca < cb || (ca == cb && a.id < b.id);
                         });
        node.axis = static_cast<std::uint8_t>(widest);
        return middle;
    }

    // The cheapest bin boundary over the three axes; cost is sum(area * count) of both sides
    // (half areas, unnormalised). One pass over the primitives bins all three axes.
    Split findSplit(std::size_t begin, std::size_t end, const Bounds& centroids) const {
        std::array<std::array<Bin, kBins>, 3> bins{};
        Vec3 scale(0.0f);
        for (int axis = 0; axis < 3; ++axis) {
            const float width = centroids.hi[axis] - centroids.lo[axis];
            if (width > 0.0f) scale[axis] = kBins / width;
        }
        for (std::size_t i = begin; i < end; ++i) {
            const Item& item = primitives_[i];
            for (int axis = 0; axis < 3; ++axis) {
                Bin& bin = bins[static_cast<std::size_t>(axis)][static_cast<std::size_t>(
                    binOf(item.centroid[axis], centroids.lo[axis], scale[axis]))];
                bin.bounds.grow(item.bounds);
                ++bin.count;
            }
        }
        Split best;
        for (int axis = 0; axis < 3; ++axis) {
            if (scale[axis] == 0.0f) continue;
            const std::array<Bin, kBins>& axisBins = bins[static_cast<std::size_t>(axis)];
            // Sweep from the right to get each suffix's cost, then from the left.
            std::array<float, kBins> rightCost{};
            Bounds right;
            std::uint32_t rightCount = 0;
            for (int b = kBins - 1; b > 0; --b) {
                right.grow(axisBins[static_cast<std::size_t>(b)].bounds);
                rightCount += axisBins[static_cast<std::size_t>(b)].count;
                rightCost[static_cast<std::size_t>(b)] = right.halfArea() * static_cast<float>(rightCount);
            }
            Bounds left;
            std::uint32_t leftCount = 0;
            for (int b = 0; b < kBins - 1; ++b) {
                left.grow(axisBins[static_cast<std::size_t>(b)].bounds);
                leftCount += axisBins[static_cast<std::size_t>(b)].count;
                if (leftCount == 0 || leftCount == end - begin) continue;
                const float cost = left.halfArea() * static_cast<float>(leftCount) + rightCost[static_cast<std::size_t>(b + 1)];
                if (cost < best.cost) best = {axis, b, cost};
            }
        }
        return best;
    }

    std::vector<Item> primitives_;
    std::vector<BvhNode> nodes_;
};

}  // namespace

Bvh::Bvh(std::vector<BvhPrimitive> primitives) {
    const auto started = std::chrono::steady_clock::now();
    if (primitives.size() >= std::numeric_limits<std::uint32_t>::max())
        throw std::length_error("too many primitives for a BVH with 32-bit offsets");
    if (!primitives.empty()) {
        Builder builder(primitives);
        primitives = {};  // the builder works on its own copy: free this one before the build's peak
        nodes_ = builder.build();
        ids_ = builder.ids();
    }
    stats_.buildSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    stats_.nodes = nodes_.size();
    stats_.nodeBytes = nodes_.size() * sizeof(BvhNode);
    stats_.primitives = ids_.size();
}

}  // namespace lightpath
