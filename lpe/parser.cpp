// Recursive-descent parser for light path expressions (DESIGN.md, "The alphabet of light paths").
//
// Grammar (whitespace between tokens is ignored):
//   expression  := alternation
//   alternation := sequence ('|' sequence)*
//   sequence    := repetition+
//   repetition  := atom [ '*' | '+' | '?' | '{' n '}' | '{' n ',' '}' | '{' n ',' m '}' ]
//   atom        := '(' alternation ')' | event
//   event       := letter | '<' tuple '>' | '[' ['^'] member+ ']' | quoted-label
//   letter      := E | C | L | B | D | G | S | s | R | T | .
//   tuple       := type [scatter] label-position*    (missing positions mean '.')
//   member      := letter | '<' tuple '>' | quoted-label
//
// Decisions where regular-expression dialects differ, chosen so that every byte string either
// parses or gets a message that says what was expected:
// - An empty group `()`, an empty alternative (`|D`, `D|`, `(D|)`) and an empty expression are
//   errors: each side of `|` must name at least one event.
// - One quantifier per atom, as in ECMAScript (`D**` is "nothing to repeat"); ECMAScript's lazy
//   `*?` has no meaning for a language and is an error too. Write `(D*)?` to repeat a repetition.
// - `{n,m}` needs n <= m; counts above kMaxRepetition are refused with a LimitError.
// - `[]` and `[^]` are errors (an empty set is almost certainly a typo), as are nested sets.
// - Labels are quoted with ' and cannot contain it; an empty label '' is an error.
// - In a tuple, `L` means emitters only, as in OSL; a bare `L` also matches the background.
// - A tuple's label position also accepts a set of labels, `<RD['a' 'b']>` or `<RD[^'a']>`: an
//   extension of OSL's sets to the label position, which lets toDot print every edge faithfully.
#include <string>
#include <utility>

#include "lpe/error.h"
#include "lpe/syntax.h"

namespace lpe::syntax {
namespace {

constexpr const char* kExpectedEvent =
    "expected an event (E, L, D, G, S, s, R, T, B, ., <...>, [...], '...') or '('";

constexpr const char* kUnmatched = "unmatched ')': no group is open";

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }
bool isDigit(char c) { return c >= '0' && c <= '9'; }
bool isLetter(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }
bool isQuantifier(char c) { return c == '*' || c == '+' || c == '?' || c == '{'; }

std::string column(std::size_t position) { return std::to_string(position + 1); }

// A character as an error message shows it: 'X' when printable, otherwise its byte value.
std::string quoted(char c) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte > 0x20 && byte < 0x7f) return std::string("'") + c + "'";
    constexpr const char* kHex = "0123456789ABCDEF";
    return std::string("byte 0x") + kHex[byte >> 4] + kHex[byte & 0xf];
}

// The compact (Heckbert) letters, at the top level and inside sets.
bool compactPattern(char c, EventPattern& pattern) {
    pattern = EventPattern{};
    switch (c) {
        case 'E':
        case 'C': pattern.types = bit(EventType::Camera); return true;
        case 'L': pattern.types = bit(EventType::Emitter) | bit(EventType::Background); return true;
        case 'B': pattern.types = bit(EventType::Background); return true;
        case 'R': pattern.types = bit(EventType::Reflection); return true;
        case 'T': pattern.types = bit(EventType::Transmission); return true;
        case 'D': pattern.scatters = bit(Scatter::Diffuse); return true;
        case 'G': pattern.scatters = bit(Scatter::Glossy); return true;
        case 'S': pattern.scatters = bit(Scatter::Specular); return true;
        case 's': pattern.scatters = bit(Scatter::Straight); return true;
        case '.': return true;
        default: return false;
    }
}

// Letters of a tuple's type position; `L` is emitters only there, as in OSL.
bool tupleType(char c, TypeMask& mask) {
    switch (c) {
        case 'E':
        case 'C': mask = bit(EventType::Camera); return true;
        case 'R': mask = bit(EventType::Reflection); return true;
        case 'T': mask = bit(EventType::Transmission); return true;
        case 'L': mask = bit(EventType::Emitter); return true;
        case 'B': mask = bit(EventType::Background); return true;
        default: return false;
    }
}

