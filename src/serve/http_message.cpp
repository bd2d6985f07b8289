#include "serve/http_message.h"

#include <algorithm>

namespace lightpath::serve {
namespace {

int hexDigit(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

// RFC 3986 2.1; a '%' not followed by two hex digits stays as it is.
std::string percentDecode(std::string_view text, bool plusIsSpace) {
    std::string decoded;
    decoded.reserve(text.size());
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '%' && i + 2 < text.size() && hexDigit(text[i + 1]) >= 0 && hexDigit(text[i + 2]) >= 0) {
            decoded.push_back(static_cast<char>(hexDigit(text[i + 1]) * 16 + hexDigit(text[i + 2])));
            i += 2;
        } else {
            decoded.push_back(plusIsSpace && c == '+' ? ' ' : c);
        }
    }
    return decoded;
}

char lower(char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; }

}  // namespace

bool equalsIgnoringCase(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) { return lower(x) == lower(y); });
}

std::vector<std::string_view> headerValues(const HeaderList& headers, std::string_view name) {
    std::vector<std::string_view> values;
    for (const auto& [key, value] : headers)
        if (equalsIgnoringCase(key, name)) values.emplace_back(value);
    return values;
}

bool Target::has(std::string_view key) const { return value(key).has_value(); }

std::optional<std::string> Target::value(std::string_view key) const {
    for (const auto& [k, v] : parameters)
        if (k == key) return v;
    return std::nullopt;
}

Target parseTarget(std::string_view target) {
    Target parsed;
    const std::size_t question = target.find('?');
    parsed.path = percentDecode(target.substr(0, question), false);
    if (question == std::string_view::npos) return parsed;
    std::string_view query = target.substr(question + 1);
    while (!query.empty()) {
        const std::size_t end = query.find('&');
        const std::string_view pair = query.substr(0, end);
        if (!pair.empty()) {
            const std::size_t equals = pair.find('=');
            parsed.parameters.emplace_back(percentDecode(pair.substr(0, equals), true),
                                           equals == std::string_view::npos ? std::string() : percentDecode(pair.substr(equals + 1), true));
        }
        if (end == std::string_view::npos) break;
        query.remove_prefix(end + 1);
    }
    return parsed;
}

}  // namespace lightpath::serve
