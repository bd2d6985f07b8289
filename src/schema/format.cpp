#include "schema/format.h"

#include <charconv>
#include <cmath>

namespace lightpath {

std::string formatNumber(double value) {
    if (std::isnan(value)) return "nan";
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    // The shortest text that reads back as the same double: 0.1 prints as "0.1", -1.0 as "-1".
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

namespace {

// The shortest text that reads back as the same float: 1e-30f prints as "1e-30", not as the
// double it widens to (1.0000000031710769e-30).
std::string formatFloat(float value) {
    if (!std::isfinite(value)) return formatNumber(value);
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

}  // namespace

std::string formatVec3(const Vec3& v) {
    // Appended piece by piece: `"[" + std::string` trips a false -Wrestrict in g++ 12.
    std::string text = "[";
    text += formatFloat(v.x);
    text += ", ";
    text += formatFloat(v.y);
    text += ", ";
    text += formatFloat(v.z);
    text += "]";
    return text;
}

}  // namespace lightpath
