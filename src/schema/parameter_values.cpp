#include "schema/parameter_values.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "schema/format.h"
#include "schema/schema_error.h"

namespace lightpath {
namespace {

// The numbers of a default as docs print it: "0.5", "[1, 0, 0]", "[[0, 0, 0], [1, 0, 0], [0, 1, 0]]".
std::vector<float> parseNumbers(std::string_view text) {
    std::string cleaned(text);
    std::replace_if(cleaned.begin(), cleaned.end(), [](char c) { return c == '[' || c == ']' || c == ','; }, ' ');
    std::istringstream in(cleaned);
    std::vector<float> numbers;
    for (float x; in >> x;) numbers.push_back(x);
    return numbers;
}

// One number is grey (or the same on every axis).
Vec3 parseTriple(std::string_view text) {
    const std::vector<float> n = parseNumbers(text);
    if (n.size() < 3) return Vec3(n.empty() ? 0.0f : n[0]);
    return {n[0], n[1], n[2]};
}

std::array<Vec3, 3> parsePoints(std::string_view text) {
    std::vector<float> n = parseNumbers(text);
    n.resize(9, 0.0f);
    return {Vec3(n[0], n[1], n[2]), Vec3(n[3], n[4], n[5]), Vec3(n[6], n[7], n[8])};
}

std::string unquoted(std::string_view text) {
    if (text.size() >= 2 && text.front() == '"' && text.back() == '"') text = text.substr(1, text.size() - 2);
    return std::string(text);
}

}  // namespace

ParameterValues::ParameterValues(const TypeSchema& schema) : schema_(&schema) {
    for (const Parameter& p : schema.parameters) {
        Slot slot;
        switch (p.type) {
            case ParameterType::Number:
            case ParameterType::NumberOrTexture: slot.value = p.defaultText.empty() ? 0.0f : std::stof(std::string(p.defaultText)); break;
            case ParameterType::Integer: slot.value = p.defaultText.empty() ? 0 : std::stoi(std::string(p.defaultText)); break;
            case ParameterType::Boolean: slot.value = p.defaultText == "true"; break;
            case ParameterType::Colour:
            case ParameterType::Point:
            case ParameterType::Vector:
            case ParameterType::PerAxis: slot.value = parseTriple(p.defaultText); break;
            case ParameterType::ThreePoints: slot.value = parsePoints(p.defaultText); break;
            case ParameterType::Name:
            case ParameterType::Text: slot.value = unquoted(p.defaultText); break;
        }
        slots_.push_back(std::move(slot));
    }
}

std::size_t ParameterValues::indexOf(std::string_view name) const {
    for (std::size_t i = 0; i < schema_->parameters.size(); ++i)
        if (schema_->parameters[i].name == name) return i;
    throw SchemaError(std::string(schema_->family) + " \"" + std::string(schema_->name) + "\" has no parameter \"" +
                      std::string(name) + "\"");
}

bool ParameterValues::has(std::string_view name) const { return slots_[indexOf(name)].given; }

const ParameterValues::Value& ParameterValues::valueOf(std::string_view name, ParameterType expected) const {
    const std::size_t i = indexOf(name);
    const ParameterType type = schema_->parameters[i].type;
    const auto family = [](ParameterType t) {
        if (t == ParameterType::Colour || t == ParameterType::Point || t == ParameterType::Vector ||
            t == ParameterType::PerAxis)
            return ParameterType::Point;
        if (t == ParameterType::Text) return ParameterType::Name;
        if (t == ParameterType::NumberOrTexture) return ParameterType::Number;
        return t;
    };
    if (family(type) != family(expected)) {
        throw SchemaError(std::string(name) + " is a " + std::string(typeName(type)) + ", not a " +
                          std::string(typeName(expected)));
    }
    return slots_[i].value;
}

float ParameterValues::number(std::string_view name) const { return std::get<float>(valueOf(name, ParameterType::Number)); }
int ParameterValues::integer(std::string_view name) const { return std::get<int>(valueOf(name, ParameterType::Integer)); }
bool ParameterValues::boolean(std::string_view name) const { return std::get<bool>(valueOf(name, ParameterType::Boolean)); }
Rgb ParameterValues::colour(std::string_view name) const {
    const Vec3 value = std::get<Vec3>(valueOf(name, ParameterType::Colour));
    if (slots_[indexOf(name)].texture) fail(name, "expected a number or an array of 3 numbers (this parameter takes no texture)");
    return value;
}

const TextureReference* ParameterValues::texture(std::string_view name) const {
    const ParameterType type = schema_->parameters[indexOf(name)].type;
    (void)valueOf(name, type == ParameterType::NumberOrTexture ? type : ParameterType::Colour);
    const Slot& slot = slots_[indexOf(name)];
    return slot.texture ? &*slot.texture : nullptr;
}

bool ParameterValues::anyTexture() const {
    return std::any_of(slots_.begin(), slots_.end(), [](const Slot& slot) { return slot.texture.has_value(); });
}
Vec3 ParameterValues::vec3(std::string_view name) const { return std::get<Vec3>(valueOf(name, ParameterType::Point)); }
std::array<Vec3, 3> ParameterValues::points(std::string_view name) const {
    return std::get<std::array<Vec3, 3>>(valueOf(name, ParameterType::ThreePoints));
}
const std::string& ParameterValues::text(std::string_view name) const {
    return std::get<std::string>(valueOf(name, ParameterType::Text));
}

void ParameterValues::store(std::string_view name, Value value, std::initializer_list<ParameterType> accepted) {
    const std::size_t i = indexOf(name);
    const Parameter& p = schema_->parameters[i];
    if (std::find(accepted.begin(), accepted.end(), p.type) == accepted.end()) {
        throw SchemaError(std::string(name) + ": expected a " + std::string(typeName(p.type)));
    }
    slots_[i].value = std::move(value);
    slots_[i].texture.reset();
    slots_[i].given = true;
}

void ParameterValues::set(std::string_view name, double value) {
    const Parameter& p = schema_->parameters[indexOf(name)];
    const float stored = static_cast<float>(value);
    if (!std::isfinite(value) || !p.range.admits(value) || !p.range.admits(stored)) {
        throw SchemaError(std::string(name) + ": expected a number " + p.range.describe() + ", got " + formatNumber(value));
    }
    store(name, stored, {ParameterType::Number, ParameterType::NumberOrTexture});
}

void ParameterValues::set(std::string_view name, int value) {
    const Parameter& p = schema_->parameters[indexOf(name)];
    if (p.type == ParameterType::Number || p.type == ParameterType::NumberOrTexture)
        return set(name, static_cast<double>(value));
    if (!p.range.admits(value)) {
        throw SchemaError(std::string(name) + ": expected an integer " + p.range.describe() + ", got " + std::to_string(value));
    }
    store(name, value, {ParameterType::Integer});
}

void ParameterValues::set(std::string_view name, bool value) { store(name, value, {ParameterType::Boolean}); }

void ParameterValues::set(std::string_view name, const Vec3& value) {
    const Parameter& p = schema_->parameters[indexOf(name)];
    for (int c = 0; c < 3; ++c) {
        if (!std::isfinite(value[c]) || !p.range.admits(value[c])) {
            throw SchemaError(std::string(name) + ": expected each of 3 numbers " + p.range.describe() + ", got " +
                              formatVec3(value));
        }
    }
    if (p.type == ParameterType::Vector && value == Vec3(0.0f)) {
        throw SchemaError(std::string(name) + ": expected a non-zero vector, got " + formatVec3(value));
    }
    store(name, value, {ParameterType::Colour, ParameterType::Point, ParameterType::Vector, ParameterType::PerAxis});
}

void ParameterValues::set(std::string_view name, const std::array<Vec3, 3>& value) {
    const Parameter& p = schema_->parameters[indexOf(name)];
    for (const Vec3& point : value) {
        for (int c = 0; c < 3; ++c) {
            if (!std::isfinite(point[c]) || !p.range.admits(point[c])) {
                throw SchemaError(std::string(name) + ": expected 3 points, each coordinate " + p.range.describe() +
                                  ", got " + formatVec3(point));
            }
        }
    }
    store(name, value, {ParameterType::ThreePoints});
}

void ParameterValues::set(std::string_view name, std::string value) {
    const Parameter& p = schema_->parameters[indexOf(name)];
    if (p.type == ParameterType::Name && !isValidName(value)) {
        throw SchemaError(std::string(name) + ": expected a name of " + std::string(kNameCharacters) + ", got \"" + value +
                          "\"");
    }
    if (const auto words = choicesOf(p); !words.empty() && std::find(words.begin(), words.end(), value) == words.end()) {
        std::string expected;
        for (const std::string& word : words) expected += (expected.empty() ? "" : ", ") + word;
        throw SchemaError(std::string(name) + ": expected one of " + expected + ", got \"" + value + "\"");
    }
    store(name, std::move(value), {ParameterType::Name, ParameterType::Text});
}

void ParameterValues::set(std::string_view name, TextureReference texture) {
    const Parameter& p = schema_->parameters[indexOf(name)];
    const bool scalar = p.type == ParameterType::NumberOrTexture;
    for (int c = 0; c < 3; ++c) {
        if (!std::isfinite(texture.tint[c]) || !p.range.admits(texture.tint[c]))
            throw SchemaError(std::string(name) + ".tint: expected each of 3 numbers " + p.range.describe() + ", got " +
                              formatVec3(texture.tint));
    }
    if (scalar && !(texture.tint.g == texture.tint.r && texture.tint.b == texture.tint.r))
        throw SchemaError(std::string(name) + ".tint: expected one number, got " + formatVec3(texture.tint));
    if (!(std::isfinite(texture.uvScale) && texture.uvScale > 0.0f))
        throw SchemaError(std::string(name) + ".uv_scale: expected a positive number, got " + formatNumber(texture.uvScale));
    if (texture.cutoff && (!scalar || !(*texture.cutoff >= 0.0f && *texture.cutoff <= 1.0f)))
        throw SchemaError(std::string(name) + ".cutoff: " +
                          (scalar ? "expected a number 0 <= x <= 1, got " + formatNumber(*texture.cutoff)
                                  : std::string("only a texture of a number has a cutoff")));
    if (scalar) store(name, texture.tint.r, {ParameterType::NumberOrTexture});
    else store(name, Vec3(0.0f), {ParameterType::Colour});
    slots_[indexOf(name)].texture = std::move(texture);
}

void ParameterValues::locateDeclaration(std::string position, std::string keyPath) {
    position_ = std::move(position);
    keyPath_ = std::move(keyPath);
}

void ParameterValues::locate(std::string_view name, std::string position, std::string keyPath) {
    Slot& slot = slots_[indexOf(name)];
    slot.position = std::move(position);
    slot.keyPath = std::move(keyPath);
}

std::string ParameterValues::located(std::string_view name, std::string_view message) const {
    const Slot& slot = slots_[indexOf(name)];
    std::string position = slot.position, keyPath = slot.keyPath;
    if (position.empty()) {
        position = position_;
        keyPath = keyPath_.empty() ? std::string(name) : keyPath_ + "." + std::string(name);
    }
    return (position.empty() ? "" : position + ": ") + keyPath + ": " + std::string(message);
}

void ParameterValues::fail(std::string_view name, std::string_view message) const {
    throw SchemaError(located(name, message));
}

}  // namespace lightpath
