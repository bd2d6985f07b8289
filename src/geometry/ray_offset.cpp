#include "geometry/ray_offset.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

#include "math/float_bits.h"
#include "util/hot_path.h"

namespace lightpath {
namespace {

constexpr float kOrigin = 1.0f / 32.0f;     // below this magnitude use the absolute offset
constexpr float kFloatScale = 1.0f / 65536.0f;
constexpr float kIntScale = 256.0f;         // ulps per unit of normal

float offsetCoordinateWachterBinder(float p, float n) {
    const auto ulps = static_cast<std::int32_t>(kIntScale * n);
    const auto bits = std::bit_cast<std::int32_t>(p);
    // Adding to the integer representation moves by ulps; the sign picks the direction.
    const float moved = std::bit_cast<float>(bits + ((p < 0.0f) ? -ulps : ulps));
    return std::fabs(p) < kOrigin ? p + kFloatScale * n : moved;
}

// One float further along the normal's sign, so rounding of p + offset cannot undo the move.
float roundAway(float moved, float normal) {
    if (normal > 0.0f) return nextFloatUp(moved);
    if (normal < 0.0f) return nextFloatDown(moved);
    return moved;
}

}  // namespace

LIGHTPATH_HOT_PATH
Vec3 offsetRayOrigin(const Vec3& p, const Vec3& n, float travelled) {
    const Vec3 magnitude = glm::abs(p);
    const float t = std::isfinite(travelled) ? std::fabs(travelled) : 0.0f;
    const float error = kPointErrorScale * (std::max({magnitude.x, magnitude.y, magnitude.z}) + 2.0f * t);
    const float distance = error * (std::fabs(n.x) + std::fabs(n.y) + std::fabs(n.z));
    const Vec3 offset = distance * n;
    const Vec3 moved = p + offset;
    return {roundAway(moved.x, n.x), roundAway(moved.y, n.y), roundAway(moved.z, n.z)};
}

Vec3 offsetRayOriginWachterBinder(const Vec3& p, const Vec3& n) {
    return {offsetCoordinateWachterBinder(p.x, n.x), offsetCoordinateWachterBinder(p.y, n.y),
            offsetCoordinateWachterBinder(p.z, n.z)};
}

}  // namespace lightpath
