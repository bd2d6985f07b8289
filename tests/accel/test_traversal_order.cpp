// The order in which closest-hit traversal pushes a node's entered children (placeFarToNear),
// on each SIMD path, against std::stable_sort: farthest entry first, equal entries in lane order.
// Hits do not depend on this order (a tie between primitives goes to the smaller id), so the
// brute-force tests cannot see a wrong one; this test checks the order itself.
#include <doctest/doctest.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include "accel/bvh_traversal.h"
#include "accel/simd_path.h"
#include "math/random.h"

namespace lightpath {
namespace {

std::uint32_t bitsOf(float x) { return std::bit_cast<std::uint32_t>(x); }

// Every mask of two or more lanes, with `entries` as the lanes' entry distances: counts the masks
// whose first popcount(mask) slots are not the stable sort's (child, entry bits), or whose
// returned count or child (visited next, the last of them) is not the stable sort's.
// `place` is a path's placeFarToNear.
template <typename Place>
int wrongOrders(Place place, const float (&entries)[kBvhWidth]) {
    BvhNode node{};
    for (int lane = 0; lane < kBvhWidth; ++lane) node.children[lane] = 1000u + static_cast<std::uint32_t>(lane);
    alignas(32) float entry[kBvhWidth];
    std::memcpy(entry, entries, sizeof(entry));
    int wrong = 0;
    for (int mask = 0; mask < 1 << kBvhWidth; ++mask) {
        if (std::popcount(static_cast<unsigned>(mask)) < 2) continue;
        std::vector<int> expected;
        for (int lane = 0; lane < kBvhWidth; ++lane)
            if (mask >> lane & 1) expected.push_back(lane);
        std::stable_sort(expected.begin(), expected.end(), [&](int a, int b) { return entry[a] > entry[b]; });
        bvh_detail::Pending out[kBvhWidth];
        std::memset(out, 0xff, sizeof(out));
        const auto placed = place(node, mask, entry, out);
        bool same = placed.nearest == node.children[expected.back()] &&
                    placed.count == static_cast<int>(expected.size());
        for (std::size_t i = 0; i < expected.size(); ++i)
            same = same && out[i].child == node.children[expected[i]] && bitsOf(out[i].entry) == bitsOf(entry[expected[i]]);
        wrong += !same;
    }
    return wrong;
}

template <typename Place>
void checkOrders(Place place) {
    const float inf = std::numeric_limits<float>::infinity();
    const float patterns[][kBvhWidth] = {
        {0.5f, 3.0f, 1.0f, 7.0f, 2.0f, 6.0f, 4.0f, 5.0f},          // distinct
        {2.0f, 2.0f, 2.0f, 2.0f, 2.0f, 2.0f, 2.0f, 2.0f},          // all tied
        {1.0f, 2.0f, 1.0f, 2.0f, 3.0f, 1.0f, 3.0f, 2.0f},          // tied in groups
        {0.0f, -0.0f, 0.0f, 1.0f, -0.0f, inf, inf, 1.0f},          // signed zeros tie; infinities
        {-1.0f, 0.25f, -3.0f, 0.25f, -1.0f, 8.0f, -0.5f, 1e-30f},  // negative (a ray's tMin < 0)
    };
    for (const auto& entries : patterns) {
        INFO("entries " << entries[0] << " " << entries[1] << " " << entries[2] << " " << entries[3] << " "
                        << entries[4] << " " << entries[5] << " " << entries[6] << " " << entries[7]);
        CHECK(wrongOrders(place, entries) == 0);
    }
    // Random entries from a few values, so that most masks hold ties, and from many.
    Pcg32 rng(27, 8);
    for (int round = 0; round < 200; ++round) {
        float entries[kBvhWidth];
        const std::uint32_t values = round % 2 == 0 ? 3u : 1u << 20;
        for (float& e : entries) e = static_cast<float>(rng.nextUint() % values) * 0.125f;
        INFO("round " << round);
        CHECK(wrongOrders(place, entries) == 0);
    }
}

TEST_CASE("closest-hit push order = stable sort by decreasing entry, baseline path") {
    checkOrders([](const BvhNode& node, int mask, const float* entry, bvh_detail::Pending* out) {
        return bvh_baseline::placeFarToNear(node, mask, entry, out);
    });
}

#ifdef LIGHTPATH_AVX2_PATH
TEST_CASE("closest-hit push order = stable sort by decreasing entry, AVX2 path") {
    if (!simd::supported(simd::Path::Avx2)) {
        MESSAGE("AVX2 not supported here: not tested");
        return;
    }
    checkOrders([](const BvhNode& node, int mask, const float* entry, bvh_detail::Pending* out) {
        return bvh_avx2::placeFarToNear(node, mask, entry, out);
    });
}
#endif

}  // namespace
}  // namespace lightpath
