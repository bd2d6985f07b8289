#pragma once
// The values one declaration gives a type, checked against its schema, each remembering where it
// came from, so that a type's make() can refuse a combination with a located error.
#include <array>
#include <cstddef>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "math/types.h"
#include "schema/type_schema.h"

namespace lightpath {

// How a texture's texels encode values: sRGB (colour images: decoded by sRGB's EOTF before they
// are filtered) or linear (data: roughness, normals; float images). Automatic: sRGB for 8-bit
// images, linear otherwise. (Here, below the materials, since a TextureReference carries it.)
enum class TextureColorSpace { automatic, srgb, linear };

// A Colour given as an image, `{ texture = "FILE", tint = ..., uv_scale = ..., filter = ... }`:
// the file (resolved against the scene's folder) and how to read it. Materials open it
// (materials/texture.h, colorParameter); the schema only carries it.
struct TextureReference {
    std::string file;
    Rgb tint{1.0f};        // multiplies the texels
    float uvScale = 1.0f;  // texture coordinates are multiplied by it: repeats per unit of uv
    bool filtered = true;  // false: point sampled (the finest level's texels), to show aliasing
    TextureColorSpace colorSpace = TextureColorSpace::automatic;  // `colorspace`: "srgb", "linear"
    // A NumberOrTexture's mask (`cutoff`): the value is 1 where the texel reaches it, else 0.
    std::optional<float> cutoff;
};

class ParameterValues {
public:
    // Every parameter at its default (defaults are parsed from Parameter::defaultText).
    explicit ParameterValues(const TypeSchema& schema);

    const TypeSchema& schema() const { return *schema_; }
    bool has(std::string_view name) const;  // given explicitly

    float number(std::string_view name) const;
    int integer(std::string_view name) const;
    bool boolean(std::string_view name) const;
    // A Colour given as a number or RGB; a located error when it was given as a texture (a
    // parameter its type reads as a constant, e.g. `emission`).
    Rgb colour(std::string_view name) const;
    // The texture a Colour or a NumberOrTexture was given as, or null for a constant. A
    // NumberOrTexture's number() is then its texture's factor (its tint).
    const TextureReference* texture(std::string_view name) const;
    bool anyTexture() const;  // some Colour was given as a texture
    Vec3 vec3(std::string_view name) const;  // a Point, a Vector or a PerAxis
    std::array<Vec3, 3> points(std::string_view name) const;  // ThreePoints
    const std::string& text(std::string_view name) const;  // a Name or a Text

    // Set programmatically (conformance kit, loaders): checks type and range, throws SchemaError.
    void set(std::string_view name, double value);       // Number, NumberOrTexture
    void set(std::string_view name, int value);          // Integer, or a Number
    void set(std::string_view name, bool value);         // Boolean
    void set(std::string_view name, const Vec3& value);  // Colour, Point, Vector, PerAxis
    void set(std::string_view name, const std::array<Vec3, 3>& value);  // ThreePoints
    void set(std::string_view name, std::string value);  // Name, Text
    void set(std::string_view name, const char* value) { set(name, std::string(value)); }
    void set(std::string_view name, TextureReference texture);  // a Colour or NumberOrTexture as a texture

    // Where the declaration is ("FILE:LINE:COL" and its key path, "lights[0]"), for errors about
    // keys it leaves out; and where one value was read.
    void locateDeclaration(std::string position, std::string keyPath);
    void locate(std::string_view name, std::string position, std::string keyPath);

    // "FILE:LINE:COL: KEY_PATH: MESSAGE" at `name` (at the declaration when it was not given;
    // "NAME: MESSAGE" when nothing is located).
    std::string located(std::string_view name, std::string_view message) const;
    [[noreturn]] void fail(std::string_view name, std::string_view message) const;

private:
    using Value = std::variant<float, int, bool, Vec3, std::array<Vec3, 3>, std::string>;
    struct Slot {
        Value value;
        std::optional<TextureReference> texture;  // a Colour given as a texture
        bool given = false;
        std::string position, keyPath;
    };
    std::size_t indexOf(std::string_view name) const;
    const Value& valueOf(std::string_view name, ParameterType expected) const;
    void store(std::string_view name, Value value, std::initializer_list<ParameterType> accepted);

    const TypeSchema* schema_;  // not owned: schemas are static
    std::vector<Slot> slots_;   // one per schema parameter, in its order
    std::string position_, keyPath_;
};

}  // namespace lightpath
