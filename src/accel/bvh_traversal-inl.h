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

// The lanes of `mask` (two or more) in out[], farthest entry first; returns how many. Two, the
// common case, take one comparison.
inline int sortFarToNear(const BvhNode& node, int mask, const Float8& entry, bvh_detail::Pending out[kBvhWidth]) {
    alignas(32) float t[kBvhWidth];
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
        const bvh_detail::Pending p{node.children[lane], t[lane]};
        int i = n++;
        for (; i > 0 && out[i - 1].entry < p.entry; --i) out[i] = out[i - 1];
        out[i] = p;
    }
    return n;
}

// Asks for a pushed node's four cache lines ahead of its visit, so that incoherent rays, whose
// nodes are rarely cached, wait for several at once rather than one after another.
inline void prefetchNode(const BvhNode* nodes, std::uint32_t child) {
    if (BvhChild::isLeaf(child)) return;
    const char* bytes = reinterpret_cast<const char*>(nodes + child);
    for (std::size_t line = 0; line < sizeof(BvhNode); line += 64) __builtin_prefetch(bytes + line);
}

// All children are tested at their parent; those entered are pushed farthest first with their
// entry distances, the nearest is visited at once, and a popped child is skipped when a hit
// found since is nearer than its entry.
template <typename Test>
void closest(const Bvh& bvh, const Ray& ray, const float& tLimit, Test& test) {
    const RaySetup setup(ray);
    bvh_detail::Pending stack[bvh_detail::kStackSize];
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
                bvh_detail::Pending sorted[kBvhWidth];
                const int n = sortFarToNear(node, mask, entry, sorted);
                for (int i = 0; i < n - 1; ++i) {
                    prefetchNode(nodes, sorted[i].child);
                    stack[top++] = sorted[i];
                }
                current = sorted[n - 1].child;
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
