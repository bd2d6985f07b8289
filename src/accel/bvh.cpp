#include "accel/bvh.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <chrono>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "util/parallel_chunks.h"

namespace lightpath {
namespace {

using simd::Float4;

constexpr int kBins = 16;
// A block's primitives are tested four at once, so the SAH counts blocks of kBvhLeafSize, not
// primitives (as Embree's builders do for their 4-triangle leaves).
float blocks(std::size_t count) {
    return static_cast<float>((count + kBvhLeafSize - 1) / kBvhLeafSize);
}
// Below this depth splits follow the SAH; deeper (only in pathological inputs) they halve the
// range, so the depth stays within what bvh_detail::kStackSize allows.
constexpr int kSahDepthLimit = 64;
// A range that fits one block is still split when its two sides' areas sum to less than this
// share of its own: two flat leaves (a room's floor and a wall) then take the rays one L-shaped
// leaf's box would. The rest of 1 is the cost of the step to the extra leaf against a leaf's
// test: the two leaves are lanes of a wide node tested anyway, or stay one leaf where the collapse
// has no lanes for them (Collapser::oneBlock; docs/performance.md, Small leaves split).
constexpr float kSmallSplitAreaShare = 0.9f;
// A subtree at least this large goes to the shared queue, where an idle thread may take it;
// smaller ones are built depth-first by the thread that split their parent.
constexpr std::size_t kParallelGrain = 4096;
// A range at least this large is binned in chunks of kChunkSize items that every idle thread
// helps with (Embree's parallel binning), so two threads share the top splits, which otherwise run
// on one; bins merge exactly (min, max, sums), so the bins are those of one pass. The partition
// that follows stays in place on one thread: it costs a third of the binning, and an
// out-of-place parallel one would touch a second array, whose first-touch page faults cost more.
constexpr std::size_t kChunkedGrain = 32768;
constexpr std::size_t kChunkSize = 4096;

std::size_t chunksOf(std::size_t count) { return (count + kChunkSize - 1) / kChunkSize; }

// A primitive as the builder moves it around: two 16-byte rows, its box's corners, with its id's
// bits in the low corner's fourth lane (Embree's PrimRef). Centroids are taken doubled, lo + hi:
// the factor 2 is exact, and the bin scale, computed from doubled centroids too, absorbs it, so
// every bin (hence the tree) is the one 0.5 * (lo + hi) gives.
struct alignas(16) Item {
    float lo[4];
    float hi[4];  // lane 3 is 0

    std::uint32_t id() const { return std::bit_cast<std::uint32_t>(lo[3]); }
    Float4 low() const { return Float4::load(lo); }
    Float4 high() const { return Float4::load(hi); }
    // The low corner without the id: as a float, an id is a denormal (or a NaN), and arithmetic
    // on denormals takes microcode assists on many processors.
    Float4 corner() const { return simd::xyzOnly(low()); }
    Float4 doubledCentroid() const { return corner() + high(); }
};

// A box in two registers (lane 3 is not part of it); empty: lo = +inf, hi = -inf.
struct Box {
    Float4 lo{std::numeric_limits<float>::infinity()};
    Float4 hi{-std::numeric_limits<float>::infinity()};

    void grow(Float4 low, Float4 high) {
        lo = simd::minKeepSecond(low, lo);
        hi = simd::maxKeepSecond(high, hi);
    }
    void grow(const Box& b) { grow(b.lo, b.hi); }
    void grow(Float4 p) { grow(p, p); }
    // Bounds::halfArea's expression, float for float, for a box that holds something.
    float nonEmptyHalfArea() const {
        alignas(16) float d[4];
        (hi - lo).store(d);
        return d[0] * d[1] + d[1] * d[2] + d[2] * d[0];
    }
};

// Centroid bins of all three axes (Wald 2007).
struct Bins {
    Box boxes[3][kBins];
    std::uint32_t counts[3][kBins]{};

