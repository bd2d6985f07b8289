#include "scene/camera.h"

#include <cmath>

#include "util/hot_path.h"

namespace lightpath {

Camera::Camera(const CameraDescription& d)
    : eye_(d.eye), projection_(d.projection), width_(d.width), height_(d.height) {
    forward_ = glm::normalize(d.lookAt - d.eye);
    right_ = glm::normalize(glm::cross(forward_, d.up));
    up_ = glm::cross(right_, forward_);
    halfHeight_ = orthographic() ? 0.5f * d.orthographicHeight : std::tan(glm::radians(d.verticalFovDegrees) * 0.5f);
}

Vec2 Camera::filmPlane(float x, float y) const {
    // Map the film position to [-aspect, aspect] x [-1, 1] times halfHeight_: on the image plane at
    // distance 1 (perspective), or on the film itself (orthographic).
    const float aspect = static_cast<float>(width_) / static_cast<float>(height_);
    return {(2.0f * x / static_cast<float>(width_) - 1.0f) * aspect * halfHeight_,
            (1.0f - 2.0f * y / static_cast<float>(height_)) * halfHeight_};
}

Vec3 Camera::filmDirection(float x, float y) const {
    if (orthographic()) return forward_;
    const Vec2 p = filmPlane(x, y);
    return forward_ + p.x * right_ + p.y * up_;
}

Vec3 Camera::filmOrigin(float x, float y) const {
    if (!orthographic()) return eye_;
    const Vec2 p = filmPlane(x, y);
    return eye_ + p.x * right_ + p.y * up_;
}

LIGHTPATH_HOT_PATH
Ray Camera::generateRay(float x, float y) const {
    Ray ray;
    if (orthographic()) {
        ray.origin = filmOrigin(x, y);
        ray.direction = forward_;
        return ray;
    }
    ray.origin = eye_;
    ray.direction = glm::normalize(filmDirection(x, y));
    return ray;
}

float Camera::depth(const Vec3& point) const { return glm::dot(point - eye_, forward_); }

std::optional<Vec2> Camera::filmPosition(const Vec3& point) const {
    // generateRay inverted: the point's coordinates on the image plane at distance 1, or on the
    // orthographic film (no division by depth).
    const Vec3 d = point - eye_;
    const float depth = glm::dot(d, forward_);
    if (!(depth > 0.0f)) return std::nullopt;
    const float aspect = static_cast<float>(width_) / static_cast<float>(height_);
    const float scale = orthographic() ? 1.0f : depth;
    const float u = glm::dot(d, right_) / scale, v = glm::dot(d, up_) / scale;
    return Vec2{(u / (aspect * halfHeight_) + 1.0f) * 0.5f * static_cast<float>(width_),
                (1.0f - v / halfHeight_) * 0.5f * static_cast<float>(height_)};
}

std::optional<std::array<Vec2, 2>> Camera::filmSegment(Vec3 a, Vec3 b) const {
    constexpr float kNear = 1e-4f;
    const float da = depth(a), db = depth(b);
    if (da < kNear && db < kNear) return std::nullopt;
    if (da < kNear) a = a + (b - a) * ((kNear - da) / (db - da));
    if (db < kNear) b = b + (a - b) * ((kNear - db) / (da - db));
    const auto pa = filmPosition(a), pb = filmPosition(b);
    if (!pa || !pb) return std::nullopt;
    return std::array<Vec2, 2>{*pa, *pb};
}

std::optional<Vec2> Camera::project(const Vec3& point) const {
    const std::optional<Vec2> p = filmPosition(point);
    if (!p || !(p->x >= 0.0f && p->x < static_cast<float>(width_) && p->y >= 0.0f && p->y < static_cast<float>(height_)))
        return std::nullopt;
    return p;
}

float Camera::imageArea() const {
    const float aspect = static_cast<float>(width_) / static_cast<float>(height_);
    return (2.0f * aspect * halfHeight_) * (2.0f * halfHeight_);
}

float Camera::cosineInImage(const Vec3& direction) const {
    const float cosTheta = glm::dot(direction, forward_);
    if (!(cosTheta > 0.0f)) return 0.0f;
    const float aspect = static_cast<float>(width_) / static_cast<float>(height_);
    const float u = glm::dot(direction, right_) / cosTheta, v = glm::dot(direction, up_) / cosTheta;
    if (std::fabs(u) > aspect * halfHeight_ || std::fabs(v) > halfHeight_) return 0.0f;
    return cosTheta;
}

float Camera::importance(const Vec3& direction) const {
    if (orthographic()) return 0.0f;  // a Dirac in direction: no join reaches it (connectible())
    const float c = cosineInImage(direction);
    return c > 0.0f ? 1.0f / (imageArea() * c * c * c * c) : 0.0f;
}

float Camera::pdfDirection(const Vec3& direction) const {
    if (orthographic()) return 0.0f;
    const float c = cosineInImage(direction);
    return c > 0.0f ? 1.0f / (imageArea() * c * c * c) : 0.0f;
}

}  // namespace lightpath
