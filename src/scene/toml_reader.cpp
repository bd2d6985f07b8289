#include "scene/toml_reader.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "scene/scene_loader.h"
#include "scene/spelling.h"

namespace lightpath {

std::string positionOf(const toml::source_region& where) {
    const std::string file = where.path ? *where.path : std::string("<scene>");
    return file + ":" + std::to_string(where.begin.line) + ":" + std::to_string(where.begin.column);
}

std::string locatedMessage(const toml::source_region& where, std::string_view keyPath,
                           std::string_view message) {
    return positionOf(where) + ": " + std::string(keyPath) + ": " + std::string(message);
}

void failAt(const toml::source_region& where, std::string_view keyPath,
            std::string_view message) {
    throw SceneError(locatedMessage(where, keyPath, message));
}

std::string describe(const toml::node& node) {
    switch (node.type()) {
        case toml::node_type::integer: return std::to_string(node.as_integer()->get());
        case toml::node_type::floating_point: return formatNumber(node.as_floating_point()->get());
        case toml::node_type::string: return "a string (\"" + node.as_string()->get() + "\")";
        case toml::node_type::boolean: return "a boolean";
        case toml::node_type::table: return "a table";
        case toml::node_type::date: return "a date";
        case toml::node_type::time: return "a time";
        case toml::node_type::date_time: return "a date-time";
        case toml::node_type::array: {
            const std::size_t size = node.as_array()->size();
            if (size == 0) return "an empty array";
            return "an array of " + std::to_string(size) + (size == 1 ? " element" : " elements");
        }
        case toml::node_type::none: break;
    }
    return "nothing";
}

namespace {

std::optional<double> numericValue(const toml::node& node) {
    if (const auto* i = node.as_integer()) return static_cast<double>(i->get());
    if (const auto* f = node.as_floating_point()) return f->get();
    return std::nullopt;
}

// Keys and values in the order they appear in the file (toml++ keeps tables sorted by key).
std::vector<std::pair<const toml::key*, const toml::node*>> inFileOrder(const toml::table& table) {
    std::vector<std::pair<const toml::key*, const toml::node*>> entries;
    for (const auto& [key, node] : table) entries.emplace_back(&key, &node);
    std::stable_sort(entries.begin(), entries.end(), [](const auto& a, const auto& b) {
        const toml::source_position& pa = a.first->source().begin;
        const toml::source_position& pb = b.first->source().begin;
        return pa.line != pb.line ? pa.line < pb.line : pa.column < pb.column;
    });
    return entries;
}

}  // namespace

TomlValue::TomlValue(const toml::node& node, std::string keyPath)
    : node_(&node), keyPath_(std::move(keyPath)) {}

std::filesystem::path TomlValue::folder() const {
    const auto& path = node_->source().path;
    return path ? std::filesystem::path(*path).parent_path() : std::filesystem::path();
}

std::string TomlValue::position() const { return positionOf(node_->source()); }

std::string TomlValue::located(std::string_view message) const {
    return locatedMessage(node_->source(), keyPath_, message);
}

void TomlValue::fail(std::string_view message) const {
    failAt(node_->source(), keyPath_, message);
}

void TomlValue::expected(std::string_view what) const {
    fail("expected " + std::string(what) + ", got " + describe(*node_));
}

float TomlValue::number(const NumberRule& rule) const {
    const std::optional<double> value = numericValue(*node_);
    if (!value) expected(rule.expected);
    // NaN and infinity are valid TOML (nan, inf) but never a meaningful scene quantity.
    if (!std::isfinite(*value)) expected("a finite number");
    if (std::abs(*value) > kMaxMagnitude) expected("a number " + std::string(kMagnitudeRange));
    if (!rule.admits(*value)) expected(rule.expected);
    // The rule holds for the number as stored: in single precision 179.999999 is 180, 1e-50 is 0.
    const float stored = static_cast<float>(*value);
    if (!rule.admits(stored)) {
        fail("expected " + std::string(rule.expected) + ", got " + describe(*node_) + ", which is " +
             formatNumber(stored) + " in single precision");
    }
    return stored;
}

int TomlValue::integer(int low, int high) const {
    const std::string rule =
        "an integer from " + std::to_string(low) + " to " + std::to_string(high);
    const auto* node = node_->as_integer();
    if (!node || node->get() < low || node->get() > high) expected(rule);
    return static_cast<int>(node->get());
}

Vec3 TomlValue::vec3(const NumberRule& rule) const {
    const std::vector<TomlValue> xyz = array(3, "3 numbers");
    return {xyz[0].number(rule), xyz[1].number(rule), xyz[2].number(rule)};
}

Vec3 TomlValue::numberOrVec3(const NumberRule& rule) const {
    if (numericValue(*node_)) return Vec3(number(rule));
    if (!node_->is_array()) expected("a number or an array of 3 numbers");
    return vec3(rule);
}

Rgb TomlValue::rgb() const { return numberOrVec3(nonNegative); }

std::string TomlValue::string() const {
    const auto* node = node_->as_string();
    if (!node) expected("a string");
    return node->get();
}

bool TomlValue::boolean() const {
    const auto* node = node_->as_boolean();
    if (!node) expected("true or false");
    return node->get();
}

TomlTable TomlValue::table() const {
    const auto* node = node_->as_table();
    if (!node) expected("a table");
    return TomlTable(*node, keyPath_);
}

std::vector<TomlValue> TomlValue::array(std::size_t size, std::string_view expectedElements) const {
    const auto* node = node_->as_array();
    if (!node || node->size() != size) {
        expected("an array of " + std::string(expectedElements));
    }
    std::vector<TomlValue> elements;
    for (std::size_t i = 0; i < size; ++i) {
        elements.emplace_back((*node)[i], keyPath_ + "[" + std::to_string(i) + "]");
    }
    return elements;
}

std::vector<TomlTable> TomlValue::tables() const {
    // The classic slip is [spheres] where [[spheres]] was meant: say which brackets to write.
    const auto* node = node_->as_array();
    if (!node) expected("an array of tables ([[" + keyPath_ + "]] sections)");
    std::vector<TomlTable> result;
    for (std::size_t i = 0; i < node->size(); ++i) {
        TomlValue element((*node)[i], keyPath_ + "[" + std::to_string(i) + "]");
        result.push_back(element.table());
    }
    return result;
}

TomlTable::TomlTable(const toml::table& table, std::string keyPath)
    : table_(&table), keyPath_(std::move(keyPath)) {}

std::string TomlTable::keyPathOf(std::string_view key) const {
    return keyPath_.empty() ? std::string(key) : keyPath_ + "." + std::string(key);
}

void TomlTable::allowOnly(std::initializer_list<std::string_view> allowed) const {
    allowOnly(std::vector<std::string_view>(allowed));
}

std::string TomlTable::position() const { return positionOf(table_->source()); }

void TomlTable::allowOnly(const std::vector<std::string_view>& allowed) const {
    const std::vector<std::string> known(allowed.begin(), allowed.end());
    for (const auto& [key, node] : inFileOrder(*table_)) {
        if (std::find(known.begin(), known.end(), key->str()) != known.end()) continue;
        failAt(key->source(), keyPathOf(key->str()),
               unknownNameMessage("key", key->str(), known, ListKnown::withoutSuggestion));
    }
}

std::optional<TomlValue> TomlTable::find(std::string_view key) const {
    const toml::node* node = table_->get(key);
    if (!node) return std::nullopt;
    return TomlValue(*node, keyPathOf(key));
}

TomlValue TomlTable::required(std::string_view key) const {
    std::optional<TomlValue> value = find(key);
    if (!value) fail("missing required key \"" + std::string(key) + "\"");
    return *value;
}

std::vector<std::pair<std::string, TomlValue>> TomlTable::entries() const {
    std::vector<std::pair<std::string, TomlValue>> result;
    for (const auto& [key, node] : inFileOrder(*table_)) {
        result.emplace_back(std::string(key->str()), TomlValue(*node, keyPathOf(key->str())));
    }
    return result;
}

void TomlTable::fail(std::string_view message) const {
    failAt(table_->source(), keyPath_, message);
}

void TomlTable::failAtKey(std::string_view key, std::string_view message) const {
    if (const toml::node* node = table_->get(key)) failAt(node->source(), keyPathOf(key), message);
    failAt(table_->source(), keyPathOf(key), message);
}

}  // namespace lightpath
