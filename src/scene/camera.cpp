#include "scene/camera.h"

#include <cmath>

#include "util/hot_path.h"

namespace lightpath {

Camera::Camera(const CameraDescription& d)
    : eye_(d.eye), width_(d.width), height_(d.height) {
    forward_ = glm::normalize(d.lookAt - d.eye);
    right_ = glm::normalize(glm::cross(forward_, d.up));
    up_ = glm::cross(right_, forward_);
    halfHeight_ = std::tan(glm::radians(d.verticalFovDegrees) * 0.5f);
}

Vec3 Camera::filmDirection(float x, float y) const {
    // Map the film position to [-aspect, aspect] x [-1, 1] (times tan(fov/2)) on the image plane
    // at distance 1.
    const float aspect = static_cast<float>(width_) / static_cast<float>(height_);
    const float u = (2.0f * x / static_cast<float>(width_) - 1.0f) * aspect * halfHeight_;
    const float v = (1.0f - 2.0f * y / static_cast<float>(height_)) * halfHeight_;
    return forward_ + u * right_ + v * up_;
}

LIGHTPATH_HOT_PATH
Ray Camera::generateRay(float x, float y) const {
    Ray ray;
    ray.origin = eye_;
    ray.direction = glm::normalize(filmDirection(x, y));
    return ray;
}

float Camera::depth(const Vec3& point) const { return glm::dot(point - eye_, forward_); }

std::optional<Vec2> Camera::filmPosition(const Vec3& point) const {
    // generateRay inverted: the point's coordinates on the image plane at distance 1.
    const Vec3 d = point - eye_;
    const float depth = glm::dot(d, forward_);
    if (!(depth > 0.0f)) return std::nullopt;
    const float aspect = static_cast<float>(width_) / static_cast<float>(height_);
    const float u = glm::dot(d, right_) / depth, v = glm::dot(d, up_) / depth;
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
    const float c = cosineInImage(direction);
    return c > 0.0f ? 1.0f / (imageArea() * c * c * c * c) : 0.0f;
}

float Camera::pdfDirection(const Vec3& direction) const {
    const float c = cosineInImage(direction);
    return c > 0.0f ? 1.0f / (imageArea() * c * c * c) : 0.0f;
}

}  // namespace lightpath
