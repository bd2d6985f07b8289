#include "scene/camera.h"

#include <cmath>

namespace lightpath {

PinholeCamera::PinholeCamera(const CameraDescription& d)
    : eye_(d.eye), width_(d.width), height_(d.height) {
    forward_ = glm::normalize(d.lookAt - d.eye);
    right_ = glm::normalize(glm::cross(forward_, d.up));
    up_ = glm::cross(right_, forward_);
    halfHeight_ = std::tan(glm::radians(d.verticalFovDegrees) * 0.5f);
}

Ray PinholeCamera::generateRay(float x, float y) const {
    // Map the film position to [-aspect, aspect] x [-1, 1] on the image plane at distance 1.
    const float aspect = static_cast<float>(width_) / static_cast<float>(height_);
    const float u = (2.0f * x / static_cast<float>(width_) - 1.0f) * aspect * halfHeight_;
    const float v = (1.0f - 2.0f * y / static_cast<float>(height_)) * halfHeight_;
    Ray ray;
    ray.origin = eye_;
    ray.direction = glm::normalize(forward_ + u * right_ + v * up_);
    return ray;
}

float PinholeCamera::depth(const Vec3& point) const { return glm::dot(point - eye_, forward_); }

std::optional<Vec2> PinholeCamera::project(const Vec3& point) const {
    // generateRay's mapping run backwards: the point's offset from the eye in the camera frame,
    // divided by its depth, lands on the image plane at distance 1 (perspective division).
    const Vec3 offset = point - eye_;
    const float z = glm::dot(offset, forward_);
    if (!(z > 0.0f)) return std::nullopt;
    const float aspect = static_cast<float>(width_) / static_cast<float>(height_);
    const float u = glm::dot(offset, right_) / z, v = glm::dot(offset, up_) / z;
    return Vec2{(u / (aspect * halfHeight_) + 1.0f) * 0.5f * static_cast<float>(width_),
                (1.0f - v / halfHeight_) * 0.5f * static_cast<float>(height_)};
}

}  // namespace lightpath
