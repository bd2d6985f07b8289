// Embree as a backend: its own triangle test, so it must agree with brute force on the closest
// primitive except at rare ties and edges, and answer every query the scene geometry asks.
#include <doctest/doctest.h>

#include "ray_sets.h"
#include "scene/scene_loader.h"

namespace lightpath {
namespace {

TEST_CASE("Embree = brute force on the closest primitive, but for rare ties") {
    if (!embreeAvailable()) {
        MESSAGE("built without Embree: nothing to compare");
        CHECK_THROWS_AS(SceneGeometry({}, {}, {}, {}, Accelerator::Embree), std::invalid_argument);
        return;
    }
    const Scene scene = loadScene(LIGHTPATH_SOURCE_DIR "/scenes/cornell-sphere.toml");
    for (const auto& soup : {test::randomSoup(21, 600, 40), test::Soup{{}, {}, scene.triangles}}) {
        const SceneGeometry brute(soup.spheres, soup.planes, soup.triangles, {}, Accelerator::BruteForce);
        const SceneGeometry embree(soup.spheres, soup.planes, soup.triangles, {}, Accelerator::Embree);
        Bounds box;
        for (const Triangle& t : soup.triangles) box.grow(t.a);
        const auto rays = test::randomRays(21, 6000, box.lo, box.hi);
        std::size_t hits = 0, differ = 0, occludedDiffer = 0;
        Pcg32 rng(5, 5);
        for (Ray ray : rays) {
            if (rng.nextUint() % 4 == 0) ray.ignoredPrimitive = rng.nextUint() % static_cast<std::uint32_t>(brute.primitiveCount());
            const auto a = brute.intersect(ray), b = embree.intersect(ray);
            hits += a.has_value();
            // A different primitive at the same distance is a tie (coincident faces, shared edges).
            const bool same = a.has_value() == b.has_value() &&
                              (!a || a->primitive == b->primitive || std::abs(a->t - b->t) <= 1e-4f * a->t);
            differ += !same;
            occludedDiffer += brute.occluded(ray) != embree.occluded(ray);
        }
        INFO(rays.size() << " rays, " << hits << " hits, " << differ << " differ, " << occludedDiffer
                         << " any-hit answers differ");
        CHECK(hits > rays.size() / 4);
        CHECK(differ <= rays.size() / 1000);
        CHECK(occludedDiffer <= rays.size() / 1000);
    }
}

}  // namespace
}  // namespace lightpath
