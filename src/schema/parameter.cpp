#include "schema/parameter.h"

#include <algorithm>
#include <cmath>

#include "schema/format.h"

namespace lightpath {

bool isNameCharacter(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-' || c == '.';
}

bool isValidName(std::string_view name) {
    return !name.empty() && std::all_of(name.begin(), name.end(), isNameCharacter);
}

std::string_view typeName(ParameterType type) {
    switch (type) {
        case ParameterType::Number: return "number";
        case ParameterType::Integer: return "integer";
        case ParameterType::Boolean: return "boolean";
        case ParameterType::Colour: return "RGB or number";
        case ParameterType::NumberOrTexture: return "number or texture";
        case ParameterType::Point: return "point";
        case ParameterType::Vector: return "vector";
        case ParameterType::PerAxis: return "number or [x, y, z]";
        case ParameterType::ThreePoints: return "3 points";
        case ParameterType::Name: return "string";
        case ParameterType::Text: return "string";
    }
    return "value";
}

std::vector<std::string> choicesOf(const Parameter& parameter) {
    std::vector<std::string> words;
    std::string_view rest = parameter.choices;
    while (!rest.empty()) {
        const std::size_t bar = rest.find('|');
        words.emplace_back(rest.substr(0, bar));
        rest = bar == std::string_view::npos ? std::string_view() : rest.substr(bar + 1);
    }
    return words;
}

bool Range::isAny() const { return std::isinf(low) && low < 0 && std::isinf(high) && high > 0; }

std::string Range::describe() const {
    const bool bounded = !std::isinf(low), boundedAbove = !std::isinf(high);
    const std::string lowOp = lowExclusive ? "<" : "<=", highOp = highExclusive ? "<" : "<=";
    if (bounded && boundedAbove) return formatNumber(low) + " " + lowOp + " x " + highOp + " " + formatNumber(high);
    if (bounded) return (lowExclusive ? "> " : ">= ") + formatNumber(low);
    if (boundedAbove) return highOp + " " + formatNumber(high);
    return "any";
}

}  // namespace lightpath
