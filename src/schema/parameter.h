#pragma once
// One key a type accepts (a material's `kd`, a light's `position`): its kind of value, unit,
// default, allowed range and one-line meaning. The loader checks scene files against it,
// `lightpath types` and scenes/README.md's tables print it, the conformance kit samples it.
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace lightpath {

enum class ParameterType : std::uint8_t {
    Number,   // float, finite, within range
    Integer,  // int within range
    Boolean,
    Colour,   // RGB or one number for grey; each channel within range (default >= 0)
    NumberOrTexture,  // a Number, or a texture's one channel (an alpha mask)
    Point,    // [x, y, z], each component within range
    Vector,   // [x, y, z], non-zero
    PerAxis,  // one number for all three axes or [x, y, z], each within range (a mesh's scale)
    ThreePoints,  // [[x,y,z], [x,y,z], [x,y,z]], each coordinate within range (a triangle's corners)
    Name,     // a label: letters, digits, '_', '-', '.'
    Text,     // any string (e.g. a file)
};

// How docs name a type: "number", "RGB or number", "point", ...
std::string_view typeName(ParameterType type);

// A Name's characters. Names become labels in light path expressions, written between single
// quotes (<L'key'>), so they are kept to characters that can always be typed there.
inline constexpr std::string_view kNameCharacters = "letters, digits, '_', '-' or '.'";
bool isNameCharacter(char c);
bool isValidName(std::string_view name);

// What a Number/Integer/Colour channel (or a Point, PerAxis or ThreePoints component) must satisfy.
struct Range {
    double low = -std::numeric_limits<double>::infinity();
    double high = std::numeric_limits<double>::infinity();
    bool lowExclusive = false;
    bool highExclusive = false;

    bool admits(double value) const {
        const bool aboveLow = lowExclusive ? value > low : value >= low;
        const bool belowHigh = highExclusive ? value < high : value <= high;
        return aboveLow && belowHigh;
    }
    bool isAny() const;
    // "> 0", ">= 0", "0 < x < 180", "<= 1", "any"
    std::string describe() const;
};

inline constexpr Range kAnyValue{};
inline constexpr Range kNonNegative{0.0, std::numeric_limits<double>::infinity(), false, false};
inline constexpr Range kPositive{0.0, std::numeric_limits<double>::infinity(), true, false};

struct Parameter {
    std::string_view name;         // the TOML key
    ParameterType type = ParameterType::Number;
    std::string_view unit;         // "W/(m² sr)", "m", "" when it has none
    std::string_view defaultText;  // as docs print it: "0", "[1, 0, 0]", "" when required or none
    Range range;
    std::string_view doc;          // one line: what it means
    bool required = false;
    std::string_view choices;      // the words a Name accepts, "smooth|flat"; empty: any name
    std::string_view excludes;     // a parameter of the same schema that may not be given with this one
};

// The words of `choices`, in order ("smooth|flat" -> smooth, flat).
std::vector<std::string> choicesOf(const Parameter& parameter);

}  // namespace lightpath
