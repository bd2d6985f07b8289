// The BVH against the lecture's loop over every primitive: the same closest hit (t, primitive
// and the hit record built from them) and the same any-hit answer, ray by ray.
#include <doctest/doctest.h>

#include <algorithm>
#include <string>

#include "accel/bvh.h"
#include "ray_sets.h"
#include "scene/scene_loader.h"

namespace lightpath {
namespace {

using test::Soup;

// Checks every ray, and again with a random primitive ignored (the lecture's own-primitive rule).
void expectSameAnswers(const SceneGeometry& brute, const SceneGeometry& bvh, const std::vector<Ray>& rays,
                       const std::string& what) {
    Pcg32 rng(99, 4);
    std::size_t closestDiffer = 0, anyDiffer = 0, hits = 0, occluded = 0;
    for (Ray ray : rays) {
        for (int pass = 0; pass < 2; ++pass) {
            if (pass == 1) ray.ignoredPrimitive = rng.nextUint() % static_cast<std::uint32_t>(brute.primitiveCount());
            const auto a = brute.intersect(ray);
            const auto b = bvh.intersect(ray);
            const bool same = a.has_value() == b.has_value() &&
                              (!a || (a->t == b->t && a->primitive == b->primitive && a->point == b->point &&
                                      a->shadingNormal == b->shadingNormal && a->object == b->object));
            closestDiffer += !same;
            hits += a.has_value();
            const bool blocked = brute.occluded(ray);
            anyDiffer += blocked != bvh.occluded(ray);
            occluded += blocked;
        }
    }
    INFO(what << ": " << rays.size() << " rays, " << hits << " closest hits and " << occluded << " occluded");
    CHECK(closestDiffer == 0);
    CHECK(anyDiffer == 0);
    // A ray set that hits nothing would test nothing.
    CHECK(hits > rays.size() / 10);
}

SceneGeometry geometryOf(const Soup& soup, Accelerator accelerator) {
    return SceneGeometry(soup.spheres, soup.planes, soup.triangles, {}, accelerator);
}

TEST_CASE("BVH = brute force on random triangle and sphere soups") {
    for (std::uint64_t seed : {1u, 2u, 3u}) {
        const Soup soup = test::randomSoup(seed, 400, 60);
        const SceneGeometry brute = geometryOf(soup, Accelerator::BruteForce);
        const SceneGeometry bvh = geometryOf(soup, Accelerator::Bvh);
        expectSameAnswers(brute, bvh, test::randomRays(seed, 8000, Vec3(-12.0f), Vec3(12.0f)),
                          "random rays, soup " + std::to_string(seed));
        expectSameAnswers(brute, bvh, test::adversarialRays(soup, seed, 6000),
                          "adversarial rays, soup " + std::to_string(seed));
    }
}

TEST_CASE("BVH = brute force with the naive intersection tests too") {
    const Soup soup = test::randomSoup(7, 300, 40);
    const SceneGeometry brute(soup.spheres, soup.planes, soup.triangles, NumericsOptions::naive(), Accelerator::BruteForce);
    const SceneGeometry bvh(soup.spheres, soup.planes, soup.triangles, NumericsOptions::naive(), Accelerator::Bvh);
    expectSameAnswers(brute, bvh, test::randomRays(7, 8000, Vec3(-12.0f), Vec3(12.0f)), "naive tests");
}

TEST_CASE("BVH = brute force on the bunny") {
    const Scene scene = loadScene(LIGHTPATH_SOURCE_DIR "/scenes/bunny.toml");
    const Soup bunny{{}, {}, scene.triangles};
    const SceneGeometry brute = geometryOf(bunny, Accelerator::BruteForce);
    const SceneGeometry bvh = geometryOf(bunny, Accelerator::Bvh);
    Bounds box;
    for (const Triangle& t : bunny.triangles) box.grow(t.a);
    // Brute force costs 69,451 triangle tests a ray: 150 rays of each kind, each also with a primitive ignored.
    expectSameAnswers(brute, bvh, test::randomRays(11, 150, box.lo, box.hi), "bunny, random rays");
    expectSameAnswers(brute, bvh, test::adversarialRays(bunny, 11, 150), "bunny, adversarial rays");
}

TEST_CASE("equal t: the smaller primitive id wins, as in the loop") {
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
}

TEST_CASE("BVH layout: 32-byte nodes, every primitive in exactly one leaf, boxes contain their children") {
    const Soup soup = test::randomSoup(5, 2000, 100);
    std::vector<BvhPrimitive> primitives;
    for (std::uint32_t i = 0; i < soup.triangles.size(); ++i) {
        Bounds b;
        b.grow(soup.triangles[i].a);
        b.grow(soup.triangles[i].b);
        b.grow(soup.triangles[i].c);
        primitives.push_back({b, i});
    }
    const Bvh bvh(primitives);
    CHECK(bvh.stats().nodeBytes == 32 * bvh.stats().nodes);
    std::vector<int> seen(primitives.size(), 0);
    const auto nodes = bvh.nodes();
    const auto contains = [](const BvhNode& outer, const Vec3& lo, const Vec3& hi) {
        return glm::all(glm::lessThanEqual(outer.lo, lo)) && glm::all(glm::greaterThanEqual(outer.hi, hi));
    };
    std::size_t bad = 0;
    for (std::size_t n = 0; n < nodes.size(); ++n) {
        const BvhNode& node = nodes[n];
        if (node.count > 0) {
            CHECK(node.count <= 4);
            for (std::uint32_t i = node.offset; i < node.offset + node.count; ++i) {
                const std::uint32_t id = bvh.primitiveIds()[i];
                ++seen[id];
                bad += !contains(node, primitives[id].bounds.lo, primitives[id].bounds.hi);
            }
        } else {
            bad += !contains(node, nodes[n + 1].lo, nodes[n + 1].hi);
            bad += !contains(node, nodes[node.offset].lo, nodes[node.offset].hi);
        }
    }
    CHECK(bad == 0);
    CHECK(std::count(seen.begin(), seen.end(), 1) == static_cast<std::ptrdiff_t>(seen.size()));
}

TEST_CASE("coincident primitives (no centroid spread) still build a shallow, complete tree") {
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
}

TEST_CASE("an empty scene and a planes-only scene") {
    const SceneGeometry empty({}, {}, {}, {}, Accelerator::Bvh);
    Ray ray;
    CHECK_FALSE(empty.intersect(ray));
    CHECK_FALSE(empty.occluded(ray));
    const SceneGeometry planes({}, {Plane{Vec3(0, 0, 3), Vec3(0, 0, -1), 0}}, {}, {}, Accelerator::Bvh);
    const auto hit = planes.intersect(ray);
    REQUIRE(hit);
    CHECK(hit->t == doctest::Approx(3.0f));
    CHECK(planes.occluded(ray));
}

}  // namespace
}  // namespace lightpath
