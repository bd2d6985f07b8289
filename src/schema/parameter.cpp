#include "schema/parameter.h"

#include <cmath>

#include "schema/format.h"

namespace lightpath {

std::string_view typeName(ParameterType type) {
    switch (type) {
        case ParameterType::Number: return "number";
        case ParameterType::Integer: return "integer";
        case ParameterType::Boolean: return "boolean";
        case ParameterType::Colour: return "RGB or number";
        case ParameterType::Point: return "point";
        case ParameterType::Vector: return "vector";
        case ParameterType::Name: return "string";
        case ParameterType::Text: return "string";
    }
    return "value";
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
