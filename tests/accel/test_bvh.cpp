// The BVH against the lecture's loop over every primitive: the same closest hit (t, primitive
// and the hit record built from them) and the same any-hit answer, ray by ray, on every SIMD
// path this processor can run (AVX2 and the SSE2 baseline on most x86-64).
#include <doctest/doctest.h>

#include <algorithm>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "accel/bvh.h"
#include "accel/simd_path.h"
#include "ray_sets.h"
#include "scene/scene_loader.h"

namespace lightpath {
namespace {

using test::Soup;

// Runs `check` once per SIMD path this processor supports, each BVH built (so traversed) on it.
template <typename Check>
void onEverySimdPath(Check check) {
    const simd::Path before = simd::activePath();
    for (const simd::Path path : {simd::Path::Baseline, simd::Path::Avx2}) {
        if (!simd::supported(path)) {
            MESSAGE("SIMD path " << simd::pathName(path) << " not supported here: not tested");
            continue;
        }
        simd::setPath(path);
        INFO("SIMD path " << simd::pathName(path));
        check();
    }
    simd::setPath(before);
}

// Brute force's answers to a ray set: every ray, and again with a random primitive ignored (the
// lecture's own-primitive rule). Its loop tests primitives one by one and builds no BVH, so the
// SIMD path does not change them: computed once, they judge the BVH on every path. A ray is
// occluded when it hits anything within its range, that is when the closest hit exists: the
// any-hit answer is read from it rather than from a second loop over every primitive.
struct BruteAnswers {
    std::string what;
    std::vector<Ray> rays;
    std::vector<std::optional<SurfaceHit>> closest;
    std::size_t hits = 0;
};

BruteAnswers bruteAnswers(const SceneGeometry& brute, const std::vector<Ray>& rays, const std::string& what) {
    BruteAnswers answers{what, {}, {}};
    Pcg32 rng(99, 4);
    for (Ray ray : rays) {
        for (int pass = 0; pass < 2; ++pass) {
            if (pass == 1) ray.ignoredPrimitive = rng.nextUint() % static_cast<std::uint32_t>(brute.primitiveCount());
            answers.rays.push_back(ray);
            answers.closest.push_back(brute.intersect(ray));
            answers.hits += answers.closest.back().has_value();
        }
    }
    return answers;
}

void expectSameAnswers(const BruteAnswers& brute, const SceneGeometry& bvh) {
    std::size_t closestDiffer = 0, normalDiffer = 0, anyDiffer = 0;
    for (std::size_t i = 0; i < brute.rays.size(); ++i) {
        const Ray& ray = brute.rays[i];
        const auto& a = brute.closest[i];
        const auto b = bvh.intersect(ray);
        // The BVH hands its triangle test's barycentrics to the hit record (point, smooth
        // normal), brute force tests the triangle again: the same bits either way.
        const bool same = a.has_value() == b.has_value() &&
                          (!a || (a->t == b->t && a->primitive == b->primitive && a->point == b->point &&
                                  a->normal == b->normal && a->shadingNormal == b->shadingNormal &&
                                  a->object == b->object));
        closestDiffer += !same;
        // A triangle's normal is read from a table made at construction: triangleNormal's bits.
        if (b && b->shape == nullptr) normalDiffer += b->normal != triangleNormal(bvh.triangleOf(b->primitive));
        anyDiffer += a.has_value() != bvh.occluded(ray);
    }
    INFO(brute.what << ": " << brute.rays.size() / 2 << " rays, " << brute.hits << " hits (with and without a primitive ignored)");
    CHECK(closestDiffer == 0);
    CHECK(normalDiffer == 0);
    CHECK(anyDiffer == 0);
    // A ray set that hits nothing would test nothing.
    CHECK(brute.hits > brute.rays.size() / 2 / 10);
}

// The same, and brute force's own any-hit loop against its closest hit (the small scenes' rays).
void expectSameAnswers(const SceneGeometry& brute, const SceneGeometry& bvh, const std::vector<Ray>& rays,
                       const std::string& what) {
    const BruteAnswers answers = bruteAnswers(brute, rays, what);
    std::size_t bruteDiffer = 0;
    for (std::size_t i = 0; i < answers.rays.size(); ++i)
        bruteDiffer += brute.occluded(answers.rays[i]) != answers.closest[i].has_value();
    INFO(what);
    CHECK(bruteDiffer == 0);
    expectSameAnswers(answers, bvh);
}

SceneGeometry geometryOf(const Soup& soup, Accelerator accelerator) {
    return SceneGeometry(soup.spheres, soup.planes, soup.triangles, {}, accelerator);
}

TEST_CASE("BVH = brute force on random triangle and sphere soups") {
    for (std::uint64_t seed : {1u, 2u, 3u}) {
        const Soup soup = test::randomSoup(seed, 400, 60);
        const SceneGeometry brute = geometryOf(soup, Accelerator::BruteForce);
        const BruteAnswers random = bruteAnswers(brute, test::randomRays(seed, 8000, Vec3(-12.0f), Vec3(12.0f)),
                                                 "random rays, soup " + std::to_string(seed));
        const BruteAnswers adversarial = bruteAnswers(brute, test::adversarialRays(soup, seed, 6000),
                                                      "adversarial rays, soup " + std::to_string(seed));
        onEverySimdPath([&] {
            const SceneGeometry bvh = geometryOf(soup, Accelerator::Bvh);
            expectSameAnswers(random, bvh);
            expectSameAnswers(adversarial, bvh);
        });
    }
}

TEST_CASE("BVH = brute force with the naive intersection tests too") {
    onEverySimdPath([&] {
        const Soup soup = test::randomSoup(7, 300, 40);
        const SceneGeometry brute(soup.spheres, soup.planes, soup.triangles, NumericsOptions::naive(), Accelerator::BruteForce);
        const SceneGeometry bvh(soup.spheres, soup.planes, soup.triangles, NumericsOptions::naive(), Accelerator::Bvh);
        expectSameAnswers(brute, bvh, test::randomRays(7, 8000, Vec3(-12.0f), Vec3(12.0f)), "naive tests");
    });
}

TEST_CASE("BVH = brute force on the bunny") {
    const Scene scene = loadScene(LIGHTPATH_SOURCE_DIR "/scenes/bunny.toml");
    const Soup bunny{{}, {}, scene.triangles};
    const SceneGeometry brute = geometryOf(bunny, Accelerator::BruteForce);
    Bounds box;
    for (const Triangle& t : bunny.triangles) box.grow(t.a);
    // Brute force costs 69,451 triangle tests a ray: 150 rays of each kind, each also with a primitive ignored.
    const BruteAnswers random = bruteAnswers(brute, test::randomRays(11, 150, box.lo, box.hi), "bunny, random rays");
    const BruteAnswers adversarial = bruteAnswers(brute, test::adversarialRays(bunny, 11, 150), "bunny, adversarial rays");
    onEverySimdPath([&] {
        const SceneGeometry bvh = geometryOf(bunny, Accelerator::Bvh);
        expectSameAnswers(random, bvh);
        expectSameAnswers(adversarial, bvh);
    });
}

TEST_CASE("BVH = brute force on scenes of 1 to 12 primitives (a root that is a leaf, part-filled nodes)") {
    onEverySimdPath([&] {
        // The soup's first triangles are degenerate (flat in two axes) and its second shares their
        // edge: start after them, so that there is something to hit.
        const Soup full = test::randomSoup(21, 14, 2);
        for (std::size_t n = 1; n <= 12; ++n) {
            // The first n of the triangles and then of the spheres.
            Soup soup;
            const std::size_t triangles = std::min<std::size_t>(n, 10);
            soup.triangles.assign(full.triangles.begin() + 2, full.triangles.begin() + 2 + static_cast<std::ptrdiff_t>(triangles));
            soup.spheres.assign(full.spheres.begin(), full.spheres.begin() + static_cast<std::ptrdiff_t>(n - triangles));
            const SceneGeometry brute = geometryOf(soup, Accelerator::BruteForce);
            const SceneGeometry bvh = geometryOf(soup, Accelerator::Bvh);
            // Aimed at the primitives, so that most rays hit something even in a tiny scene.
            Pcg32 rng(n, 3);
            std::vector<Ray> rays;
            for (int i = 0; i < 400; ++i) {
                const Triangle& t = soup.triangles[rng.nextUint() % soup.triangles.size()];
                Ray ray;
                ray.origin = test::uniformIn(rng, Vec3(-12.0f), Vec3(12.0f));
                const Vec3 target = i % 4 == 0 && !soup.spheres.empty() ? soup.spheres[0].center : (t.a + t.b + t.c) / 3.0f;
                ray.direction = glm::normalize(target - ray.origin);
                rays.push_back(ray);
            }
            expectSameAnswers(brute, bvh, rays, std::to_string(n) + " primitives");
        }
    });
}

TEST_CASE("equal t: the smaller primitive id wins, as in the loop") {
    onEverySimdPath([&] {
        // Two identical triangles and two identical spheres: every hit is a tie.
        const Triangle t{{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}, 0};
        const Sphere s{{0, 0, 5}, 1.0f, 0};
        const SceneGeometry brute({s, s}, {}, {t, t, t}, {}, Accelerator::BruteForce);
        const SceneGeometry bvh({s, s}, {}, {t, t, t}, {}, Accelerator::Bvh);
        for (const Vec3 origin : {Vec3(0.1f, 0.0f, -3.0f), Vec3(0.0f, 0.2f, 9.0f)}) {
            Ray ray;
            ray.origin = origin;
            ray.direction = glm::normalize(Vec3(0.0f, 0.0f, origin.z < 0 ? 1.0f : -1.0f));
            const auto a = brute.intersect(ray), b = bvh.intersect(ray);
            REQUIRE(a);
            REQUIRE(b);
            CHECK(a->primitive == b->primitive);
            CHECK(a->t == b->t);
        }
    });
}

std::vector<BvhPrimitive> soupPrimitives(const Soup& soup) {
    std::vector<BvhPrimitive> primitives;
    for (std::uint32_t i = 0; i < soup.triangles.size(); ++i) {
        Bounds b;
        b.grow(soup.triangles[i].a);
        b.grow(soup.triangles[i].b);
        b.grow(soup.triangles[i].c);
        primitives.push_back({b, i});
    }
    return primitives;
}

TEST_CASE("BVH layout: 8-wide nodes, every primitive in exactly one leaf, boxes contain their children") {
    const Soup soup = test::randomSoup(5, 2000, 100);
    const std::vector<BvhPrimitive> primitives = soupPrimitives(soup);
    const Bvh bvh(primitives);
    CHECK(bvh.stats().nodeBytes == 256 * bvh.stats().nodes);
    CHECK(bvh.stats().primitives == primitives.size());
    REQUIRE_FALSE(BvhChild::isLeaf(bvh.root()));
    std::vector<int> seen(primitives.size(), 0), reached(bvh.nodes().size(), 0);
    const auto nodes = bvh.nodes();
    const auto contains = [](const Bounds& outer, const Bounds& inner) {
        return glm::all(glm::lessThanEqual(outer.lo, inner.lo)) && glm::all(glm::greaterThanEqual(outer.hi, inner.hi));
    };
    std::size_t bad = 0, lanes = 0, usedLanes = 0;
    // Walk from the root: each lane's box must contain its subtree's boxes, or its leaf's primitives.
    std::vector<std::uint32_t> pending{bvh.root()};
    while (!pending.empty()) {
        const std::uint32_t index = pending.back();
        pending.pop_back();
        ++reached[index];
        const BvhNode& node = nodes[index];
        for (int lane = 0; lane < kBvhWidth; ++lane) {
            ++lanes;
            const std::uint32_t child = node.children[lane];
            const Bounds box = node.childBounds(lane);
            if (child == BvhChild::kEmpty) {
                bad += !box.empty();
                continue;
            }
            ++usedLanes;
            if (BvhChild::isLeaf(child)) {
                CHECK(BvhChild::count(child) <= 4);
                CHECK(BvhChild::firstSlot(child) % 4 == 0);
                for (std::uint32_t i = 0; i < 4; ++i) {
                    const std::uint32_t id = bvh.slotIds()[BvhChild::firstSlot(child) + i];
                    if (i >= BvhChild::count(child)) {
                        bad += id != kBvhEmptySlot;
                        continue;
                    }
                    ++seen[id];
                    bad += !contains(box, primitives[id].bounds);
                }
            } else {
                const BvhNode& inner = nodes[child];
                for (int l = 0; l < kBvhWidth; ++l)
                    if (inner.children[l] != BvhChild::kEmpty) bad += !contains(box, inner.childBounds(l));
                pending.push_back(child);
            }
        }
    }
    CHECK(bad == 0);
    CHECK(std::count(seen.begin(), seen.end(), 1) == static_cast<std::ptrdiff_t>(seen.size()));
    CHECK(std::count(reached.begin(), reached.end(), 1) == static_cast<std::ptrdiff_t>(reached.size()));
    // The collapse fills nodes: more than four of eight lanes on average, twice a binary tree's two
    // (leaves end the opening, so nodes just above them are part-filled, as in Embree's BVH8).
    INFO(usedLanes << " of " << lanes << " lanes used");
    CHECK(usedLanes * 2 > lanes);
}

TEST_CASE("a block's worth of primitives is two leaves only where they are much smaller: a floor and a wall") {
    // Boxes of a unit quad's two triangles (each spans the quad). Half areas by hand: a unit
    // quad's box 1, the unit cube 3, a 2 x 1 strip 2. The builder splits a block when its two
    // sides sum to less than 0.9 of the whole (the step to a second leaf costs the rest), and keeps
    // the two leaves only as lanes of a wide node that is there anyway.
    const auto quad = [](Vec3 lo, Vec3 hi, std::uint32_t id) {
        return std::vector<BvhPrimitive>{{{lo, hi}, id}, {{lo, hi}, id + 1}};
    };
    const auto join = [](std::vector<BvhPrimitive> a, const std::vector<BvhPrimitive>& b) {
        a.insert(a.end(), b.begin(), b.end());
        return a;
    };
    const auto floor = quad({0, 0, 0}, {1, 0, 1}, 0);
    const auto wall = quad({0, 0, 0}, {0, 1, 1}, 2);
    const auto nextToFloor = quad({1, 0, 0}, {2, 0, 1}, 2);
    const auto farAway = quad({10, 0, 0}, {11, 0, 1}, 4);
    // The root's leaves, each as its sorted ids.
    const auto leavesOf = [](const Bvh& bvh) {
        std::vector<std::uint32_t> children{bvh.root()};
        if (!BvhChild::isLeaf(bvh.root())) {
            children.clear();
            for (const std::uint32_t child : bvh.nodes()[bvh.root()].children)
                if (child != BvhChild::kEmpty) children.push_back(child);
        }
        std::vector<std::vector<std::uint32_t>> leaves;
        for (const std::uint32_t child : children) {
            REQUIRE(BvhChild::isLeaf(child));
            std::vector<std::uint32_t> ids;
            for (std::uint32_t i = 0; i < BvhChild::count(child); ++i) ids.push_back(bvh.slotIds()[BvhChild::firstSlot(child) + i]);
            std::sort(ids.begin(), ids.end());
            leaves.push_back(ids);
        }
        std::sort(leaves.begin(), leaves.end());
        return leaves;
    };
    using Leaves = std::vector<std::vector<std::uint32_t>>;
    SUBCASE("a floor and a wall beside other geometry: 1 + 1 < 0.9 x 3, two flat leaves, not one cube") {
        CHECK(leavesOf(Bvh(join(join(floor, wall), farAway))) == Leaves{{0, 1}, {2, 3}, {4, 5}});
    }
    SUBCASE("a flat 2 x 1 strip: 1 + 1 is not below 0.9 x 2, one leaf") {
        CHECK(leavesOf(Bvh(join(join(floor, nextToFloor), farAway))) == Leaves{{0, 1, 2, 3}, {4, 5}});
    }
    SUBCASE("the floor and the wall alone: one leaf, as a node of two leaves would cost a node test more") {
        const Bvh bvh(join(floor, wall));
        CHECK(BvhChild::isLeaf(bvh.root()));
        CHECK(leavesOf(bvh) == Leaves{{0, 1, 2, 3}});
        CHECK(bvh.stats().nodes == 0);
    }
}

TEST_CASE("a BVH traverses on the SIMD path active when it was built") {
    const std::vector<BvhPrimitive> primitives = soupPrimitives(test::randomSoup(6, 100, 0));
    onEverySimdPath([&] { CHECK(Bvh(primitives).simdPath() == simd::activePath()); });
    CHECK(simd::supported(simd::Path::Baseline));
    if (!simd::supported(simd::Path::Avx2)) CHECK_THROWS_AS(simd::setPath(simd::Path::Avx2), std::invalid_argument);
}

TEST_CASE("the parallel build makes the same tree on 1, 2 and 5 threads") {
    // Large enough that subtrees go to the shared queue (the builder's grain is 4096 primitives).
    const Soup soup = test::randomSoup(8, 60000, 0);
    const std::vector<BvhPrimitive> primitives = soupPrimitives(soup);
    const Bvh one(primitives, 1);
    const auto sameTree = [&](const Bvh& other) {
        const auto a = one.nodes(), b = other.nodes();
        return a.size() == b.size() && one.root() == other.root() &&
               std::equal(one.slotIds().begin(), one.slotIds().end(), other.slotIds().begin(), other.slotIds().end()) &&
               std::equal(a.begin(), a.end(), b.begin(), [](const BvhNode& x, const BvhNode& y) {
                   return std::memcmp(&x, &y, sizeof(BvhNode)) == 0;
               });
    };
    CHECK(one.nodes().size() > 60000 / 16);
    CHECK(sameTree(Bvh(primitives, 2)));
    CHECK(sameTree(Bvh(primitives, 5)));
}

TEST_CASE("coincident primitives (no centroid spread) still build a shallow, complete tree") {
    onEverySimdPath([&] {
        const Triangle t{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0};
        const std::vector<Triangle> same(5000, t);
        const SceneGeometry brute({}, {}, same, {}, Accelerator::BruteForce);
        const SceneGeometry bvh({}, {}, same, {}, Accelerator::Bvh);
        Ray ray;
        ray.origin = Vec3(0.2f, 0.2f, -1.0f);
        const auto a = brute.intersect(ray), b = bvh.intersect(ray);
        REQUIRE(b);
        CHECK(a->primitive == b->primitive);
        CHECK(b->primitive == 0);
    });
}

TEST_CASE("planes tested two at once = the scalar plane test: ties, an odd count, parallel rays, short segments") {
    // Five planes (two packs and a padding lane): p0 and p1 coincide (their tie goes to p0, the
    // smaller id), p2 is a floor, p3 leans, p4 faces p0 from behind the origin. A sphere and a
    // triangle share the scene so that planes compete with the BVH's hits.
    const std::vector<Plane> planes{{Vec3(0, 0, 5), Vec3(0, 0, -1), 0},
                                    {Vec3(0, 0, 5), Vec3(0, 0, -1), 1},
                                    {Vec3(0, -1, 0), Vec3(0, 1, 0), 2},
                                    {Vec3(3, 0, 0), glm::normalize(Vec3(1.0f, 0.2f, 0.1f)), 3},
                                    {Vec3(0, 0, -7), Vec3(0, 0, 1), 4}};
    const std::vector<Sphere> spheres{{Vec3(0.5f, 0.0f, 2.0f), 0.75f, 5}};
    const std::vector<Triangle> triangles{{Vec3(-2, -0.5f, 3), Vec3(2, -0.5f, 3), Vec3(0, 2, 3), 6}};
    Pcg32 rng(17, 3);
    std::vector<Ray> rays;
    for (int i = 0; i < 4000; ++i) {
        Ray ray;
        ray.origin = Vec3(rng.nextFloat(), rng.nextFloat(), rng.nextFloat()) * 4.0f - 2.0f;
        // Every fourth ray runs parallel to p0 and p1 (direction z = 0), and every third is a
        // segment ending at a random distance, as a shadow ray does.
        const float z = i % 4 == 0 ? 0.0f : rng.nextFloat() * 2.0f - 1.0f;
        ray.direction = glm::normalize(Vec3(rng.nextFloat() * 2.0f - 1.0f, rng.nextFloat() * 2.0f - 1.0f, z));
        if (i % 3 == 0) ray.tMax = rng.nextFloat() * 8.0f;
        rays.push_back(ray);
    }
    onEverySimdPath([&] {
        const SceneGeometry brute(spheres, planes, triangles, {}, Accelerator::BruteForce);
        const SceneGeometry bvh(spheres, planes, triangles, {}, Accelerator::Bvh);
        expectSameAnswers(brute, bvh, rays, "five planes, a sphere and a triangle");
        // The coincident pair: the smaller id wins, and with it ignored the other is hit.
        Ray ray;
        ray.origin = Vec3(-1.5f, 1.5f, 0.0f);
        const auto first = bvh.intersect(ray);
        REQUIRE(first);
        CHECK(first->primitive == bvh.shapeId(1));  // p0: after the sphere's id 0
        ray.ignoredPrimitive = first->primitive;
        const auto second = bvh.intersect(ray);
        REQUIRE(second);
        CHECK(second->primitive == bvh.shapeId(2));
        CHECK(second->t == first->t);
    });
}

TEST_CASE("an empty scene and a planes-only scene") {
    onEverySimdPath([&] {
        const SceneGeometry empty({}, {}, {}, {}, Accelerator::Bvh);
        Ray ray;
        CHECK_FALSE(empty.intersect(ray));
        CHECK_FALSE(empty.occluded(ray));
        const SceneGeometry planes({}, {Plane{Vec3(0, 0, 3), Vec3(0, 0, -1), 0}}, {}, {}, Accelerator::Bvh);
        const auto hit = planes.intersect(ray);
        REQUIRE(hit);
        CHECK(hit->t == doctest::Approx(3.0f));
        CHECK(planes.occluded(ray));
    });
}

}  // namespace
}  // namespace lightpath
