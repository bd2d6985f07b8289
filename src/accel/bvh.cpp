#include "accel/bvh.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <thread>

namespace lightpath {
namespace {

constexpr int kBins = 16;
// Relative costs of one node visit and one leaf block test. A block's primitives are tested four
// at once, so the SAH counts blocks of kBvhLeafSize, not primitives (as Embree's builders do
// for their 4-triangle leaves): a range that fits one block is always a leaf.
constexpr float kTraversalCost = 1.0f;

float blocks(std::size_t count) {
    return static_cast<float>((count + kBvhLeafSize - 1) / kBvhLeafSize);
}
// Below this depth splits follow the SAH; deeper (only in pathological inputs) they halve the
// range, so the depth stays within what bvh_detail::kStackSize allows.
constexpr int kSahDepthLimit = 64;
// A subtree at least this large goes to the shared queue, where an idle thread may take it;
// smaller ones are built depth-first by the thread that split their parent.
constexpr std::size_t kParallelGrain = 4096;

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

// The intermediate binary tree: an interior node (count 0) has its children at `first` and
// `first + 1`; a leaf holds items [first, first + count).
// No member initializers: the array for 2N - 1 of them is allocated uninitialised, and pages
// never written are never resident.
struct BinaryNode {
    Bounds bounds() const { return {{lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]}}; }

    float lo[3], hi[3];
    std::uint32_t first;
    std::uint32_t count;
};

struct Split {
    int axis = -1;
    int bin = 0;  // primitives in bins [0, bin] go left
    float cost = std::numeric_limits<float>::infinity();
};

int binOf(float centroid, float lo, float scale) {
    return std::clamp(static_cast<int>((centroid - lo) * scale), 0, kBins - 1);
}

// Builds the binary tree. Every split depends only on the items of its own range, and threads
// work on disjoint ranges, so the tree's shape and the items' order are the same for any number
// of threads; only the binary nodes' indices vary, and collapse() reads the tree in child order.
class BinaryBuilder {
public:
    explicit BinaryBuilder(const std::vector<BvhPrimitive>& primitives) {
        items_.reserve(primitives.size());
        for (const BvhPrimitive& p : primitives) items_.push_back({p.bounds, p.bounds.centroid(), p.id});
        // A binary tree over N primitives has at most 2N - 1 nodes.
        nodes_ = std::make_unique_for_overwrite<BinaryNode[]>(2 * items_.size() - 1);
    }

    void build(unsigned threads) {
        nextNode_ = 1;
        queue_.push_back({0, items_.size(), 0, 0});
        outstanding_ = 1;
        std::vector<std::jthread> workers;
        for (unsigned t = 1; t < threads; ++t) workers.emplace_back([this] { work(); });
        work();
    }

    const std::vector<Item>& items() const { return items_; }
    const BinaryNode& node(std::uint32_t index) const { return nodes_[index]; }

private:
    struct Task {
        std::size_t begin, end;
        std::uint32_t node;
        int depth;
    };

    void work() {
        std::vector<Task> local;
        for (;;) {
            Task task;
            {
                std::unique_lock lock(mutex_);
                wake_.wait(lock, [&] { return !queue_.empty() || outstanding_ == 0; });
                if (queue_.empty()) return;
                task = queue_.back();
                queue_.pop_back();
            }
            local.push_back(task);
            while (!local.empty()) {
                const Task t = local.back();
                local.pop_back();
                BinaryNode& node = nodes_[t.node];
                const std::size_t middle = split(t.begin, t.end, t.depth, node);
                if (middle == t.end) continue;  // a leaf
                const auto children = nextNode_.fetch_add(2);
                node.first = children;
                for (const Task child : {Task{middle, t.end, children + 1, t.depth + 1},
                                         Task{t.begin, middle, children, t.depth + 1}}) {
                    if (child.end - child.begin >= kParallelGrain) {
                        const std::lock_guard lock(mutex_);
                        ++outstanding_;
                        queue_.push_back(child);
                        wake_.notify_one();
                    } else {
                        local.push_back(child);
                    }
                }
            }
            const std::lock_guard lock(mutex_);
            if (--outstanding_ == 0) wake_.notify_all();
        }
    }

