#include "geometry/ray_offset.h"

#include <bit>
#include <cmath>
#include <cstdint>

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

}  // namespace

Vec3 offsetRayOriginWachterBinder(const Vec3& p, const Vec3& n) {
    return {offsetCoordinateWachterBinder(p.x, n.x), offsetCoordinateWachterBinder(p.y, n.y),
            offsetCoordinateWachterBinder(p.z, n.z)};
}

}  // namespace lightpath
