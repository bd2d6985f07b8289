#include "schema/markdown.h"

namespace lightpath {

namespace {

// Markdown code: `text`. Appended, not "`" + text + "`": GCC 12 inlines operator+(const char*,
// std::string&&) into a memcpy its -Wrestrict check misreads (GCC bug 105329).
std::string codeSpan(std::string_view text) {
    std::string span;
    span.reserve(text.size() + 2);
    span += '`';
    span += text;
    span += '`';
    return span;
}

}  // namespace

std::string allowedText(const Parameter& p) {
    const std::string range = p.range.isAny() ? "any" : codeSpan(p.range.describe());
    switch (p.type) {
        case ParameterType::Colour: return "each channel " + range;
        case ParameterType::Point:
        case ParameterType::PerAxis: return p.range.isAny() ? "any" : "each " + range;
        case ParameterType::ThreePoints: return p.range.isAny() ? "any" : "each coordinate " + range;
        case ParameterType::Vector: return "non-zero";
        case ParameterType::Name: {
            if (p.choices.empty()) return "a name (see Conventions)";
            std::string words;
            for (const std::string& word : choicesOf(p)) words += (words.empty() ? "`" : ", `") + word + "`";
            return words;
        }
        case ParameterType::Boolean: return "`true` or `false`";
        case ParameterType::Text: return "any";
        case ParameterType::Number:
        case ParameterType::NumberOrTexture:
        case ParameterType::Integer: return range;
    }
    return range;
}

std::string defaultCell(const Parameter& p) {
    if (p.required) return "**required**";
    if (p.defaultText.empty()) return "none";
    return codeSpan(p.defaultText);
}

std::string markdownTable(const TypeSchema& schema) {
    std::string table = "| key | type | unit | default | allowed | meaning |\n| --- | --- | --- | --- | --- | --- |\n";
    for (const Parameter& p : schema.parameters) {
        table += "| `" + std::string(p.name) + "` | " + std::string(typeName(p.type)) + " | " +
                 (p.unit.empty() ? std::string("–") : std::string(p.unit)) + " | " + defaultCell(p) + " | " +
                 allowedText(p) + " | " + std::string(p.doc) + " |\n";
    }
    return table;
}

}  // namespace lightpath