    // Fills `node`'s bounds and either makes it a leaf (returns end) or partitions the range and
    // returns where the second child starts.
    std::size_t split(std::size_t begin, std::size_t end, int depth, BinaryNode& node) {
        Bounds bounds, centroids;
        for (std::size_t i = begin; i < end; ++i) {
            bounds.grow(items_[i].bounds);
            centroids.grow(items_[i].centroid);
        }
        for (int a = 0; a < 3; ++a) {
            node.lo[a] = bounds.lo[a];
            node.hi[a] = bounds.hi[a];
        }
        node.count = 0;
        const std::size_t count = end - begin;
        const auto makeLeaf = [&] {
            node.first = static_cast<std::uint32_t>(begin);
            node.count = static_cast<std::uint32_t>(count);
            return end;
        };
        if (count == 1) return makeLeaf();

        const Vec3 extent = centroids.hi - centroids.lo;
        const int widest = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
        if (depth < kSahDepthLimit && extent[widest] > 0.0f) {
            const Split best = findSplit(begin, end, centroids);
            const float leafCost = blocks(count);
            const float splitCost = kTraversalCost + best.cost / bounds.halfArea();
            if (count <= kBvhLeafSize && !(splitCost < leafCost)) return makeLeaf();
            if (best.axis >= 0) {
                const int axis = best.axis;
                const float lo = centroids.lo[axis];
                const float scale = kBins / (centroids.hi[axis] - centroids.lo[axis]);
                const auto mid = std::partition(items_.begin() + static_cast<std::ptrdiff_t>(begin),
                                                items_.begin() + static_cast<std::ptrdiff_t>(end),
                                                [&](const Item& p) {
                                                    return binOf(p.centroid[axis], lo, scale) <= best.bin;
                                                });
                const auto middle = static_cast<std::size_t>(mid - items_.begin());
                if (middle > begin && middle < end) return middle;
            }
        }
        if (count <= kBvhLeafSize) return makeLeaf();
        // Coincident centroids, or too deep: halve the range along the widest axis by centroid
        // (ties in id order, so the build is deterministic).
        const std::size_t middle = begin + count / 2;
        std::nth_element(items_.begin() + static_cast<std::ptrdiff_t>(begin),
                         items_.begin() + static_cast<std::ptrdiff_t>(middle),
                         items_.begin() + static_cast<std::ptrdiff_t>(end), [&](const Item& a, const Item& b) {
                             const float ca = a.centroid[widest], cb = b.centroid[widest];
                             return ca < cb || (ca == cb && a.id < b.id);
                         });
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
            const Item& item = items_[i];
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
                rightCost[static_cast<std::size_t>(b)] = right.halfArea() * blocks(rightCount);
            }
            Bounds left;
            std::uint32_t leftCount = 0;
            for (int b = 0; b < kBins - 1; ++b) {
                left.grow(axisBins[static_cast<std::size_t>(b)].bounds);
                leftCount += axisBins[static_cast<std::size_t>(b)].count;
                if (leftCount == 0 || leftCount == end - begin) continue;
                const float cost = left.halfArea() * blocks(leftCount) + rightCost[static_cast<std::size_t>(b + 1)];
                if (cost < best.cost) best = {axis, b, cost};
            }
        }
        return best;
    }

    std::vector<Item> items_;
    std::unique_ptr<BinaryNode[]> nodes_;
    std::atomic<std::uint32_t> nextNode_{1};
    std::mutex mutex_;
    std::condition_variable wake_;
    std::vector<Task> queue_;
    std::size_t outstanding_ = 0;
};

// Turns the binary tree into 8-wide nodes, depth first: a wide node takes its binary node's
// children and, while it has room, opens the interior child of largest surface area (the one a
// ray most likely enters) in place. Leaves get one block of slots each.
class Collapser {
public:
    Collapser(const BinaryBuilder& binary, std::vector<BvhNode>& nodes, std::vector<std::uint32_t>& ids)
        : binary_(binary), nodes_(nodes), ids_(ids) {}

