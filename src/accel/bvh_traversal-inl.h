// Closest-hit and any-hit traversal of a Bvh's 8-wide nodes, written once and compiled once per
// SIMD path: bvh_traversal.h includes this file twice (no include guard), with LIGHTPATH_BVH_AVX2 0 for
// the baseline (a node as two SSE2 halves; simd.h) and 1, between LIGHTPATH_BEGIN_AVX2 and
// LIGHTPATH_END_AVX2, for AVX2 (a node in one register). Each copy lives in its own namespace,
// so the two never meet at link time. Includes belong in bvh.h, outside the AVX2 region.

#if LIGHTPATH_BVH_AVX2
namespace lightpath::bvh_avx2 {

// The eight lanes of a node in one AVX register. Comparisons are ordered (false for a NaN) and
// max/min return their second operand for a NaN, exactly as SSE2's do.
struct Float8 {
    __m256 v;

    Float8() = default;
    explicit Float8(__m256 value) : v(value) {}
    explicit Float8(float s) : v(_mm256_set1_ps(s)) {}
    static Float8 load(const float* p) { return Float8(_mm256_load_ps(p)); }  // 32-byte aligned
    void store(float* p) const { _mm256_store_ps(p, v); }
};
// Free functions, not hidden friends: GCC 12 does not apply `#pragma GCC target` to the latter.
inline Float8 operator-(Float8 a, Float8 b) { return Float8(_mm256_sub_ps(a.v, b.v)); }
inline Float8 operator*(Float8 a, Float8 b) { return Float8(_mm256_mul_ps(a.v, b.v)); }
inline int lessEqual(Float8 a, Float8 b) { return _mm256_movemask_ps(_mm256_cmp_ps(a.v, b.v, _CMP_LE_OQ)); }
inline Float8 maxKeepSecond(Float8 x, Float8 acc) { return Float8(_mm256_max_ps(x.v, acc.v)); }
inline Float8 minKeepSecond(Float8 x, Float8 acc) { return Float8(_mm256_min_ps(x.v, acc.v)); }

#else
namespace lightpath::bvh_baseline {

// The eight lanes of a node as two simd::Float4 halves.
struct Float8 {
    simd::Float4 low, high;

    Float8() = default;
    Float8(simd::Float4 l, simd::Float4 h) : low(l), high(h) {}
    explicit Float8(float s) : low(s), high(s) {}
    static Float8 load(const float* p) { return {simd::Float4::load(p), simd::Float4::load(p + 4)}; }
    void store(float* p) const {
        low.store(p);
        high.store(p + 4);
    }
};
inline Float8 operator-(Float8 a, Float8 b) { return {a.low - b.low, a.high - b.high}; }
inline Float8 operator*(Float8 a, Float8 b) { return {a.low * b.low, a.high * b.high}; }
inline int lessEqual(Float8 a, Float8 b) {
    return simd::lessEqual(a.low, b.low) | simd::lessEqual(a.high, b.high) << 4;
}
inline Float8 maxKeepSecond(Float8 x, Float8 acc) {
    return {simd::maxKeepSecond(x.low, acc.low), simd::maxKeepSecond(x.high, acc.high)};
}
inline Float8 minKeepSecond(Float8 x, Float8 acc) {
    return {simd::minKeepSecond(x.low, acc.low), simd::minKeepSecond(x.high, acc.high)};
}

#endif

static_assert(kBvhWidth == 8, "Float8 holds one node's lanes");

struct RaySetup {
    Float8 origin[3];
    Float8 inverse[3];
    Float8 farInverse[3];  // inverse grown by kFarPadding: the padding costs no multiply per node
    Float8 tMin;
    int nearSide[3];  // which of a node's planes[side] a ray enters an axis' slab through

    explicit RaySetup(const Ray& ray) : tMin(ray.tMin) {
        // 1/±0 is ±inf; a zero component then yields ±inf (or NaN on a slab plane), handled below.
        for (int a = 0; a < 3; ++a) {
            origin[a] = Float8(ray.origin[a]);
            inverse[a] = Float8(1.0f / ray.direction[a]);
            farInverse[a] = Float8(1.0f / ray.direction[a] * bvh_detail::kFarPadding);
            nearSide[a] = std::signbit(ray.direction[a]) ? 1 : 0;
        }
    }

