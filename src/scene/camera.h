#pragma once
#include <array>
#include <cstdint>
#include <optional>

#include "math/ray.h"
#include "math/types.h"

namespace lightpath {

// How the film maps to rays: through one point (a pinhole, perspective), or parallel to the view
// from a rectangle of the film's size in the scene (orthographic, as an architect's elevation or
// a diagram shows it: sizes do not shrink with distance).
enum class Projection : std::uint8_t { Perspective, Orthographic };

// The camera as a scene gives it. The vertical extent is fixed (the field of view, or the
// orthographic view's height); the horizontal one follows the image's aspect ratio, so changing
// the resolution never stretches the picture, it widens or narrows it.
struct CameraDescription {
    Vec3 eye{0.0f, 0.0f, 5.0f};
    Vec3 lookAt{0.0f};
    Vec3 up{0.0f, 1.0f, 0.0f};
    float verticalFovDegrees = 45.0f;
    Projection projection = Projection::Perspective;
    float orthographicHeight = 2.0f;  // the orthographic view's height in scene units, centred on the eye
    int width = 640;
    int height = 480;
};

// A perspective camera is a pinhole at the eye. An orthographic one shoots parallel rays along
// the view from the film: a rectangle through the eye, perpendicular to the view, its height
// orthographicHeight (pbrt-v4 5.1's OrthographicCamera).
class Camera {
public:
    explicit Camera(const CameraDescription& description);

    // Ray through the film position (x, y) in pixels, (0,0) the top-left corner of the image;
    // the centre of pixel (i, j) is (i + 0.5, j + 0.5).
    Ray generateRay(float x, float y) const;
    // The unnormalised direction of that ray: perspective, the film position's point on the image
    // plane at distance 1 (forward + u right + v up), linear in (x, y), which is what a
    // rasteriser's edge functions and perspective-correct depth need; orthographic, forward.
    Vec3 filmDirection(float x, float y) const;
    // Where that ray starts: the eye, or (orthographic) the film position's point on the film,
    // eye + u right + v up, linear in (x, y).
    Vec3 filmOrigin(float x, float y) const;
    bool orthographic() const { return projection_ == Projection::Orthographic; }

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

    // Whether a point can be joined to the camera by a ray (light tracing, bdpt's t = 1): a
    // pinhole, yes; an orthographic camera sees along one direction only, a Dirac no join meets.
    bool connectible() const { return !orthographic(); }
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
    const Vec3& eye() const { return eye_; }  // orthographic: the film's centre
    const Vec3& forward() const { return forward_; }  // unit, the optical axis
    const Vec3& right() const { return right_; }      // unit, the film's x
    const Vec3& up() const { return up_; }            // unit, the film's y up

private:
    // A film position on the plane of filmDirection (perspective) or filmOrigin (orthographic),
    // in right and up units.
    Vec2 filmPlane(float x, float y) const;
    // cos theta of a direction with the optical axis when it passes through the image, else 0.
    float cosineInImage(const Vec3& direction) const;
    float imageArea() const;  // A, on the plane at distance 1

    Vec3 eye_, right_, up_, forward_;
    float halfHeight_ = 1.0f;  // tan(fov/2); orthographic: half the view's height
    Projection projection_ = Projection::Perspective;
    int width_ = 1, height_ = 1;
};

}  // namespace lightpath
