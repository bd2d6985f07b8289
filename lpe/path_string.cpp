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

// Letters of event.h's table: E/C R T L B V O, D G S s _ (and x).
bool eventType(char c, EventType& type) {
    const auto found = eventTypeOf(c);
    if (found) type = *found;
    return found.has_value();
}

bool scatter(char c, Scatter& scatter) {
    const auto found = scatterOf(c);
    if (found) scatter = *found;
    return found.has_value();
}

bool noScatter(char c) { return c == letter(Scatter::None) || c == kNoScatterAlias; }

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
                // R, T and V alone carry no scattering.
            } else if (!noScatter(c) && scatter(c, event.scatter)) {
                event.type = EventType::Reflection;
            } else {
                fail((isLetter(c) ? "unknown event letter " : "unexpected ") + shown(c) +
                     " in a path; expected one of E C D G S s L B O R T V");
            }
            path.push_back(event);
        }
        return path;
    }

    // "C TS RD'1' L'key'" or "E <TS> <RD'1'> <L.'key'>": type letter, optional scattering letter, optional quoted label; events
    // separated by whitespace. D, G, S or s alone stand for a reflection, as in the compact form.
    Path tuples() {
        Path path;
        while (pos_ < past_) {
            Event event;
            // toExpressionString's form: the same tuple in angle brackets, '.' before a label.
            const bool bracketed = text_[pos_] == '<';
            if (bracketed) ++pos_;
            const char c = pos_ < past_ ? text_[pos_] : ' ';
            if (eventType(c, event.type)) {
                ++pos_;
                if (pos_ < past_ && scatter(text_[pos_], event.scatter)) ++pos_;
                else if (bracketed && pos_ < past_ && text_[pos_] == '.') ++pos_;
            } else if (!noScatter(c) && scatter(c, event.scatter)) {
                event.type = EventType::Reflection;
                ++pos_;
            } else {
                fail((isLetter(c) ? "unknown event type " : "unexpected ") + shown(c) +
                     " in a path; expected one of E C R T L B O V (or D G S s for a reflection)");
            }
            if (pos_ < past_ && text_[pos_] == '\'') event.label = label();
            if (bracketed) {
                if (pos_ >= past_ || text_[pos_] != '>') fail("expected '>' to close the event");
                ++pos_;
            }
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
    return event.type == EventType::Reflection || event.scatter == Scatter::None;
}

}  // namespace

// Leading and trailing whitespace is ignored; whitespace between events or a quote anywhere
// selects the tuple form.
Path parsePath(std::string_view text) {
    std::size_t first = 0, past = text.size();
    while (first < past && isSpace(text[first])) ++first;
    while (past > first && isSpace(text[past - 1])) --past;
    const std::string_view body = text.substr(first, past - first);
    const bool tuples =
        std::any_of(body.begin(), body.end(), [](char c) { return isSpace(c) || c == '\'' || c == '<'; });
    PathParser parser(text, first, past);
    return tuples ? parser.tuples() : parser.compact();
}

std::string toCompactString(const Path& path) {
    std::string text;
    for (const Event& event : path) {
        text += scatters(event.type) && event.scatter != Scatter::None ? letter(event.scatter) : letter(event.type);
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

std::string toExpressionString(const Path& path) {
    std::string text;
    for (const Event& event : path) {
        if (!text.empty()) text += ' ';
        const std::string label = event.label.empty() ? "" : "'" + event.label + "'";
        // A camera, light, object emission or background matches whatever scattering it claims
        // (Automaton::symbol), so none is printed: a renderer records None there.
        if (scatters(event.type)) {
            text += std::string("<") + letter(event.type) + letter(event.scatter) + label + ">";
        } else if (!label.empty()) {
            text += std::string("<") + letter(event.type) + "." + label + ">";
        } else if (event.type == EventType::Emitter) {
            text += "<L>";  // a bare L would match every emitter and the background
        } else {
            text += letter(event.type);
        }
    }
    return text;
}

std::string toDisplayString(const Path& path) {
    return std::all_of(path.begin(), path.end(), lossless) ? toCompactString(path) : toTupleString(path);
}

}  // namespace lpe