    void merge(const Bins& other) {
        for (int a = 0; a < 3; ++a) {
            for (int b = 0; b < kBins; ++b) {
                boxes[a][b].grow(other.boxes[a][b]);
                counts[a][b] += other.counts[a][b];
            }
        }
    }
};

// Where doubled centroids fall: (c - origin) * scale along each axis, in bin widths. The same
// expression decides an item's bin and its side of the chosen split, so the children hold
// exactly the items the bins counted.
struct Binning {
    Float4 origin, scale;

    explicit Binning(const Box& centroids) : origin(centroids.lo) {
        alignas(16) float lo[4], hi[4], s[4] = {0.0f, 0.0f, 0.0f, 0.0f};
        centroids.lo.store(lo);
        centroids.hi.store(hi);
        for (int a = 0; a < 3; ++a) {
            const float width = hi[a] - lo[a];
            if (width > 0.0f) s[a] = kBins / width;
        }
        scale = Float4::load(s);
    }
    Float4 position(Float4 doubledCentroid) const { return (doubledCentroid - origin) * scale; }
    // clamp(int(position), 0, kBins - 1) per axis; clamping first keeps the conversion in range.
    void bins(Float4 doubledCentroid, std::int32_t* out) const {
        const Float4 clamped = simd::minKeepSecond(simd::maxKeepSecond(position(doubledCentroid), Float4(0.0f)),
                                                   Float4(static_cast<float>(kBins - 1)));
        simd::truncateToInts(clamped, out);
    }
    void add(const Item* items, std::size_t count, Bins& to) const {
        for (std::size_t i = 0; i < count; ++i) {
            const Float4 lo = items[i].corner(), hi = items[i].high();
            alignas(16) std::int32_t bin[4];
            bins(lo + hi, bin);
            for (int a = 0; a < 3; ++a) {
                to.boxes[a][bin[a]].grow(lo, hi);
                ++to.counts[a][bin[a]];
            }
        }
    }
};

struct Split {
    int axis = -1;
    int bin = 0;  // primitives in bins [0, bin] go left
    float cost = std::numeric_limits<float>::infinity();