bool tupleScatter(char c, ScatterMask& mask) {
    switch (c) {
        case 'D': mask = bit(Scatter::Diffuse); return true;
        case 'G': mask = bit(Scatter::Glossy); return true;
        case 'S': mask = bit(Scatter::Specular); return true;
        case 's': mask = bit(Scatter::Straight); return true;
        case '_': mask = bit(Scatter::None); return true;
        default: return false;
    }
}

std::unique_ptr<Node> leaf(EventSet events) {
    auto node = std::make_unique<Node>();
    node->kind = Node::Kind::Event;
    node->events = std::move(events);
    return node;
}

class Parser {
public:
    explicit Parser(std::string_view text) : text_(text) {}

    Expression parse() {
        Expression expression;
        expression.root = parseAlternation(0);
        skipSpace();
        // The alternation stops only at the end, at '|' (which it consumes) or at ')'.
        if (!atEnd()) fail(pos_, kUnmatched);
        expression.labels = std::move(labels_);
        return expression;
    }

private:
    std::unique_ptr<Node> parseAlternation(std::size_t depth) {
        std::vector<std::unique_ptr<Node>> alternatives;
        alternatives.push_back(parseSequence(depth));
        skipSpace();
        while (!atEnd() && peek() == '|') {
            ++pos_;
            alternatives.push_back(parseSequence(depth));
            skipSpace();
        }
        if (alternatives.size() == 1) return std::move(alternatives.front());
        auto node = std::make_unique<Node>();
        node->kind = Node::Kind::Alternate;
        node->children = std::move(alternatives);
        return node;
    }

    std::unique_ptr<Node> parseSequence(std::size_t depth) {
        std::vector<std::unique_ptr<Node>> items;
        for (;;) {
            skipSpace();
            if (atEnd() || peek() == '|' || peek() == ')') break;
            items.push_back(parseRepetition(depth));
        }
        if (items.empty() && depth == 0 && !atEnd() && peek() == ')') fail(pos_, kUnmatched);
        if (items.empty()) fail(pos_, kExpectedEvent);
        if (items.size() == 1) return std::move(items.front());
        auto node = std::make_unique<Node>();
        node->kind = Node::Kind::Concat;
        node->children = std::move(items);
        return node;
    }

    std::unique_ptr<Node> parseRepetition(std::size_t depth) {
        auto atom = parseAtom(depth);
        skipSpace();
        if (atEnd() || !isQuantifier(peek())) return atom;

        auto node = std::make_unique<Node>();
        node->kind = Node::Kind::Repeat;
        switch (peek()) {
            case '*': node->min = 0; node->max = kUnbounded; ++pos_; break;
            case '+': node->min = 1; node->max = kUnbounded; ++pos_; break;
            case '?': node->min = 0; node->max = 1; ++pos_; break;
            default: parseCount(*node); break;
        }
        node->children.push_back(std::move(atom));

        skipSpace();
        if (!atEnd() && isQuantifier(peek())) {
            fail(pos_, "nothing to repeat before '" + std::string(1, peek()) +
                           "' (to repeat a repetition, put it in parentheses)");
        }
        return node;
    }

    // {n}, {n,} or {n,m}; pos_ is at '{'.
    void parseCount(Node& node) {
        const std::size_t open = pos_++;
        skipSpace();
        const std::string min = parseNumber("expected a number after '{'");
        std::string max = min;
        skipSpace();
        bool bounded = true;
        if (!atEnd() && peek() == ',') {
            ++pos_;
            skipSpace();
            if (!atEnd() && isDigit(peek())) {
                max = parseNumber("");
            } else {
                bounded = false;
            }
            skipSpace();
        }
        if (atEnd() || peek() != '}') {
            fail(pos_, "expected '}' to close the repetition opened at column " + column(open));
        }
        ++pos_;

        // Compare the counts as written (leading zeros aside) so that huge numbers cannot overflow.
        const auto value = [](const std::string& digits) {
            const std::size_t first = digits.find_first_not_of('0');
            return first == std::string::npos ? std::string("0") : digits.substr(first);
        };
        const auto less = [&](const std::string& a, const std::string& b) {
            const std::string x = value(a), y = value(b);
            return x.size() != y.size() ? x.size() < y.size() : x < y;
        };
        const std::string limit = std::to_string(kMaxRepetition);
        if (bounded && less(max, min)) {
            fail(open, "repetition {" + min + "," + max + "}: minimum " + value(min) +
                           " is greater than maximum " + value(max));
        }
        for (const std::string& count : {min, max}) {
            if (less(limit, count)) {
                throw LimitError("LPE limit at column " + column(open) + ": repetition count " +
                                 value(count) + " is above the limit of " + limit);
            }
        }
        node.min = static_cast<std::uint32_t>(std::stoul(value(min)));
        node.max = bounded ? static_cast<std::uint32_t>(std::stoul(value(max))) : kUnbounded;
    }

