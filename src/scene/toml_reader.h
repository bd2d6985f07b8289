#pragma once
// Typed, checked reading of a scene file's TOML. Every value carries the key path that leads to
// it, so every error can say exactly where the student has to look:
//   FILE:LINE:COLUMN: KEY_PATH: expected ..., got ...
// Private to the scene loader: nothing outside src/scene sees toml++.
#include <cstddef>
#include <filesystem>
#include <initializer_list>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

#include "math/types.h"
#include "schema/format.h"

namespace lightpath {

// "FILE:LINE:COLUMN: KEY_PATH: MESSAGE" for the start of `where`; failAt throws it as a SceneError.
std::string locatedMessage(const toml::source_region& where, std::string_view keyPath,
                           std::string_view message);
[[noreturn]] void failAt(const toml::source_region& where, std::string_view keyPath,
                         std::string_view message);


// How an error message names what it found: "-1", "a string", "an array of 2 elements", ...
std::string describe(const toml::node& node);

// What a number must satisfy, and how an error message says so. Finiteness and |x| <=
// kMaxMagnitude (scene_loader.h) are always required.
struct NumberRule {
    double low = -std::numeric_limits<double>::infinity();
    double high = std::numeric_limits<double>::infinity();
    bool lowExclusive = false;
    bool highExclusive = false;
    std::string_view expected = "a number";

    bool admits(double value) const {
        const bool aboveLow = lowExclusive ? value > low : value >= low;
        const bool belowHigh = highExclusive ? value < high : value <= high;
        return aboveLow && belowHigh;
    }
};

inline constexpr NumberRule anyNumber{};
inline constexpr NumberRule nonNegative{0.0, std::numeric_limits<double>::infinity(), false, false,
                                        "a number >= 0"};
inline constexpr NumberRule positive{0.0, std::numeric_limits<double>::infinity(), true, false,
                                     "a positive number"};

class TomlTable;

// One value of the scene file together with the key path that leads to it ("spheres[2].radius").
class TomlValue {
public:
    TomlValue(const toml::node& node, std::string keyPath);

    const std::string& keyPath() const { return keyPath_; }

    // An integer or a float, finite, within `rule`.
    float number(const NumberRule& rule = anyNumber) const;
    // An integer (not a float) in [low, high].
    int integer(int low, int high) const;
    // [x, y, z], each component within `rule`.
    Vec3 vec3(const NumberRule& rule = anyNumber) const;
    // One number for all three components, or [x, y, z]; each within `rule`.
    Vec3 numberOrVec3(const NumberRule& rule) const;
    // [r, g, b], or one number for grey; each channel >= 0.
    Rgb rgb() const;
    std::string string() const;
    bool boolean() const;
    TomlTable table() const;
    bool isTable() const { return node_->is_table(); }
    // The folder of the file this value was read from ("" when it came from no file).
    std::filesystem::path folder() const;
    // An array of exactly `size` elements; `expected` says what kind, e.g. "3 numbers".
    std::vector<TomlValue> array(std::size_t size, std::string_view expected) const;
    // An array of tables ([[name]] sections).
    std::vector<TomlTable> tables() const;

    // "FILE:LINE:COLUMN" of this value.
    std::string position() const;
    // "FILE:LINE:COLUMN: KEY_PATH: MESSAGE" at this value: for warnings, and thrown by fail().
    std::string located(std::string_view message) const;
    [[noreturn]] void fail(std::string_view message) const;
    [[noreturn]] void expected(std::string_view what) const;  // "expected WHAT, got ..."

private:
    const toml::node* node_;  // not owned: the parsed document outlives every reader
    std::string keyPath_;
};

// One table of the scene file together with its key path ("" for the whole file).
class TomlTable {
public:
    TomlTable(const toml::table& table, std::string keyPath);

    const std::string& keyPath() const { return keyPath_; }
    std::string keyPathOf(std::string_view key) const;

    // Refuses the first key (in file order) that is not in `allowed`, suggesting a near one.
    void allowOnly(std::initializer_list<std::string_view> allowed) const;
    void allowOnly(const std::vector<std::string_view>& allowed) const;
    // "FILE:LINE:COLUMN" of this table.
    std::string position() const;

    std::optional<TomlValue> find(std::string_view key) const;
    // Like find(), but a missing key is an error located at this table.
    TomlValue required(std::string_view key) const;
    // Every key and value, in the order they appear in the file.
    std::vector<std::pair<std::string, TomlValue>> entries() const;

    [[noreturn]] void fail(std::string_view message) const;
    // Fails at `key`'s value if it is present, else at this table; the path names `key` either way.
    [[noreturn]] void failAtKey(std::string_view key, std::string_view message) const;

private:
    const toml::table* table_;  // not owned: the parsed document outlives every reader
    std::string keyPath_;
};

}  // namespace lightpath
