#include "lpe/path_string.h"

#include <algorithm>

#include "lpe/error.h"

namespace lpe {
namespace {

bool isLetter(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }

std::string shown(char c) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte > 0x20 && byte < 0x7f) return std::string("'") + c + "'";
    constexpr const char* kHex = "0123456789ABCDEF";
    return std::string("byte 0x") + kHex[byte >> 4] + kHex[byte & 0xf];
}

bool eventType(char c, EventType& type) {
    switch (c) {
        case 'E':
        case 'C': type = EventType::Camera; return true;
        case 'R': type = EventType::Reflection; return true;
        case 'T': type = EventType::Transmission; return true;
        case 'L': type = EventType::Emitter; return true;
        case 'B': type = EventType::Background; return true;
        default: return false;
    }
}

bool scatter(char c, Scatter& scatter) {
    switch (c) {
        case 'D': scatter = Scatter::Diffuse; return true;
        case 'G': scatter = Scatter::Glossy; return true;
        case 'S': scatter = Scatter::Specular; return true;
        case 's': scatter = Scatter::Straight; return true;
        case '_': scatter = Scatter::None; return true;
        default: return false;
    }
}

class PathParser {
public:
    PathParser(std::string_view text, std::size_t first, std::size_t past)
        : text_(text), pos_(first), past_(past) {}

    // "ESDL": one letter per event.
    Path compact() {
        Path path;
        for (; pos_ < past_; ++pos_) {
            Event event;
            const char c = text_[pos_];
            if (eventType(c, event.type)) {
                // R and T alone carry no scattering.
            } else if (c != '_' && scatter(c, event.scatter)) {
                event.type = EventType::Reflection;
            } else {
                fail((isLetter(c) ? "unknown event letter " : "unexpected ") + shown(c) +
                     " in a path; expected one of E C D G S s L B R T");
            }
            path.push_back(event);
        }
        return path;
    }

    // "C TS RD'1' L'key'": type letter, optional scattering letter, optional quoted label; events
    // separated by whitespace. D, G, S or s alone stand for a reflection, as in the compact form.
    Path tuples() {
        Path path;
        while (pos_ < past_) {
            Event event;
            const char c = text_[pos_];
            if (eventType(c, event.type)) {
                ++pos_;
                if (pos_ < past_ && scatter(text_[pos_], event.scatter)) ++pos_;
            } else if (c != '_' && scatter(c, event.scatter)) {
                event.type = EventType::Reflection;
                ++pos_;
            } else {
                fail((isLetter(c) ? "unknown event type " : "unexpected ") + shown(c) +
                     " in a path; expected one of E C R T L B (or D G S s for a reflection)");
            }
            if (pos_ < past_ && text_[pos_] == '\'') event.label = label();
            if (pos_ < past_ && !isSpace(text_[pos_])) {
                fail("unexpected " + shown(text_[pos_]) +
                     " in a path; expected a space before the next event");
            }
            while (pos_ < past_ && isSpace(text_[pos_])) ++pos_;
            path.push_back(std::move(event));
        }
        return path;
    }

private:
    std::string label() {
        const std::size_t open = pos_;
        const std::size_t close = text_.find('\'', open + 1);
        if (close == std::string_view::npos || close >= past_)
            fail("unterminated label: expected a closing '");
        if (close == open + 1) fail("empty label '': a label needs at least one character");
        pos_ = close + 1;
        return std::string(text_.substr(open + 1, close - open - 1));
    }

    [[noreturn]] void fail(const std::string& message) const {
        throw SyntaxError(std::string(text_), pos_, message);
    }

    std::string_view text_;
    std::size_t pos_;
    std::size_t past_;
};

bool lossless(const Event& event) {
    if (!event.label.empty()) return false;
    switch (event.type) {
        case EventType::Reflection: return true;
        case EventType::Transmission: return event.scatter == Scatter::None;
        default: return event.scatter == Scatter::None;
    }
}

}  // namespace

// Leading and trailing whitespace is ignored; whitespace between events or a quote anywhere
// selects the tuple form.
Path parsePath(std::string_view text) {
    std::size_t first = 0, past = text.size();
    while (first < past && isSpace(text[first])) ++first;
    while (past > first && isSpace(text[past - 1])) --past;
    const std::string_view body = text.substr(first, past - first);
    const bool tuples = std::any_of(body.begin(), body.end(), [](char c) { return isSpace(c) || c == '\''; });
    PathParser parser(text, first, past);
    return tuples ? parser.tuples() : parser.compact();
}

std::string toCompactString(const Path& path) {
    std::string text;
    for (const Event& event : path) {
        const bool scatters = event.type == EventType::Reflection || event.type == EventType::Transmission;
        text += scatters && event.scatter != Scatter::None ? letter(event.scatter) : letter(event.type);
    }
    return text;
}

std::string toTupleString(const Path& path) {
    std::string text;
    for (const Event& event : path) {
        if (!text.empty()) text += ' ';
        text += letter(event.type);
        if (event.scatter != Scatter::None) text += letter(event.scatter);
        if (!event.label.empty()) text += "'" + event.label + "'";
    }
    return text;
}

std::string toDisplayString(const Path& path) {
    return std::all_of(path.begin(), path.end(), lossless) ? toCompactString(path) : toTupleString(path);
}

}  // namespace lpe
