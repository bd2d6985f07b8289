// Camera::filmPosition and project against hand-computed positions, and as generateRay's inverse.
#include <doctest/doctest.h>

#include "scene/camera.h"

using namespace lightpath;

TEST_CASE("project: hand-computed positions of a 90-degree camera looking down -z") {
    // tan(45 deg) = 1 and a 200x100 image (aspect 2): the image plane at distance 1 spans
    // x in [-2, 2] and y in [-1, 1].
    CameraDescription d;
    d.eye = {0.0f, 0.0f, 0.0f};
    d.lookAt = {0.0f, 0.0f, -1.0f};
    d.verticalFovDegrees = 90.0f;
    d.width = 200;
    d.height = 100;
    const Camera camera(d);
    const auto centre = camera.filmPosition({0.0f, 0.0f, -5.0f});
    REQUIRE(centre);
    CHECK(centre->x == doctest::Approx(100.0));
    CHECK(centre->y == doctest::Approx(50.0));
    // (1, 0.5, -1): u = 1 of 2 -> x = (1/2 + 1) * 100 = 150; v = 0.5 -> y = (1 - 0.5) * 50 = 25.
    const auto p = camera.filmPosition({1.0f, 0.5f, -1.0f});
    REQUIRE(p);
    CHECK(p->x == doctest::Approx(150.0));
    CHECK(p->y == doctest::Approx(25.0));
    // Twice as far, twice as large: the same pixel.
    const auto q = camera.filmPosition({2.0f, 1.0f, -2.0f});
    REQUIRE(q);
    CHECK(q->x == doctest::Approx(150.0));
    CHECK(q->y == doctest::Approx(25.0));
    // The top-left corner of the image plane.
    const auto corner = camera.filmPosition({-2.0f, 1.0f, -1.0f});
    REQUIRE(corner);
    CHECK(corner->x == doctest::Approx(0.0).epsilon(1e-5));
    CHECK(corner->y == doctest::Approx(0.0).epsilon(1e-5));
    // Behind the eye, and in its plane: no position.
    CHECK_FALSE(camera.filmPosition({0.0f, 0.0f, 1.0f}));
    CHECK_FALSE(camera.filmPosition({1.0f, 0.0f, 0.0f}));
    CHECK(camera.depth({0.0f, 3.0f, -4.0f}) == doctest::Approx(4.0));
    // Outside the image: a film position (u = 3 of 2 -> x = 250), but not a projection into it.
    const auto outside = camera.filmPosition({3.0f, 0.0f, -1.0f});
    REQUIRE(outside);
    CHECK(outside->x == doctest::Approx(250.0));
    CHECK_FALSE(camera.project({3.0f, 0.0f, -1.0f}));
    REQUIRE(camera.project({1.0f, 0.5f, -1.0f}));
}

TEST_CASE("project: the point a generated ray reaches lands on the film position it came from") {
    CameraDescription d;
    d.eye = {0.3f, 1.8f, 7.5f};
    d.lookAt = {0.0f, 1.0f, 0.0f};
    d.verticalFovDegrees = 40.0f;
    d.width = 64;
    d.height = 48;
    const Camera camera(d);
    for (const float x : {0.5f, 10.25f, 31.0f, 63.5f}) {
        for (const float y : {0.5f, 20.75f, 47.5f}) {
            const Ray ray = camera.generateRay(x, y);
            const auto p = camera.filmPosition(ray.origin + 3.7f * ray.direction);
            REQUIRE(p);
            CHECK(p->x == doctest::Approx(x).epsilon(1e-4));
            CHECK(p->y == doctest::Approx(y).epsilon(1e-4));
        }
    }
}