    // The lanes whose box the ray enters within [tMin, tMax], and their entry distances. A NaN
    // slab distance (origin on a slab plane, direction parallel to it) leaves the interval as it
    // is: maxKeepSecond / minKeepSecond keep the accumulated bound.
    int enter(const BvhNode& node, Float8 tMax, Float8& entry) const {
        Float8 t0 = tMin, t1 = tMax;
        for (int a = 0; a < 3; ++a) {
            const Float8 nearPlane = Float8::load(node.planes[nearSide[a]][a]);
            const Float8 farPlane = Float8::load(node.planes[1 - nearSide[a]][a]);
            t0 = maxKeepSecond((nearPlane - origin[a]) * inverse[a], t0);
            t1 = minKeepSecond((farPlane - origin[a]) * farInverse[a], t1);
        }
        entry = t0;
        return lessEqual(t0, t1);
    }
};

// The order in which closest() pushes a node's entered lanes: farthest entry first, and among
// equal entries the lower lane first (a stable sort of the lanes by decreasing entry). Either
// path gives this same order, so both visit the same nodes in the same sequence.
// placeFarToNear(node, mask, entry, out) writes the n = popcount(mask) >= 2 entered lanes'
// (child, entry) pairs to out[0..n) in that order and returns n and the nearest child, out[n - 1]'s
// (n counted as it goes: the baseline has no popcnt instruction).
struct Placed {
    std::uint32_t nearest;
    int count;
};

// Two lanes a < b, the common case, with their entries t[]: one comparison, a first on a tie.
// A branch, on both paths: coherent rays predict it, and the processor runs ahead to the nearest
// child; a branch-free select puts the comparison on that path (tried, with the prefetches'
// leaf test also branch-free: 0.6 fewer mispredictions per random ray, but primary rays 5-8%
// slower on Zen 5 and random rays no faster; docs/performance.md, "Entered lanes ordered
// without branches").
inline Placed placeTwoFarToNear(const BvhNode& node, int a, int b, const float t[kBvhWidth], bvh_detail::Pending out[2]) {
    if (t[a] >= t[b]) {
        out[0] = {node.children[a], t[a]};
        out[1] = {node.children[b], t[b]};
        return {node.children[b], 2};
    }
    out[0] = {node.children[b], t[b]};
    out[1] = {node.children[a], t[a]};
    return {node.children[a], 2};
}

#if LIGHTPATH_BVH_AVX2

// How many entered lanes go before lane j, for every j at once: lane i does when its entry is
// larger, or equal and i < j. Comparing the entries with their rotation by s lanes (i = j + s mod
// 8) for s = 1..7 covers every pair without a branch, where an insertion sort takes a
// data-dependent branch per lane that an incoherent ray mispredicts about half the time. For a
// rotation by s, i < j holds exactly in lanes j >= 8 - s, so those lanes count a tie (>=), the
// others only a larger entry (>). Lanes not entered hold NaN, which compares false both ways.
template <int s>
[[gnu::always_inline]] inline __m256i addLanesBefore(__m256 key, __m256i rank) {
    const __m256i rotation = _mm256_setr_epi32(s & 7, (1 + s) & 7, (2 + s) & 7, (3 + s) & 7,
                                               (4 + s) & 7, (5 + s) & 7, (6 + s) & 7, (7 + s) & 7);
    const __m256 other = _mm256_permutevar8x32_ps(key, rotation);
    const __m256 larger = _mm256_cmp_ps(other, key, _CMP_GT_OQ);
    const __m256 notSmaller = _mm256_cmp_ps(other, key, _CMP_GE_OQ);
    constexpr int kTieLanes = (0xff << (8 - s)) & 0xff;
    const __m256 before = _mm256_blend_ps(larger, notSmaller, kTieLanes);
    return _mm256_sub_epi32(rank, _mm256_castps_si256(before));  // a true lane is -1
}

// Three or more lanes take no branch on their entries: the ranks come from compares
// (addLanesBefore) and the pairs move in registers. out[n..8) get garbage, so out[] needs all
// 8 slots. Inlined: as a call, the traversal loop's ray registers would be spilled around it.
[[gnu::always_inline]] inline Placed placeFarToNear(const BvhNode& node, int mask, const Float8& entry, bvh_detail::Pending out[kBvhWidth]) {
    const int rest = mask & (mask - 1);
    if ((rest & (rest - 1)) == 0) {
        alignas(32) float t[kBvhWidth];
        entry.store(t);
        return placeTwoFarToNear(node, simd::firstLane(mask), simd::firstLane(rest), t, out);
    }
    const __m256i lane = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    const __m256i laneBit = _mm256_sllv_epi32(_mm256_set1_epi32(1), lane);
    const __m256i entered = _mm256_cmpeq_epi32(_mm256_and_si256(_mm256_set1_epi32(mask), laneBit), laneBit);
    const __m256 key = _mm256_blendv_ps(_mm256_set1_ps(std::numeric_limits<float>::quiet_NaN()), entry.v,
                                        _mm256_castsi256_ps(entered));
    __m256i rank = _mm256_setzero_si256();
    rank = addLanesBefore<1>(key, rank);
    rank = addLanesBefore<2>(key, rank);
    rank = addLanesBefore<3>(key, rank);
    rank = addLanesBefore<4>(key, rank);
    rank = addLanesBefore<5>(key, rank);
    rank = addLanesBefore<6>(key, rank);
    rank = addLanesBefore<7>(key, rank);
    // A lane not entered counted nothing (NaN): it goes to slot 7, which is garbage when any
    // lane is not entered (n < 8).
    rank = _mm256_or_si256(rank, _mm256_andnot_si256(entered, _mm256_set1_epi32(kBvhWidth - 1)));
    // The inverse permutation, slot -> lane, as eight 4-bit fields of one integer: each lane
    // puts its index in field rank (lanes sharing slot 7 leave garbage there), an OR across
    // the lanes gathers them, and each slot shifts its field down (vpermps reads 3 bits).
    const __m256i field = _mm256_sllv_epi32(lane, _mm256_slli_epi32(rank, 2));
    __m128i gathered = _mm_or_si128(_mm256_castsi256_si128(field), _mm256_extracti128_si256(field, 1));
    gathered = _mm_or_si128(gathered, _mm_shuffle_epi32(gathered, _MM_SHUFFLE(1, 0, 3, 2)));
    gathered = _mm_or_si128(gathered, _mm_shuffle_epi32(gathered, _MM_SHUFFLE(2, 3, 0, 1)));
    const __m256i source = _mm256_srlv_epi32(_mm256_broadcastd_epi32(gathered), _mm256_slli_epi32(lane, 2));
    // The nearest child, read from the ranks rather than from the gathered fields: the next
    // node's loads wait for it, and this way is a few operations shorter.
    const int count = __builtin_popcount(static_cast<unsigned>(mask));
    const int last = count - 1;
    const int nearest = simd::firstLane(
        _mm256_movemask_ps(_mm256_castsi256_ps(_mm256_cmpeq_epi32(rank, _mm256_set1_epi32(last)))));
    const __m256 children = _mm256_load_ps(reinterpret_cast<const float*>(node.children));
    const __m256 sortedChildren = _mm256_permutevar8x32_ps(children, source);
    const __m256 sortedEntries = _mm256_permutevar8x32_ps(entry.v, source);
    // Interleaved as Pending's (child, entry): unpack pairs up within each 128-bit half (slots
    // 0 1 4 5 and 2 3 6 7), the half permutes put them back in order.
    const __m256 low = _mm256_unpacklo_ps(sortedChildren, sortedEntries);
    const __m256 high = _mm256_unpackhi_ps(sortedChildren, sortedEntries);
    _mm256_storeu_ps(reinterpret_cast<float*>(out), _mm256_permute2f128_ps(low, high, 0x20));
    _mm256_storeu_ps(reinterpret_cast<float*>(out + 4), _mm256_permute2f128_ps(low, high, 0x31));
    return {node.children[nearest], count};
}

#else

// The baseline keeps an insertion sort for three or more lanes: it runs only where AVX2 is
// missing, and gives the same order as the AVX2 path's ranks.
inline Placed placeFarToNear(const BvhNode& node, int mask, const Float8& entry, bvh_detail::Pending out[kBvhWidth]) {
    alignas(32) float t[kBvhWidth];
    entry.store(t);
    const int a = simd::firstLane(mask);
    mask &= mask - 1;
    const int b = simd::firstLane(mask);
    mask &= mask - 1;
    const Placed two = placeTwoFarToNear(node, a, b, t, out);
    if (mask == 0) return two;
    int n = 2;
    for (; mask != 0; mask &= mask - 1) {
        const int lane = simd::firstLane(mask);
        const bvh_detail::Pending p{node.children[lane], t[lane]};
        int i = n++;
        for (; i > 0 && out[i - 1].entry < p.entry; --i) out[i] = out[i - 1];
        out[i] = p;
    }
    return {out[n - 1].child, n};
}

#endif

// The same for entries in memory (tests): entry[lane] for each lane of `mask` (two or more).
inline Placed placeFarToNear(const BvhNode& node, int mask, const float entry[kBvhWidth], bvh_detail::Pending out[kBvhWidth]) {
    return placeFarToNear(node, mask, Float8::load(entry), out);
}

// Asks for a pushed node's four cache lines ahead of its visit, so that incoherent rays, whose
// nodes are rarely cached, wait for several at once rather than one after another.
inline void prefetchNode(const BvhNode* nodes, std::uint32_t child) {
    if (BvhChild::isLeaf(child)) return;
    const char* bytes = reinterpret_cast<const char*>(nodes + child);
    for (std::size_t line = 0; line < sizeof(BvhNode); line += 64) __builtin_prefetch(bytes + line);
}

// Pushes the entered lanes of `mask` (two or more) farthest first, asks for the pushed nodes'
// lines, and returns the nearest child, visited next. The AVX2 path places them on the stack
// in place (all eight slots written); the baseline sorts in a local array and copies, as before
// the AVX2 ranks: in place, its insertion sort took 4-5% more instructions per ray.
[[gnu::always_inline]] inline std::uint32_t pushFarToNear(const BvhNode* nodes, const BvhNode& node, int mask, const Float8& entry,
                                                          bvh_detail::Pending* stack, int& top) {
#if LIGHTPATH_BVH_AVX2
    const Placed placed = placeFarToNear(node, mask, entry, stack + top);
    const int pushed = placed.count - 1;
    for (int i = 0; i < pushed; ++i) prefetchNode(nodes, stack[top + i].child);
    top += pushed;
#else
    bvh_detail::Pending sorted[kBvhWidth];
    const Placed placed = placeFarToNear(node, mask, entry, sorted);
    for (int i = 0; i < placed.count - 1; ++i) {
        prefetchNode(nodes, sorted[i].child);
        stack[top++] = sorted[i];
    }
#endif
    return placed.nearest;
}

// All children are tested at their parent; those entered are pushed farthest first with their
// entry distances, the nearest is visited at once, and a popped child is skipped when a hit
// found since is nearer than its entry.
template <typename Test>
void closest(const Bvh& bvh, const Ray& ray, const float& tLimit, Test& test) {
    const RaySetup setup(ray);
    // pushFarToNear may write a node's eight slots above the top, whatever it pushes.
    bvh_detail::Pending stack[bvh_detail::kStackSize + kBvhWidth];
    int top = 0;
    std::uint32_t current = bvh.root();
    const BvhNode* nodes = bvh.nodes().data();
    for (;;) {
        if (!BvhChild::isLeaf(current)) {
            const BvhNode& node = nodes[current];
            Float8 entry;
            const int mask = setup.enter(node, Float8(tLimit * bvh_detail::kLimitSlack), entry);
            if (mask != 0) {
                if ((mask & (mask - 1)) == 0) {
                    current = node.children[simd::firstLane(mask)];
                    continue;
                }
                current = pushFarToNear(nodes, node, mask, entry, stack, top);
                continue;
            }
        } else {
            test(BvhChild::firstSlot(current), BvhChild::count(current));
        }
        for (;;) {
            if (top == 0) return;
            const bvh_detail::Pending next = stack[--top];
            if (next.entry <= tLimit * bvh_detail::kLimitSlack) {
                current = next.child;
                break;
            }
        }
    }
}

// Any hit ends the search, and most shadow rays reach their light: their every candidate box is
// visited whatever the order, so children go in lane order, without sorting.
template <typename Test>
bool any(const Bvh& bvh, const Ray& ray, Test& test) {
    const RaySetup setup(ray);
    const Float8 tMax(ray.tMax * bvh_detail::kLimitSlack);
    std::uint32_t stack[bvh_detail::kStackSize];
    int top = 0;
    std::uint32_t current = bvh.root();
    const BvhNode* nodes = bvh.nodes().data();
    for (;;) {
        if (!BvhChild::isLeaf(current)) {
            const BvhNode& node = nodes[current];
            Float8 entry;
            int mask = setup.enter(node, tMax, entry);
            if (mask != 0) {
                current = node.children[simd::firstLane(mask)];
                for (mask &= mask - 1; mask != 0; mask &= mask - 1) {
                    const std::uint32_t child = node.children[simd::firstLane(mask)];
                    prefetchNode(nodes, child);
                    stack[top++] = child;
                }
                continue;
            }
        } else if (test(BvhChild::firstSlot(current), BvhChild::count(current))) {
            return true;
        }
        if (top == 0) return false;
        current = stack[--top];
    }
}

}  // namespace
