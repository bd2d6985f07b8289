// Secondary rays: every one leaves its surface by more than the hit point's rounding error, at
// any scale, and stays finite when the hit is degenerate.
#include <doctest/doctest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

#include "geometry/ray_offset.h"
#include "accel/scene_geometry.h"
#include "geometry/spawn_ray.h"
#include "math/float_bits.h"
#include "reference.h"
#include "../support/uniform_real.h"

namespace lightpath {
namespace {

bool finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Same float, bit for bit (NaN: any NaN).
bool sameFloat(float a, float b) {
    return std::isnan(a) ? std::isnan(b) : std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b);
}
bool sameRay(const Ray& a, const Ray& b) {
    for (int i = 0; i < 3; ++i)
        if (!sameFloat(a.origin[i], b.origin[i]) || !sameFloat(a.direction[i], b.direction[i])) return false;
    return sameFloat(a.tMin, b.tMin) && sameFloat(a.tMax, b.tMax) && a.ignoredPrimitive == b.ignoredPrimitive;
}

TEST_CASE("nextFloatUp and nextFloatDown are std::nextafter towards +inf and -inf") {
    using limits = std::numeric_limits<float>;
    constexpr float inf = limits::infinity();
    std::vector<float> values{0.0f, -0.0f, limits::denorm_min(), -limits::denorm_min(), limits::min(), -limits::min(),
                              limits::max(), -limits::max(), inf, -inf, limits::quiet_NaN(), 1.0f, -1.0f,
                              std::bit_cast<float>(0x007fffffu), std::bit_cast<float>(0x807fffffu)};
    std::mt19937 rng(17);
    for (int i = 0; i < 2000000; ++i) values.push_back(std::bit_cast<float>(static_cast<std::uint32_t>(rng())));
    for (const float x : values) {
        CAPTURE(x);
        REQUIRE(sameFloat(nextFloatUp(x), std::nextafter(x, inf)));
        REQUIRE(sameFloat(nextFloatDown(x), std::nextafter(x, -inf)));
    }
    // The cases that differ from "bits plus or minus one": through zero, and the infinities.
    CHECK(sameFloat(nextFloatUp(-limits::denorm_min()), -0.0f));
    CHECK(sameFloat(nextFloatDown(limits::denorm_min()), 0.0f));
    CHECK(sameFloat(nextFloatUp(-0.0f), limits::denorm_min()));
    CHECK(sameFloat(nextFloatUp(limits::max()), inf));
    CHECK(sameFloat(nextFloatUp(-inf), -limits::max()));
    CHECK(sameFloat(nextFloatDown(-inf), -inf));
}

TEST_CASE("shadow rays from shared origins are the rays spawned one by one, under every offset method") {
    std::mt19937_64 rng(5);
    test::UniformReal<float> u(-1.0f, 1.0f);
    const Sphere sphere{{0.3f, -0.2f, 0.5f}, 0.7f, 0};
    for (const RayOffset offset : {RayOffset::Robust, RayOffset::WachterBinder, RayOffset::FixedEpsilon, RayOffset::None,
                                   RayOffset::OwnPrimitive}) {
        NumericsOptions numerics;
        numerics.offset = offset;
        const SceneGeometry geometry({sphere}, {}, {}, numerics);
        int compared = 0;
        for (int i = 0; i < 2000; ++i) {
            Ray camera;
            camera.origin = Vec3{u(rng), u(rng), u(rng)} * 4.0f + Vec3{0.0f, 0.0f, 6.0f};
            camera.direction = glm::normalize(sphere.center + 0.5f * Vec3{u(rng), u(rng), u(rng)} - camera.origin);
            auto hit = geometry.intersect(camera);
            if (!hit) continue;
            if (i % 7 == 0) hit->normal = Vec3{0.0f};  // a degenerate hit: no side, each ray leaves along itself
            RayOrigins origins(*hit, numerics);
            for (int light = 0; light < 4; ++light) {  // lights on both sides of the surface, some twice
                const Vec3 target = hit->point + 3.0f * Vec3{u(rng), u(rng), u(rng)};
                CAPTURE(i);
                CHECK(sameRay(spawnShadowRay(origins, target, Vec3{0.0f}), spawnShadowRay(*hit, target, Vec3{0.0f}, numerics)));
                CHECK(sameRay(spawnShadowRay(origins, target, Vec3{0.0f}), spawnShadowRay(*hit, target, Vec3{0.0f}, numerics)));
                ++compared;
            }
        }
        CHECK(compared > 1000);
    }
}

// Shadow rays between two points seen from inside a closed surface, the second point ending the
// segment as an area light's sample does: {blocked with the target's normal, blocked without it}.
// Short chords graze the surface, so an error of an ulp across it is many along the ray.
struct ChordCount {
    int blocked = 0, blockedWithoutNormal = 0, cast = 0;
};
ChordCount castChords(const SceneGeometry& geometry, const Vec3& inside) {
    std::mt19937_64 rng(11);
    test::UniformReal<float> u(-1.0f, 1.0f);
    ChordCount count;
    for (int i = 0; i < 20000; ++i) {
        const Vec3 d = glm::normalize(Vec3{u(rng), u(rng), u(rng)});
        const float spread = std::pow(10.0f, -4.0f + 4.0f * (0.5f + 0.5f * u(rng)));  // chords 1e-4 .. 1 long
        const Vec3 e = glm::normalize(d + spread * Vec3{u(rng), u(rng), u(rng)});
        const auto from = geometry.intersect(Ray{inside, d});
        const auto to = geometry.intersect(Ray{inside, e});
        if (!from || !to || from->point == to->point) continue;
        ++count.cast;
        count.blocked += geometry.occluded(spawnShadowRay(*from, to->point, to->normal, geometry.numerics()));
        count.blockedWithoutNormal += geometry.occluded(spawnShadowRay(*from, to->point, Vec3{0.0f}, geometry.numerics()));
    }
    return count;
}

TEST_CASE("a shadow ray ending on a surface is not blocked by that surface, along grazing chords of a closed sphere and box") {
    const Vec3 inside{0.1f, -0.2f, 0.05f};
    std::vector<Triangle> box;  // the cube [-1, 1]^3, two triangles a face
    for (int axis = 0; axis < 3; ++axis) {
        for (const float side : {-1.0f, 1.0f}) {
            const auto corner = [&](float s, float t) {
                Vec3 p{0.0f};
                p[axis] = side;
                p[(axis + 1) % 3] = s;
                p[(axis + 2) % 3] = t;
                return p;
            };
            box.push_back({corner(-1, -1), corner(1, -1), corner(1, 1), 0});
            box.push_back({corner(-1, -1), corner(1, 1), corner(-1, 1), 0});
        }
    }
    for (const RayOffset offset : {RayOffset::Robust, RayOffset::WachterBinder}) {
        NumericsOptions numerics;
        numerics.offset = offset;
        CAPTURE(int(offset));
        const ChordCount sphere = castChords(SceneGeometry({Sphere{{0.0f, 0.0f, 0.0f}, 1.0f, 0}}, {}, {}, numerics), inside);
        CHECK(sphere.cast > 19000);
        CHECK(sphere.blocked == 0);
        // The control: a point target is only shortened by a fixed fraction, which these chords defeat.
        CHECK(sphere.blockedWithoutNormal > 0);
        const ChordCount cube = castChords(SceneGeometry({}, {}, box, numerics), inside);
        CHECK(cube.cast > 19000);
        CHECK(cube.blocked == 0);
        CHECK(cube.blockedWithoutNormal > 0);
        MESSAGE("blocked without the target's normal: sphere ", sphere.blockedWithoutNormal, ", box ",
                cube.blockedWithoutNormal, " of ", cube.cast);
    }
}

TEST_CASE("the robust offset puts the origin on the leaving side of the exact plane, at every scale") {
    std::mt19937_64 rng(3);
    test::UniformReal<float> u(0.0f, 1.0f);
    for (const float scale : {1e-4f, 1.0f, 1e6f}) {
        CAPTURE(scale);
        const Triangle tri{scale * Vec3{0.3f, 0.1f, 0.2f}, scale * Vec3{1.1f, 0.4f, -0.3f}, scale * Vec3{0.2f, 0.9f, 0.7f}, 0};
        const SceneGeometry geometry({}, {}, {tri});
        int wrongSide = 0, selfHits = 0;
        for (int i = 0; i < 5000; ++i) {
            const Vec3 target = tri.a + 0.3f * (tri.b - tri.a) * u(rng) + 0.3f * (tri.c - tri.a) * u(rng);
            Ray camera;
            camera.origin = target + scale * Vec3{0.2f, 0.3f, 2.0f};
            camera.direction = glm::normalize(target - camera.origin);
            const auto hit = geometry.intersect(camera);
            REQUIRE(hit);
            const Vec3 light = hit->point + scale * glm::normalize(-camera.direction + Vec3{u(rng), 0.0f, u(rng)});
            const Ray shadow = spawnShadowRay(*hit, light, Vec3{0.0f}, geometry.numerics());
            const long double side = test::planeDistance(tri, shadow.origin) * test::planeDistance(tri, light);
            wrongSide += !(side > 0);
            selfHits += geometry.occluded(shadow);
        }
        CHECK(wrongSide == 0);
        CHECK(selfHits == 0);
    }
}

TEST_CASE("the offset scales with the point: a contact gap of 1e-3 of a tiny scene stays closed") {
    const Vec3 p{1e-4f, 2e-4f, -1e-4f};
    const Vec3 moved = offsetRayOrigin(p, {0.0f, 1.0f, 0.0f}, 1e-4f);
    CHECK(moved.y > p.y);
    CHECK(moved.y - p.y < 1e-3f * 1e-4f);
    // Wachter and Binder's absolute offset near the origin is larger than that gap.
    CHECK(offsetRayOriginWachterBinder(p, {0.0f, 1.0f, 0.0f}).y - p.y > 1e-7f);
}

TEST_CASE("spawned rays stay finite from a zero-length or NaN normal and towards a light on the point") {
    SurfaceHit hit;
    hit.point = {1.0f, 2.0f, 3.0f};
    for (const Vec3 normal : {Vec3{0.0f}, Vec3{std::numeric_limits<float>::quiet_NaN()}}) {
        hit.normal = normal;
        const Ray ray = spawnRay(hit, {0.0f, 1.0f, 0.0f}, NumericsOptions{});
        CHECK(finite(ray.origin));
        CHECK(ray.origin.y > hit.point.y);
        const Ray shadow = spawnShadowRay(hit, hit.point, Vec3{0.0f}, NumericsOptions{});
        CHECK(finite(shadow.origin));
        CHECK_FALSE(std::isnan(shadow.tMax));
    }
}

TEST_CASE("shadow segments stop short of the light") {
    SurfaceHit hit;
    hit.point = {0.0f, 0.0f, 0.0f};
    hit.normal = {0.0f, 1.0f, 0.0f};
    const Ray shadow = spawnShadowRay(hit, {0.0f, 4.0f, 0.0f}, Vec3{0.0f}, NumericsOptions{});
    CHECK(shadow.tMax < 4.0f);
    CHECK(shadow.tMax > 3.999f);
}

}  // namespace
}  // namespace lightpath