    // An item's side: bin <= this->bin, which is position < bin + 1 (bin + 1 <= kBins - 1, so the
    // clamp to the last bin never decides; a NaN position is bin 0, left, here too).
    bool left(const Binning& binning, Float4 doubledCentroid) const {
        const int atOrAbove = simd::lessEqual(Float4(static_cast<float>(bin + 1)), binning.position(doubledCentroid));
        return (atOrAbove >> axis & 1) == 0;
    }
};

// The cheapest bin boundary over the three axes; cost is sum(area * blocks) of both sides (half
// areas, unnormalised). Only non-empty bins are visited: an empty bin leaves both sides' boxes
// and counts, so its boundary costs what the previous one did and never wins (a split must be
// strictly cheaper), which keeps the choice exactly that of the full sweep while small ranges,
// most of the tree, fill only a few of the bins.
Split findSplit(const Bins& bins, std::size_t count, const Binning& binning) {
    alignas(16) float scale[4];
    binning.scale.store(scale);
    Split best;
    for (int axis = 0; axis < 3; ++axis) {
        if (scale[axis] == 0.0f) continue;
        const std::uint32_t* counts = bins.counts[axis];
        // Sweep from the right to get each suffix's cost (0 while it is empty), then from the left.
        std::array<float, kBins> rightCost;
        Box right;
        std::uint32_t rightCount = 0;
        float suffixCost = 0.0f;
        for (int b = kBins - 1; b > 0; --b) {
            if (counts[b] != 0) {
                right.grow(bins.boxes[axis][b]);
                rightCount += counts[b];
                suffixCost = right.nonEmptyHalfArea() * blocks(rightCount);
            }
            rightCost[static_cast<std::size_t>(b)] = suffixCost;
        }
        Box left;
        std::uint32_t leftCount = 0;
        for (int b = 0; b < kBins - 1; ++b) {
            if (counts[b] == 0) continue;
            left.grow(bins.boxes[axis][b]);
            leftCount += counts[b];
            if (leftCount == count) break;
            const float cost = left.nonEmptyHalfArea() * blocks(leftCount) + rightCost[static_cast<std::size_t>(b + 1)];
            if (cost < best.cost) best = {axis, b, cost};
        }
    }
    return best;
}

// The best SAH split of a range that fits one block, over every way to cut its items in two (at
// most seven for four): each side is one block, so a cut costs its two boxes' half areas. The
// boxes of all subsets are built up from smaller ones, a grow each.
struct SmallSplit {
    unsigned left = 0;  // bit i: item i goes left; 0: no split
    float cost = std::numeric_limits<float>::infinity();
};

SmallSplit findSmallSplit(const Item* items, std::size_t count) {
    constexpr unsigned kSubsets = 1u << kBvhLeafSize;
    std::array<Box, kSubsets> boxes;  // boxes[0] is empty
    std::array<float, kSubsets> area;
    const unsigned all = (1u << count) - 1u;
    for (unsigned m = 1; m <= all; ++m) {
        const int item = std::countr_zero(m);
        boxes[m] = boxes[m & (m - 1u)];
        boxes[m].grow(items[item].corner(), items[item].high());
        area[m] = boxes[m].nonEmptyHalfArea();
    }
    // Each cut once (the last item stays right); ties keep the first mask, so the build is deterministic.
    SmallSplit best;
    for (unsigned m = 1; m < (1u << (count - 1)); ++m) {
        const float cost = area[m] + area[all ^ m];
        if (cost < best.cost) best = {m, cost};
    }
    return best;
}

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

// A loop over chunks that the thread running it shares with idle threads. Helpers register
// under the builder's mutex while the loop is listed, so the owner, after unlisting it, knows
// when the last chunk is done.
struct ChunkLoop {
    void (*run)(const void* body, std::size_t chunk);
    const void* body;
    std::size_t chunks;
    std::atomic<std::size_t> next{0};
    int helpers = 0;  // guarded by the builder's mutex

    void runChunks() {
        for (std::size_t chunk; (chunk = next.fetch_add(1, std::memory_order_relaxed)) < chunks;) run(body, chunk);
    }
};

// Builds the binary tree. Every split depends only on the items of its own range (binned in
// chunks or in one pass, the bins are the same), and threads work on disjoint ranges, so the
// tree's shape and the items' order are the same for any number of threads; only the binary
// nodes' indices vary, and collapse() reads the tree in child order.
class BinaryBuilder {
public:
    explicit BinaryBuilder(std::size_t count) : count_(count), items_(std::make_unique_for_overwrite<Item[]>(count)) {}

    void build(const Bvh::PrimitiveSource& primitives, unsigned threads) {
        threads_ = threads;
        // A binary tree over N primitives has at most 2N - 1 nodes; each thread may leave part of
        // its last block unused. Pages never written are never resident.
        nodes_ = std::make_unique_for_overwrite<BinaryNode[]>(2 * count_ - 1 + threads * kNodeBlock);
        nextNode_ = 1;
        outstanding_ = 1;  // the root, pushed once the items exist; until then workers only help
        std::vector<std::jthread> workers;
        for (unsigned t = 1; t < threads; ++t) workers.emplace_back([this] { work(); });
        Task root{0, count_, 0, 0, {}, {}};
        convert(primitives, root);
        {
            const std::lock_guard lock(mutex_);
            queue_.push_back(root);
        }
        wake_.notify_all();
        work();
    }

