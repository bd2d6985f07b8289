#pragma once
#include <array>
#include <optional>

#include "math/ray.h"
#include "math/types.h"

namespace lightpath {

// A pinhole camera. The vertical field of view is fixed; the horizontal one follows the image's
// aspect ratio, so changing the resolution never stretches the picture, it widens or narrows it.
struct CameraDescription {
    Vec3 eye{0.0f, 0.0f, 5.0f};
    Vec3 lookAt{0.0f};
    Vec3 up{0.0f, 1.0f, 0.0f};
    float verticalFovDegrees = 45.0f;
    int width = 640;
    int height = 480;
};

class Camera {
public:
    explicit Camera(const CameraDescription& description);

    // Ray through the film position (x, y) in pixels, (0,0) the top-left corner of the image;
    // the centre of pixel (i, j) is (i + 0.5, j + 0.5).
    Ray generateRay(float x, float y) const;
    // The unnormalised direction of that ray: the film position's point on the image plane at
    // distance 1 (forward + u right + v up). Linear in (x, y), which is what a rasteriser's edge
    // functions and perspective-correct depth need.
    Vec3 filmDirection(float x, float y) const;

    // The film position (pixels, (0,0) top-left, as generateRay takes it) whose ray passes through
    // `point`; nullopt when the point is behind the camera or outside the image.
    std::optional<Vec2> project(const Vec3& point) const;
    // The same film position wherever it falls, inside the image or not (for drawing a path's
    // segments that leave it); nullopt only on or behind the plane of the eye.
    std::optional<Vec2> filmPosition(const Vec3& point) const;
    // Distance of `point` in front of the eye along the viewing direction (negative: behind).
    float depth(const Vec3& point) const;
    // The film positions of the ends of the part of segment a-b in front of the eye (for drawing
    // a path over the image); nullopt when all of it is behind. Clipped in 3D first, since
    // projecting a point behind the eye flips it.
    std::optional<std::array<Vec2, 2>> filmSegment(Vec3 a, Vec3 b) const;

    // The pinhole's importance We and directional density for a unit direction leaving the eye
    // (Veach 1997, 10.3.4.3; pbrt-v4 5.2.3), both 0 outside the image. With A the image's area on
    // the plane at distance 1 and theta the angle to the optical axis, a film position uniform over
    // the image gives directions of density 1 / (A cos^3 theta), and We = 1 / (A cos^4 theta): a
    // light path splatting beta f We cos(theta) / d^2 adds, on average, 1/(width height) of each
    // pixel's mean radiance, so one light path per pixel sample makes the splats' sum / spp exact.
    float importance(const Vec3& direction) const;
    float pdfDirection(const Vec3& direction) const;

    int width() const { return width_; }
    int height() const { return height_; }
    const Vec3& eye() const { return eye_; }
    const Vec3& forward() const { return forward_; }  // unit, the optical axis

private:
    // cos theta of a direction with the optical axis when it passes through the image, else 0.
    float cosineInImage(const Vec3& direction) const;
    float imageArea() const;  // A, on the plane at distance 1

    Vec3 eye_, right_, up_, forward_;
    float halfHeight_ = 1.0f;  // tan(fov/2)
    int width_ = 1, height_ = 1;
};

}  // namespace lightpath
