#pragma once
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

class PinholeCamera {
public:
    explicit PinholeCamera(const CameraDescription& description);

    // Ray through the film position (x, y) in pixels, (0,0) the top-left corner of the image;
    // the centre of pixel (i, j) is (i + 0.5, j + 0.5).
    Ray generateRay(float x, float y) const;

    // The inverse of generateRay: the film position (x, y) in pixels where `point` appears, or
    // nothing when it lies on or behind the plane of the eye (depth <= 0). Positions outside
    // [0, width] x [0, height] are points outside the picture.
    std::optional<Vec2> project(const Vec3& point) const;
    // Distance of `point` in front of the eye along the viewing direction (negative: behind).
    float depth(const Vec3& point) const;

    int width() const { return width_; }
    int height() const { return height_; }
    const Vec3& eye() const { return eye_; }

private:
    Vec3 eye_, right_, up_, forward_;
    float halfHeight_ = 1.0f;  // tan(fov/2)
    int width_ = 1, height_ = 1;
};

}  // namespace lightpath