    const Item* items() const { return items_.get(); }
    const BinaryNode& node(std::uint32_t index) const { return nodes_[index]; }

private:
    // Node indices a thread hands out, taken from the shared count kNodeBlock at a time: one
    // atomic add per split, and threads writing the same cache lines, cost more than the splits.
    static constexpr std::uint32_t kNodeBlock = 64;  // even: children come in pairs
    struct NodeBlock {
        std::uint32_t next = 0, end = 0;
    };

    struct Task {
        std::size_t begin, end;
        std::uint32_t node;
        int depth;
        Box box, centroids;  // of the range's items' boxes and of their doubled centroids
    };

    // Items from the primitives, and the root's boxes, in parallel chunks.
    void convert(const Bvh::PrimitiveSource& primitives, Task& root) {
        const std::size_t chunks = chunksOf(count_);
        std::vector<std::array<Box, 2>> boxes(chunks);
        forEachChunk(chunks, [&](std::size_t chunk) {
            const std::size_t begin = chunk * kChunkSize, end = std::min(count_, begin + kChunkSize);
            Box box, centroids;
            constexpr std::size_t kBatch = 256;  // asked of the source at once, kept on the stack
            std::array<BvhPrimitive, kBatch> batch;
            for (std::size_t from = begin; from < end; from += kBatch) {
                const std::size_t to = std::min(end, from + kBatch);
                primitives(from, to, batch.data());
                for (std::size_t i = from; i < to; ++i) {
                    const BvhPrimitive& p = batch[i - from];
                    Item& item = items_[i];
                    item = {{p.bounds.lo.x, p.bounds.lo.y, p.bounds.lo.z, std::bit_cast<float>(p.id)},
                            {p.bounds.hi.x, p.bounds.hi.y, p.bounds.hi.z, 0.0f}};
                    box.grow(item.corner(), item.high());
                    centroids.grow(item.doubledCentroid());
                }
            }
            boxes[chunk] = {box, centroids};
        });
        for (const auto& [box, centroids] : boxes) {
            root.box.grow(box);
            root.centroids.grow(centroids);
        }
    }

    template <typename Body>
    void forEachChunk(std::size_t chunks, const Body& body) {
        if (threads_ == 1 || chunks == 1) {
            for (std::size_t chunk = 0; chunk < chunks; ++chunk) body(chunk);
            return;
        }
        ChunkLoop loop{[](const void* b, std::size_t chunk) { (*static_cast<const Body*>(b))(chunk); }, &body, chunks};
        {
            const std::lock_guard lock(mutex_);
            loops_.push_back(&loop);
        }
        wake_.notify_all();
        loop.runChunks();
        std::unique_lock lock(mutex_);
        loops_.erase(std::find(loops_.begin(), loops_.end(), &loop));
        loopDone_.wait(lock, [&] { return loop.helpers == 0; });
    }

    // A listed loop with chunks left to claim (the caller holds the mutex).
    ChunkLoop* openLoop() const {
        for (ChunkLoop* loop : loops_)
            if (loop->next.load(std::memory_order_relaxed) < loop->chunks) return loop;
        return nullptr;
    }

