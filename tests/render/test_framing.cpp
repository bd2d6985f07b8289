// The framing camera (scene/framing.h) sees the whole bounding sphere of a scene, so every corner
// of its box projects inside the image, for any aspect ratio; a camera that fits only the vertical
// field of view (the control) loses corners of a narrow image.
#include <doctest/doctest.h>

#include <cmath>

#include "scene/camera.h"
#include "scene/framing.h"

namespace lightpath {
namespace {

int cornersInside(const CameraDescription& description, const Bounds& box) {
    const Camera camera(description);
    int inside = 0;
    for (int k = 0; k < 8; ++k) {
        const Vec3 corner((k & 1) ? box.hi.x : box.lo.x, (k & 2) ? box.hi.y : box.lo.y, (k & 4) ? box.hi.z : box.lo.z);
        if (camera.project(corner)) ++inside;
    }
    return inside;
}

TEST_CASE("the framing camera sees all 8 corners of the box for any aspect ratio and view") {
    Bounds box;
    box.grow(Vec3(-3.0f, 10.0f, 2.0f));
    box.grow(Vec3(40.0f, 11.0f, 2.5f));  // long, flat and thin, far from the origin
    const int sizes[][2] = {{640, 480}, {480, 640}, {1000, 10}, {10, 1000}, {1, 1}};
    const Vec3 views[] = {kFramingDirection, Vec3(0, 0, 1), Vec3(1, 0, 0), Vec3(-0.2f, 1, 0.1f)};
    for (const auto& size : sizes) {
        const int width = size[0], height = size[1];  // not a structured binding: clang 14's CAPTURE cannot capture one
        for (const Vec3& view : views) {
            for (const float fov : {10.0f, 45.0f, 120.0f}) {
                CameraDescription camera;
                camera.width = width;
                camera.height = height;
                camera.verticalFovDegrees = fov;
                camera.eye = view;
                camera.lookAt = Vec3(0.0f);
                const CameraDescription framed = framingCamera(box, camera);
                CAPTURE(width);
                CAPTURE(height);
                CAPTURE(fov);
                CHECK(framed.lookAt == box.centroid());
                CHECK(framed.width == width);
                CHECK(framed.verticalFovDegrees == fov);
                CHECK(cornersInside(framed, box) == 8);
                // Not merely far enough: at 1.1 r / sin(a), a the smaller half-angle (r the box's
                // half-diagonal), worked out here from the field of view and the aspect ratio.
                const double r = 0.5 * glm::length(glm::dvec3(box.hi - box.lo));
                const double halfVertical = glm::radians(double(fov)) / 2.0;
                const double halfHorizontal = std::atan(std::tan(halfVertical) * double(width) / double(height));
                const double expected = 1.1 * r / std::sin(std::min(halfVertical, halfHorizontal));
                CHECK(glm::length(glm::dvec3(framed.eye - framed.lookAt)) == doctest::Approx(expected).epsilon(1e-4));
            }
        }
    }
}

TEST_CASE("control: a camera fitted to the vertical field of view alone loses corners of a narrow image") {
    Bounds box;
    box.grow(Vec3(-1.0f));
    box.grow(Vec3(1.0f));
    CameraDescription camera;
    camera.width = 100;
    camera.height = 1000;
    const CameraDescription framed = framingCamera(box, camera);
    const double radius = std::sqrt(3.0);
    const double halfVertical = 0.5 * camera.verticalFovDegrees * kPi / 180.0;
    CameraDescription verticalOnly = framed;
    verticalOnly.eye = framed.lookAt + static_cast<float>(kFramingMargin * radius / std::sin(halfVertical)) *
                                           glm::normalize(framed.eye - framed.lookAt);
    CHECK(cornersInside(framed, box) == 8);
    CHECK(cornersInside(verticalOnly, box) < 8);
}

TEST_CASE("an empty scene frames the unit sphere at the origin") {
    const CameraDescription framed = framingCamera(Bounds{}, CameraDescription{});
    CHECK(framed.lookAt == Vec3(0.0f));
    Bounds unit;
    unit.grow(Vec3(-0.5f));
    unit.grow(Vec3(0.5f));
    CHECK(cornersInside(framed, unit) == 8);
}

}  // namespace
}  // namespace lightpath
