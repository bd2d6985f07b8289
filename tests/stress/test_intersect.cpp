// The intersection tests against long-double references, on the cases the lecture's "accuracy"
// slide names: far and tangent spheres, rays through shared edges and vertices, tiny triangles.
#include <doctest/doctest.h>

#include <random>

#include "geometry/intersect.h"
#include "reference.h"
#include "../support/uniform_real.h"

namespace lightpath {
namespace {

Ray rayTowards(Vec3 origin, Vec3 target) {
    Ray ray;
    ray.origin = origin;
    ray.direction = glm::normalize(target - origin);
    return ray;
}

TEST_CASE("stable sphere test: hit or miss as the exact answer, both roots within an ulp, to 1e6 radii") {
    std::mt19937_64 rng(0x5EED);
    test::UniformReal<float> offset(-1.1f, 1.1f);
    const Sphere sphere{{0.0f, 0.0f, 0.0f}, 1.0f, 0};
    for (const float distance : {10.0f, 1e3f, 1e6f}) {
        CAPTURE(distance);
        int wrong = 0;
        double worst = 0;
        for (int i = 0; i < 20000; ++i) {
            const Ray ray = rayTowards({0.0f, 0.0f, distance}, {offset(rng), offset(rng), 0.0f});
            const test::ExactRoots exact = test::exactSphereRoots(ray, sphere);
            float t0 = 0, t1 = 0;
            const bool hit = sphereRoots(ray, sphere, t0, t1);
            wrong += hit != exact.hit;
            if (hit && exact.hit) worst = std::max({worst, test::ulpsBetween(t0, exact.t0), test::ulpsBetween(t1, exact.t1)});
        }
        CHECK(wrong == 0);
        CHECK(worst <= 1.0);
    }
}

TEST_CASE("naive b^2 - 4ac gets silhouettes wrong at 1e3 radii, which the lecture figure shows") {
    std::mt19937_64 rng(0x5EED);
    test::UniformReal<float> offset(-1.1f, 1.1f);
    const Sphere sphere{{0.0f, 0.0f, 0.0f}, 1.0f, 0};
    int wrong = 0;
    for (int i = 0; i < 20000; ++i) {
        const Ray ray = rayTowards({0.0f, 0.0f, 1e3f}, {offset(rng), offset(rng), 0.0f});
        wrong += (intersectSphereNaive(ray, sphere, 0.0f) != kNoHit) != test::exactSphereRoots(ray, sphere).hit;
    }
    CHECK(wrong > 100);
}

TEST_CASE("a ray from inside a sphere finds the far side, and a tangent ray agrees with the exact answer") {
    const Sphere sphere{{3.0f, -2.0f, 7.0f}, 0.5f, 0};
    Ray inside;
    inside.origin = sphere.center;
    inside.direction = glm::normalize(Vec3{1.0f, 2.0f, 2.0f});
    CHECK(intersectSphere(inside, sphere, 0.0f) == doctest::Approx(0.5f));
    Ray tangent = rayTowards({3.0f, -1.5f, 0.0f}, {3.0f, -1.5f, 7.0f});  // grazes the top
    const test::ExactRoots exact = test::exactSphereRoots(tangent, sphere);
    float t0 = 0, t1 = 0;
    CHECK(sphereRoots(tangent, sphere, t0, t1) == exact.hit);
}

// Two triangles sharing the edge a-c; a fan of six around the vertex o.
TEST_CASE("watertight: rays through a shared edge and a shared vertex hit, where Moller-Trumbore can slip") {
    const Vec3 a{0.1f, 0.3f, 0.0f}, b{1.3f, -0.7f, 0.0f}, c{0.9f, 1.1f, 0.0f}, d{-0.4f, 1.7f, 0.0f};
    const Triangle left{a, b, c, 0}, right{a, c, d, 0};
    std::mt19937_64 rng(7);
    test::UniformReal<float> u(0.0f, 1.0f);
    int watertightMisses = 0, mollerMisses = 0;
    for (int i = 0; i < 20000; ++i) {
        const Vec3 onEdge = a + u(rng) * (c - a);
        const Ray ray = rayTowards(onEdge + Vec3{u(rng) - 0.5f, u(rng) - 0.5f, 1.0f + u(rng)}, onEdge);
        watertightMisses += intersectTriangle(ray, left, 0.0f) == kNoHit && intersectTriangle(ray, right, 0.0f) == kNoHit;
        mollerMisses += intersectTriangleMollerTrumbore(ray, left, 0.0f) == kNoHit &&
                        intersectTriangleMollerTrumbore(ray, right, 0.0f) == kNoHit;
    }
    CHECK(watertightMisses == 0);
    MESSAGE("Moller-Trumbore misses " << mollerMisses << " of 20000 rays through the shared edge");

    const Vec3 o{0.37f, -0.21f, 0.55f};
    std::vector<Vec3> rim;
    for (int k = 0; k < 6; ++k)
        rim.push_back(o + Vec3{std::cos(1.047f * k), std::sin(1.047f * k), k % 2 ? 0.1f : -0.1f});
    std::vector<Triangle> fan;
    for (int k = 0; k < 6; ++k) fan.push_back({o, rim[k], rim[(k + 1) % 6], 0});  // each rim vertex shared exactly
    int vertexMisses = 0;
    for (int i = 0; i < 20000; ++i) {
        const Ray ray = rayTowards(o + Vec3{u(rng) - 0.5f, u(rng) - 0.5f, 1.0f}, o);
        bool hit = false;
        for (const Triangle& t : fan) hit = hit || intersectTriangle(ray, t, 0.0f) != kNoHit;
        vertexMisses += !hit;
    }
    CHECK(vertexMisses == 0);
}

TEST_CASE("no scale-dependent threshold: a triangle scaled by 1e-3 stays visible, unlike |det| < 1e-6") {
    const Triangle tiny{{0.0f, 0.0f, 0.0f}, {1e-3f, 0.0f, 0.0f}, {0.0f, 5e-4f, 0.0f}, 0};  // det = 5e-7
    const Ray ray = rayTowards({2e-4f, 1e-4f, 1.0f}, {2e-4f, 1e-4f, 0.0f});
    Vec3 weights;
    CHECK(intersectTriangle(ray, tiny, 0.0f, &weights) == doctest::Approx(1.0f));
    CHECK(weights.x + weights.y + weights.z == doctest::Approx(1.0f));
    CHECK(weights.y == doctest::Approx(0.2f));
    CHECK(intersectTriangleMollerTrumbore(ray, tiny, 0.0f) == kNoHit);
}

TEST_CASE("watertight: a ray leaving a point of the triangle is not hit by it (t below its error bound)") {
    const Triangle tri{{1e3f, 2e3f, -5e2f}, {1.7e3f, 2.2e3f, -4e2f}, {1.1e3f, 2.9e3f, -9e2f}, 0};
    std::mt19937_64 rng(11);
    test::UniformReal<float> u(0.0f, 1.0f);
    int selfHits = 0;
    for (int i = 0; i < 20000; ++i) {
        float w1 = u(rng), w2 = u(rng);
        if (w1 + w2 > 1.0f) w1 = 1.0f - w1, w2 = 1.0f - w2;
        Ray ray;
        ray.origin = (1.0f - w1 - w2) * tri.a + w1 * tri.b + w2 * tri.c;
        const Vec3 n = glm::normalize(glm::cross(tri.b - tri.a, tri.c - tri.a));
        // Leaving on the side the rounded point already lies on, so the exact t is <= 0.
        const float side = test::planeDistance(tri, ray.origin) >= 0 ? 1.0f : -1.0f;
        ray.direction = glm::normalize(side * n + Vec3{u(rng) - 0.5f, u(rng) - 0.5f, u(rng) - 0.5f});
        if (glm::dot(ray.direction, side * n) <= 0.05f) continue;
        selfHits += intersectTriangle(ray, tri, 0.0f) != kNoHit;
    }
    CHECK(selfHits == 0);
}

TEST_CASE("NaN, infinite and zero directions are no hit") {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const Sphere sphere{{0.0f, 0.0f, 0.0f}, 1.0f, 0};
    const Triangle tri{{-1.0f, -1.0f, 0.0f}, {1.0f, -1.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 0};
    for (const Vec3 direction : {Vec3{nan, 0.0f, -1.0f}, Vec3{0.0f}, Vec3{0.0f, 0.0f, -std::numeric_limits<float>::infinity()}}) {
        Ray ray;
        ray.origin = {0.0f, 0.0f, 5.0f};
        ray.direction = direction;
        CHECK(intersectSphere(ray, sphere, 0.0f) == kNoHit);
        CHECK(intersectTriangle(ray, tri, 0.0f) == kNoHit);
        CHECK(intersectTriangleMollerTrumbore(ray, tri, 0.0f) == kNoHit);
    }
}

}  // namespace
}  // namespace lightpath