    void work() {
        std::vector<Task> local;
        NodeBlock block;
        for (;;) {
            Task task;
            ChunkLoop* loop = nullptr;
            {
                std::unique_lock lock(mutex_);
                wake_.wait(lock, [&] {
                    return !queue_.empty() || (loop = openLoop()) != nullptr || outstanding_ == 0;
                });
                if (!queue_.empty()) {
                    task = queue_.back();
                    queue_.pop_back();
                    loop = nullptr;
                } else if (loop != nullptr) {
                    ++loop->helpers;
                } else {
                    return;
                }
            }
            if (loop != nullptr) {
                loop->runChunks();
                const std::lock_guard lock(mutex_);
                if (--loop->helpers == 0) loopDone_.notify_all();
                continue;
            }
            local.push_back(task);
            while (!local.empty()) {
                const Task t = local.back();
                local.pop_back();
                Task children[2];
                if (!split(t, children, block)) continue;  // a leaf
                for (const Task& child : {children[1], children[0]}) {
                    if (child.end - child.begin >= kParallelGrain) {
                        {
                            const std::lock_guard lock(mutex_);
                            ++outstanding_;
                            queue_.push_back(child);
                        }
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

    // Fills the task's node and either makes it a leaf (returns false) or partitions its range
    // into two child tasks, each with its boxes: the SAH sweep's side boxes and the centroid
    // boxes the partition grows, so no node needs a pass of its own to find them.
    bool split(const Task& t, Task (&children)[2], NodeBlock& block) {
        BinaryNode& node = nodes_[t.node];
        alignas(16) float lo[4], hi[4];
        t.box.lo.store(lo);
        t.box.hi.store(hi);
        for (int a = 0; a < 3; ++a) {
            node.lo[a] = lo[a];
            node.hi[a] = hi[a];
        }
        node.count = 0;
        const std::size_t count = t.end - t.begin;
        // Larger ranges are always split (a leaf holds one block); one that fits a block is a
        // leaf unless its best split's two sides are much smaller than it.
        SmallSplit small;
        if (count <= kBvhLeafSize) {
            const float limit = kSmallSplitAreaShare * t.box.nonEmptyHalfArea();
            if (count > 1 && t.depth < kSahDepthLimit) small = findSmallSplit(&items_[t.begin], count);
            if (!(small.cost < limit)) {
                node.first = static_cast<std::uint32_t>(t.begin);
                node.count = static_cast<std::uint32_t>(count);
                return false;
            }
        }
        if (block.next == block.end) {
            block.next = nextNode_.fetch_add(kNodeBlock, std::memory_order_relaxed);
            block.end = block.next + kNodeBlock;
        }
        const std::uint32_t first = block.next;
        block.next += 2;
        node.first = first;
        children[0] = {t.begin, 0, first, t.depth + 1, {}, {}};
        children[1] = {0, t.end, first + 1, t.depth + 1, {}, {}};
        Item* const range = &items_[t.begin];
        if (small.left != 0) {
            // The left items first, then the right ones, each side in its order.
            std::array<Item, kBvhLeafSize> sides;
            std::size_t placed = 0;
            for (const unsigned goesLeft : {1u, 0u})
                for (std::size_t i = 0; i < count; ++i)
                    if ((small.left >> i & 1u) == goesLeft) sides[placed++] = range[i];
            std::copy(sides.begin(), sides.begin() + static_cast<std::ptrdiff_t>(count), range);
            splitAt(t.begin + static_cast<std::size_t>(std::popcount(small.left)), children);
            return true;
        }

        alignas(16) float extent[4];
        (t.centroids.hi - t.centroids.lo).store(extent);
        const int widest = extent[0] >= extent[1] && extent[0] >= extent[2] ? 0 : (extent[1] >= extent[2] ? 1 : 2);
        if (t.depth < kSahDepthLimit && extent[widest] > 0.0f) {
            const Binning binning(t.centroids);
            const bool chunked = count >= kChunkedGrain;
            std::vector<Bins> chunkBins;
            Bins bins;
            if (chunked) {
                chunkBins.resize(chunksOf(count));
                forEachChunk(chunkBins.size(), [&](std::size_t chunk) {
                    const std::size_t begin = t.begin + chunk * kChunkSize;
                    binning.add(&items_[begin], std::min(kChunkSize, t.end - begin), chunkBins[chunk]);
                });
                for (const Bins& b : chunkBins) bins.merge(b);
            } else {
                binning.add(&items_[t.begin], count, bins);
            }
            const Split best = findSplit(bins, count, binning);
            if (best.axis >= 0) {
                for (int b = 0; b < kBins; ++b) children[b <= best.bin ? 0 : 1].box.grow(bins.boxes[best.axis][b]);
                const std::size_t middle = partition(t, binning, best, children);
                children[0].end = children[1].begin = middle;
                return true;  // both sides hold items: the sweep only takes splits that leave none empty
            }
        }
        // Coincident centroids, or too deep: halve the range along the widest axis by centroid
        // (ties in id order, so the build is deterministic).
        std::nth_element(range, range + count / 2, range + count, [&](const Item& a, const Item& b) {
            const float ca = a.lo[widest] + a.hi[widest], cb = b.lo[widest] + b.hi[widest];
            return ca < cb || (ca == cb && a.id() < b.id());
        });
        splitAt(t.begin + count / 2, children);
        return true;
    }

    // The children's ranges end and begin at `middle`; their boxes from their items.
    void splitAt(std::size_t middle, Task (&children)[2]) const {
        children[0].end = children[1].begin = middle;
        for (Task& child : children) {
            for (std::size_t i = child.begin; i < child.end; ++i) {
                child.box.grow(items_[i].corner(), items_[i].high());
                child.centroids.grow(items_[i].doubledCentroid());
            }
        }
    }

    // In place, swapping from both ends in the order std::partition takes for bidirectional
    // iterators, each item classified once; grows each side's centroid box.
    std::size_t partition(const Task& t, const Binning& binning, const Split& split, Task (&children)[2]) {
        Item* first = &items_[t.begin];
        Item* last = &items_[t.begin] + (t.end - t.begin);
        Box& leftCentroids = children[0].centroids;
        Box& rightCentroids = children[1].centroids;
        for (;;) {
            Float4 c;
            for (;;) {
                if (first == last) return static_cast<std::size_t>(first - items_.get());
                c = first->doubledCentroid();
                if (!split.left(binning, c)) break;
                leftCentroids.grow(c);
                ++first;
            }
            --last;
            for (;;) {
                if (first == last) {
                    rightCentroids.grow(c);
                    return static_cast<std::size_t>(first - items_.get());
                }
                const Float4 d = last->doubledCentroid();
                if (split.left(binning, d)) {
                    leftCentroids.grow(d);
                    break;
                }
                rightCentroids.grow(d);
                --last;
            }
            rightCentroids.grow(c);
            std::swap(*first, *last);
            ++first;
        }
    }

    std::size_t count_;
    std::unique_ptr<Item[]> items_;
    std::unique_ptr<BinaryNode[]> nodes_;
    unsigned threads_ = 1;
    std::atomic<std::uint32_t> nextNode_{1};
    std::mutex mutex_;
    std::condition_variable wake_;
    std::condition_variable loopDone_;
    std::vector<Task> queue_;
    std::vector<ChunkLoop*> loops_;
    std::size_t outstanding_ = 0;
};

// Where the collapse writes next: the final arrays, and the next free node and leaf block.
struct WideCursor {
    BvhNode* nodes;
    std::uint32_t* ids;
    std::uint32_t node;
    std::uint32_t block;
};

// Turns the binary tree into 8-wide nodes, depth first: a wide node takes its binary node's
// children and, while it has room, opens the interior child of largest surface area (the one a
// ray most likely enters) in place. Leaves get one block of slots each.
class Collapser {
public:
    explicit Collapser(const BinaryBuilder& binary) : binary_(binary) {}

    // The binary nodes that become the lanes of the wide node for interior node `b`; their count.
    int lanes(const BinaryNode& b, std::array<std::uint32_t, kBvhWidth>& open) const {
        open[0] = b.first;
        open[1] = b.first + 1;
        // Each open child's half area, computed once; -1 for a leaf, which is never opened.
        std::array<float, kBvhWidth> area{interiorArea(b.first), interiorArea(b.first + 1)};
        int n = 2;
        while (n < kBvhWidth) {
            int widest = -1;
            float widestArea = -1.0f;
            for (int i = 0; i < n; ++i) {
                if (area[static_cast<std::size_t>(i)] > widestArea) {
                    widest = i;
                    widestArea = area[static_cast<std::size_t>(i)];
                }
            }
            if (widest < 0) break;
            const std::uint32_t first = binary_.node(open[static_cast<std::size_t>(widest)]).first;
            for (int i = n; i > widest + 1; --i) {
                open[static_cast<std::size_t>(i)] = open[static_cast<std::size_t>(i - 1)];
                area[static_cast<std::size_t>(i)] = area[static_cast<std::size_t>(i - 1)];
            }
            open[static_cast<std::size_t>(widest)] = first;
            open[static_cast<std::size_t>(widest) + 1] = first + 1;
            area[static_cast<std::size_t>(widest)] = interiorArea(first);
            area[static_cast<std::size_t>(widest) + 1] = interiorArea(first + 1);
            ++n;
        }
        return n;
    }

    // How many wide nodes and leaf blocks the subtree under binary node `index` becomes.
    std::array<std::uint32_t, 2> size(std::uint32_t index) const {
        const BinaryNode& b = binary_.node(index);
        if (oneBlock(index).count > 0) return {0, 1};
        std::array<std::uint32_t, kBvhWidth> open;
        const int n = lanes(b, open);
        std::array<std::uint32_t, 2> total{1, 0};
        for (int lane = 0; lane < n; ++lane) {
            const auto [nodes, blocks] = size(open[static_cast<std::size_t>(lane)]);
            total[0] += nodes;
            total[1] += blocks;
        }
        return total;
    }

    // Writes the subtree under binary node `index` at the cursor, depth first; returns its child
    // reference.
    std::uint32_t collapse(std::uint32_t index, WideCursor& at) const {
        const BinaryNode& b = binary_.node(index);
        if (const ItemRange leaf = oneBlock(index); leaf.count > 0) {
            const std::uint32_t block = at.block++;
            for (std::uint32_t i = 0; i < kBvhLeafSize; ++i)
                at.ids[kBvhLeafSize * block + i] = i < leaf.count ? binary_.items()[leaf.first + i].id() : kBvhEmptySlot;
            return BvhChild::leaf(block, leaf.count);
        }
        const std::uint32_t wide = at.node++;
        std::array<std::uint32_t, kBvhWidth> open;
        const int n = lanes(b, open);
        for (int lane = 0; lane < kBvhWidth; ++lane) {
            const bool used = lane < n;
            const std::uint32_t child = used ? collapse(open[static_cast<std::size_t>(lane)], at) : BvhChild::kEmpty;
            setLane(at.nodes[wide], lane, used ? &binary_.node(open[static_cast<std::size_t>(lane)]) : nullptr, child);
        }
        return wide;
    }

    // Lane `lane` of `node`: the box of binary node `b` (empty without one: lo = +inf, hi = -inf).
    static void setLane(BvhNode& node, int lane, const BinaryNode* b, std::uint32_t child) {
        const Bounds box = b != nullptr ? b->bounds() : Bounds{};
        for (int a = 0; a < 3; ++a) {
            node.planes[0][a][lane] = box.lo[a];
            node.planes[1][a][lane] = box.hi[a];
        }
        node.children[lane] = child;
    }

private:
    struct ItemRange {
        std::uint32_t first = 0;
        std::uint32_t count = 0;  // 0: more than one block
    };
    // The items under binary node `index` when they fit one block: a leaf's, or a small split's
    // (findSmallSplit) that reached here unopened. Its two leaves pay only as lanes
    // of a wide node tested anyway; as a wide node of their own they would cost a node test more
    // than the one leaf. A subtree's items are adjacent (the partition is in place), and a split
    // of one block's items is at most kBvhLeafSize - 1 levels deep.
    ItemRange oneBlock(std::uint32_t index, std::uint32_t levels = kBvhLeafSize - 1) const {
        const BinaryNode& b = binary_.node(index);
        if (b.count > 0) return {b.first, b.count};
        if (levels == 0) return {};
        const ItemRange left = oneBlock(b.first, levels - 1);
        if (left.count == 0) return {};
        const ItemRange right = oneBlock(b.first + 1, levels - 1);
        if (right.count == 0 || left.count + right.count > kBvhLeafSize) return {};
        return {left.first, left.count + right.count};
    }

    float interiorArea(std::uint32_t index) const {
        const BinaryNode& c = binary_.node(index);
        return c.count == 0 ? c.bounds().halfArea() : -1.0f;
    }

    const BinaryBuilder& binary_;
};

}  // namespace

Bvh::Bvh(std::vector<BvhPrimitive> primitives, unsigned threads)
    : Bvh(
          primitives.size(),
          [&](std::size_t begin, std::size_t end, BvhPrimitive* out) {
              std::copy(primitives.begin() + static_cast<std::ptrdiff_t>(begin),
                        primitives.begin() + static_cast<std::ptrdiff_t>(end), out);
          },
          threads) {}

Bvh::Bvh(std::size_t count, const PrimitiveSource& source, unsigned threads) : path_(simd::activePath()) {
    const auto started = std::chrono::steady_clock::now();
    // Each leaf takes a block of kBvhLeafSize slots, and a block index has 29 bits.
    if (count > (std::size_t{BvhChild::kBlockMask} + 1) / 2)
        throw std::length_error("too many primitives for a BVH with 29-bit block indices");
    threads = threadsOrAll(threads);
    // Below the grain no subtree is shared: starting threads would cost more than the build.
    if (count < 2 * kParallelGrain) threads = 1;
    if (count > 0) {
        BinaryBuilder binary(count);
        binary.build(source, threads);
        const Collapser collapser(binary);
        const BinaryNode& top = binary.node(0);
        if (count <= kBvhLeafSize) {  // one leaf, even where the SAH split it (Collapser::oneBlock)
            ids_.resize(kBvhLeafSize);
            WideCursor at{nullptr, ids_.data(), 0, 0};
            root_ = collapser.collapse(0, at);
        } else {
            // The root's lanes' subtrees are sized, then written where one depth-first pass would
            // put them (after the root, in lane order), each on whichever build thread is free.
            std::array<std::uint32_t, kBvhWidth> open;
            const auto n = static_cast<std::size_t>(collapser.lanes(top, open));
            std::array<std::array<std::uint32_t, 2>, kBvhWidth> sizes;
            parallelChunks(n, 1, threads,
                           [&](std::size_t lane, std::size_t) { sizes[lane] = collapser.size(open[lane]); });
            std::array<WideCursor, kBvhWidth> cursors;
            std::uint32_t nodeCount = 1, blockCount = 0;
            for (std::size_t lane = 0; lane < n; ++lane) {
                cursors[lane] = {nullptr, nullptr, nodeCount, blockCount};
                nodeCount += sizes[lane][0];
                blockCount += sizes[lane][1];
            }
            nodes_.resize(nodeCount);
            ids_.resize(std::size_t{blockCount} * kBvhLeafSize);
            std::array<std::uint32_t, kBvhWidth> children;
            parallelChunks(n, 1, threads, [&](std::size_t lane, std::size_t) {
                cursors[lane].nodes = nodes_.data();
                cursors[lane].ids = ids_.data();
                children[lane] = collapser.collapse(open[lane], cursors[lane]);
            });
            for (std::size_t lane = 0; lane < kBvhWidth; ++lane)
                Collapser::setLane(nodes_[0], static_cast<int>(lane), lane < n ? &binary.node(open[lane]) : nullptr,
                                   lane < n ? children[lane] : BvhChild::kEmpty);
            root_ = 0;
        }
    }
    stats_.buildSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    stats_.nodes = nodes_.size();
    stats_.nodeBytes = nodes_.size() * sizeof(BvhNode);
    stats_.leaves = ids_.size() / kBvhLeafSize;
    stats_.primitives = count;  // each in exactly one leaf
}

}  // namespace lightpath