    std::string parseNumber(const char* message) {
        if (atEnd() || !isDigit(peek())) fail(pos_, message);
        const std::size_t first = pos_;
        while (!atEnd() && isDigit(peek())) ++pos_;
        return std::string(text_.substr(first, pos_ - first));
    }

    std::unique_ptr<Node> parseAtom(std::size_t depth) {
        const char c = peek();
        if (c == '(') {
            const std::size_t open = pos_++;
            if (depth >= kMaxNesting) {
                throw LimitError("LPE limit at column " + column(open) + ": groups nested deeper than " +
                                 std::to_string(kMaxNesting));
            }
            auto inner = parseAlternation(depth + 1);
            skipSpace();
            if (atEnd() || peek() != ')') {
                fail(pos_, "expected ')' to close the group opened at column " + column(open));
            }
            ++pos_;
            return inner;
        }
        if (c == '[') return leaf(parseSet());
        if (isQuantifier(c)) fail(pos_, "nothing to repeat before '" + std::string(1, c) + "'");

        EventSet events;
        events.patterns.push_back(parseMember(kExpectedEvent));
        return leaf(std::move(events));
    }

    // A single event: compact letter, tuple or quoted label (the members a set may hold).
    EventPattern parseMember(const std::string& expected) {
        const char c = peek();
        if (c == '<') return parseTuple();
        if (c == '\'') {
            EventPattern pattern;
            pattern.labelTests.push_back(LabelTest{{parseLabel()}, false});
            return pattern;
        }
        EventPattern pattern;
        if (compactPattern(c, pattern)) {
            ++pos_;
            return pattern;
        }
        fail(pos_, (isLetter(c) ? "unknown event letter " : "unexpected ") + quoted(c) + "; " +
                       expected);
    }

    EventSet parseSet() {
        const std::size_t open = pos_++;
        EventSet set;
        if (!atEnd() && peek() == '^') {
            set.negated = true;
            ++pos_;
        }
        const std::string expected =
            "a set holds single events: E, L, D, G, S, s, R, T, B, ., <...> or '...'";
        for (;;) {
            skipSpace();
            if (atEnd()) fail(pos_, "expected ']' to close the set opened at column " + column(open));
            if (peek() == ']') break;
            set.patterns.push_back(parseMember(expected));
        }
        if (set.patterns.empty()) fail(pos_, "empty set: " + expected);
        ++pos_;
        return set;
    }

    EventPattern parseTuple() {
        const std::size_t open = pos_++;
        const std::string closeIt = "the tuple opened at column " + column(open);
        EventPattern pattern;

        // Position 1: event type.
        skipSpace();
        if (atEnd() || peek() == '>') {
            fail(pos_, "empty tuple: expected an event type (one of E C R T L B . [) in " + closeIt);
        }
        if (peek() == '[') {
            pattern.types = parseLetterSet(tupleType, "event letter", "E C R T L B");
        } else if (peek() == '.') {
            ++pos_;
        } else if (tupleType(peek(), pattern.types)) {
            ++pos_;
        } else {
            fail(pos_, (isLetter(peek()) ? "unknown event letter " : "unexpected ") + quoted(peek()) +
                           " in tuple type position; expected one of E C R T L B . [");
        }

        // Position 2: scattering, unless a label follows the type directly (`<L'key'>`).
        skipSpace();
        if (atEnd()) fail(pos_, "expected '>' to close " + closeIt);
        if (peek() == '[' && !startsLabelSet()) {
            pattern.scatters = parseLetterSet(tupleScatter, "scattering letter", "D G S s _");
        } else if (peek() == '.') {
            ++pos_;
        } else if (tupleScatter(peek(), pattern.scatters)) {
            ++pos_;
        } else if (peek() != '>' && peek() != '\'' && peek() != '[') {
            fail(pos_, (isLetter(peek()) ? "unknown scattering letter " : "unexpected ") + quoted(peek()) +
                           " in tuple scattering position; expected one of D G S s _ . [ or a "
                           "quoted label");
        }

        // Remaining positions: labels, label sets or '.'.
        for (;;) {
            skipSpace();
            if (atEnd()) fail(pos_, "expected '>' to close " + closeIt);
            const char c = peek();
            if (c == '>') break;
            if (c == '\'') {
                pattern.labelTests.push_back(LabelTest{{parseLabel()}, false});
            } else if (c == '[') {
                pattern.labelTests.push_back(parseLabelSet());
            } else if (c == '.') {
                ++pos_;
            } else {
                fail(pos_, "expected a quoted label or '>' to close " + closeIt);
            }
        }
        ++pos_;
        return pattern;
    }