    std::uint32_t collapse(std::uint32_t index) {
        const BinaryNode& b = binary_.node(index);
        if (b.count > 0) return leaf(b);
        const auto wide = static_cast<std::uint32_t>(nodes_.size());
        nodes_.emplace_back();
        std::array<std::uint32_t, kBvhWidth> open{b.first, b.first + 1};
        int n = 2;
        while (n < kBvhWidth) {
            int widest = -1;
            float widestArea = -1.0f;
            for (int i = 0; i < n; ++i) {
                const BinaryNode& c = binary_.node(open[static_cast<std::size_t>(i)]);
                if (c.count == 0 && c.bounds().halfArea() > widestArea) {
                    widest = i;
                    widestArea = c.bounds().halfArea();
                }
            }
            if (widest < 0) break;
            const std::uint32_t first = binary_.node(open[static_cast<std::size_t>(widest)]).first;
            for (int i = n; i > widest + 1; --i) open[static_cast<std::size_t>(i)] = open[static_cast<std::size_t>(i - 1)];
            open[static_cast<std::size_t>(widest)] = first;
            open[static_cast<std::size_t>(widest) + 1] = first + 1;
            ++n;
        }
        for (int lane = 0; lane < kBvhWidth; ++lane) {
            Bounds box;  // empty for an unused lane: lo = +inf, hi = -inf
            std::uint32_t child = BvhChild::kEmpty;
            if (lane < n) {
                box = binary_.node(open[static_cast<std::size_t>(lane)]).bounds();
                child = collapse(open[static_cast<std::size_t>(lane)]);
            }
            BvhNode& node = nodes_[wide];  // collapse() may have moved the nodes
            for (int a = 0; a < 3; ++a) {
                node.planes[0][a][lane] = box.lo[a];
                node.planes[1][a][lane] = box.hi[a];
            }
            node.children[lane] = child;
        }
        return wide;
    }

private:
    std::uint32_t leaf(const BinaryNode& b) {
        const auto block = static_cast<std::uint32_t>(ids_.size() / kBvhLeafSize);
        for (std::uint32_t i = 0; i < kBvhLeafSize; ++i)
            ids_.push_back(i < b.count ? binary_.items()[b.first + i].id : kBvhEmptySlot);
        return BvhChild::leaf(block, b.count);
    }

    const BinaryBuilder& binary_;
    std::vector<BvhNode>& nodes_;
    std::vector<std::uint32_t>& ids_;
};

}  // namespace

Bvh::Bvh(std::vector<BvhPrimitive> primitives, unsigned threads) : path_(simd::activePath()) {
    const auto started = std::chrono::steady_clock::now();
    // Each leaf takes a block of kBvhLeafSize slots, and a block index has 29 bits.
    if (primitives.size() > (std::size_t{BvhChild::kBlockMask} + 1) / 2)
        throw std::length_error("too many primitives for a BVH with 29-bit block indices");
    if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
    // Below the grain no subtree is shared: starting threads would cost more than the build.
    if (primitives.size() < 2 * kParallelGrain) threads = 1;
    if (!primitives.empty()) {
        BinaryBuilder binary(primitives);
        primitives = {};  // the builder works on its own copy: free this one before the build's peak
        binary.build(threads);
        // A wide node replaces at least one binary interior node; a leaf takes at most
        // kBvhLeafSize slots per primitive, usually far fewer.
        nodes_.reserve(binary.items().size() / 2 + 1);
        ids_.reserve(binary.items().size() * 2);
        Collapser collapser(binary, nodes_, ids_);
        root_ = collapser.collapse(0);
    }
    stats_.buildSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    stats_.nodes = nodes_.size();
    stats_.nodeBytes = nodes_.size() * sizeof(BvhNode);
    stats_.leaves = ids_.size() / kBvhLeafSize;
    stats_.primitives = static_cast<std::size_t>(std::count_if(ids_.begin(), ids_.end(), [](std::uint32_t id) {
        return id != kBvhEmptySlot;
    }));
}

}  // namespace lightpath