    // Is the '[' at pos_ a set of labels (its first member is quoted)?
    bool startsLabelSet() const {
        std::size_t i = pos_ + 1;
        if (i < text_.size() && text_[i] == '^') ++i;
        while (i < text_.size() && isSpace(text_[i])) ++i;
        return i < text_.size() && text_[i] == '\'';
    }

    // [..] or [^..] of type or scattering letters inside a tuple; returns the mask it stands for.
    template <class Mask>
    Mask parseLetterSet(bool (*letterMask)(char, Mask&), const char* what, const char* letters) {
        const std::size_t open = pos_++;
        bool negated = false;
        if (!atEnd() && peek() == '^') {
            negated = true;
            ++pos_;
        }
        Mask mask = 0;
        bool empty = true;
        for (;;) {
            skipSpace();
            if (atEnd()) fail(pos_, "expected ']' to close the set opened at column " + column(open));
            if (peek() == ']') break;
            Mask one = 0;
            if (!letterMask(peek(), one)) {
                fail(pos_,
                     (isLetter(peek()) ? std::string("unknown ") + what + " " : std::string("unexpected ")) +
                         quoted(peek()) + " in a tuple set; expected one of " + letters);
            }
            mask = static_cast<Mask>(mask | one);
            empty = false;
            ++pos_;
        }
        if (empty) fail(pos_, std::string("empty set: expected one of ") + letters);
        ++pos_;
        constexpr Mask kAll = static_cast<Mask>((1u << 5) - 1);  // 5 types, 5 scatterings
        return negated ? static_cast<Mask>(kAll & ~mask) : mask;
    }

    LabelTest parseLabelSet() {
        const std::size_t open = pos_++;
        LabelTest test;
        if (!atEnd() && peek() == '^') {
            test.negated = true;
            ++pos_;
        }
        for (;;) {
            skipSpace();
            if (atEnd()) fail(pos_, "expected ']' to close the set opened at column " + column(open));
            if (peek() == ']') break;
            if (peek() != '\'') fail(pos_, "expected a quoted label in the label set");
            test.labels.push_back(parseLabel());
        }
        if (test.labels.empty()) fail(pos_, "empty set: expected a quoted label");
        ++pos_;
        return test;
    }

    // 'label'; pos_ is at the opening quote.
    std::string parseLabel() {
        const std::size_t open = pos_;
        const std::size_t close = text_.find('\'', open + 1);
        if (close == std::string_view::npos) fail(open, "unterminated label: expected a closing '");
        if (close == open + 1) fail(open, "empty label '': a label needs at least one character");
        std::string label(text_.substr(open + 1, close - open - 1));
        labels_.push_back(label);
        pos_ = close + 1;
        return label;
    }

    void skipSpace() {
        while (!atEnd() && isSpace(peek())) ++pos_;
    }
    bool atEnd() const { return pos_ >= text_.size(); }
    char peek() const { return text_[pos_]; }

    [[noreturn]] void fail(std::size_t position, const std::string& message) const {
        throw SyntaxError(std::string(text_), position, message);
    }

    std::string_view text_;
    std::size_t pos_ = 0;
    std::vector<std::string> labels_;
};

}  // namespace

Expression parseExpression(std::string_view text) {
    if (text.size() > kMaxExpressionLength) {
        throw LimitError("LPE limit: the expression is " + std::to_string(text.size()) +
                         " characters long; the limit is " + std::to_string(kMaxExpressionLength));
    }
    return Parser(text).parse();
}

}  // namespace lpe::syntax
