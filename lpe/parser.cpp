// Recursive-descent parser for light path expressions (docs/design.md, "The alphabet of light paths";
// docs/lpe.md for the differences from OSL's lpeparse.cpp).
//
// Grammar (whitespace between tokens is ignored):
//   expression  := alternation
//   alternation := sequence ('|' sequence)*
//   sequence    := repetition+
//   repetition  := atom [ '*' | '+' | '?' | '{' n '}' | '{' n ',' '}' | '{' n ',' m '}' ]
//   atom        := '(' alternation ')' | '[' alternation ']' | event
//   event       := letter | '<' tuple '>' | '[' ['^'] member+ ']' | quoted-label
//   letter      := E | C | L | B | O | V | D | G | S | s | R | T | .
//   tuple       := type [scatter] label-position*    (missing positions mean '.')
//   member      := letter | '<' tuple '>' | quoted-label
//
// Square brackets have two readings. Heckbert writes `[...]` for "optional" (`E[S*](D|G)L`), OSL
// for a set of events (`[SG]`). A bracket holding an operator, a group, a nested bracket or `|`
// is Heckbert's optional group; one holding single events only is OSL's set.
//
// Decisions where regular-expression dialects differ, chosen so that every byte string either
// parses or gets a message that says what was expected:
// - `|` binds loosest, as in regular expressions (OSL binds it tighter than concatenation;
//   Precedence::Osl reads it OSL's way, to explain the difference).
// - An empty group `()`, an empty alternative (`|D`, `D|`, `(D|)`) and an empty expression are
//   errors: each side of `|` must name at least one event.
// - One quantifier per atom, as in ECMAScript (`D**` is "nothing to repeat"); ECMAScript's lazy
//   `*?` has no meaning for a language and is an error too. Write `(D*)?` to repeat a repetition.
// - `{n,m}` needs n <= m; counts above kMaxRepetition are refused with a LimitError.
// - `[]` and `[^]` are errors (an empty set is almost certainly a typo), as are nested sets.
// - Labels are quoted with ' and cannot contain it; an empty label '' is an error.
// - A bare `L` is Heckbert's: every emitter, lights, emitting objects (O) and the background.
//   Inside OSL's constructs, a set `[LO]` or a tuple `<L>`, `L` is OSL's: lights only.
// - `x` (OSL's "no scattering", lightpath's `_`) is a tuple position only, as in OSL.
// - A tuple's label may follow the type directly, `<L'key'>` for OSL's `<L.'key'>`: OSL reads a
//   second position as a scattering and no event scatters by a name, so OSL's reading matches
//   nothing and the shorthand gives meaning only to expressions that would otherwise be dead.
// - A tuple's label position also accepts a set of labels, `<RD['a' 'b']>` or `<RD[^'a']>`: an
//   extension of OSL's sets to the label position, which lets toDot print every edge faithfully.
#include <string>
#include <utility>

#include "lpe/error.h"
#include "lpe/syntax.h"

namespace lpe::syntax {
namespace {

constexpr const char* kExpectedEvent =
    "expected an event (E, L, D, G, S, s, R, T, B, V, O, ., <...>, [...], '...') or '('";

constexpr const char* kUnmatched = "unmatched ')': no group is open";

constexpr const char* kBothBrackets =
    " ([ ] of single events is OSL's set, e.g. [SG]; [ ] holding an operator, a group or | is "
    "Heckbert's optional, e.g. [S*] = (S*)?)";

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

// The letters of event.h's table, spaced, for messages: "E C R T L B V O".
std::string spaced(const std::string& letters) {
    std::string out;
    for (const char c : letters) {
        if (!out.empty()) out.push_back(' ');
        out.push_back(c);
    }
    return out;
}
std::string typeLetters() {
    std::string letters(kEventTypeLetters.begin(), kEventTypeLetters.end());
    letters.insert(1, 1, kCameraAlias);
    return spaced(letters);
}
std::string scatterLetters() {
    std::string letters(kScatterLetters.begin(), kScatterLetters.end());
    letters.push_back(kNoScatterAlias);
    return spaced(letters);
}

// Where a compact letter stands: at the top level (Heckbert's reading) or in an OSL set.
enum class Context { TopLevel, InSet };

// The compact letters. A type letter matches every scattering, a scattering letter every type.
bool compactPattern(char c, Context context, EventPattern& pattern) {
    pattern = EventPattern{};
    if (c == '.') return true;
    if (c == kNoScatterAlias) return false;  // a tuple position only, as in OSL
    if (const auto type = eventTypeOf(c)) {
        pattern.types = bit(*type);
        // Heckbert's L is every emitter; OSL's, inside its sets, is lights only.
        if (*type == EventType::Emitter && context == Context::TopLevel)
            pattern.types = bit(EventType::Emitter) | bit(EventType::ObjectEmission) | bit(EventType::Background);
        return true;
    }
    if (const auto scatter = scatterOf(c); scatter && *scatter != Scatter::None) {
        pattern.scatters = bit(*scatter);
        return true;
    }
    return false;
}

// Letters of a tuple's type position; `L` is lights only there, as in OSL.
bool tupleType(char c, TypeMask& mask) {
    const auto type = eventTypeOf(c);
    if (type) mask = bit(*type);
    return type.has_value();
}

bool tupleScatter(char c, ScatterMask& mask) {
    const auto scatter = scatterOf(c);
    if (scatter) mask = bit(*scatter);
    return scatter.has_value();
}

std::unique_ptr<Node> leaf(EventSet events, std::size_t begin, std::size_t end) {
    auto node = std::make_unique<Node>();
    node->kind = Node::Kind::Event;
    node->events = std::move(events);
    node->begin = begin;
    node->end = end;
    return node;
}

class Parser {
public:
    Parser(std::string_view text, Precedence precedence) : text_(text), precedence_(precedence) {}

    Expression parse() {
        Expression expression;
        expression.root = parseAlternation(0);
        skipSpace();
        // The alternation stops only at the end, at '|' (which it consumes) or at ')'.
        if (!atEnd()) fail(pos_, kUnmatched);
        expression.labels = std::move(labels_);
        expression.heckbertBrackets = std::move(heckbert_);
        expression.shorthandDots = std::move(dots_);
        expression.singleMemberSets = std::move(singles_);
        expression.letterThenLabel = std::move(letterThen_);
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

    bool endsSequence() const {
        const char c = peek();
        if (c == ')' || (c == ']' && brackets_ > 0)) return true;
        return c == '|' && precedence_ == Precedence::Regex;
    }

    std::unique_ptr<Node> parseSequence(std::size_t depth) {
        std::vector<std::unique_ptr<Node>> items;
        for (;;) {
            skipSpace();
            if (atEnd() || endsSequence()) break;
            if (peek() == '|') {
                // OSL's precedence: `|` joins the item before it and the one after it.
                if (items.empty()) fail(pos_, kExpectedEvent);
                ++pos_;
                skipSpace();
                if (atEnd() || endsSequence() || peek() == '|') fail(pos_, kExpectedEvent);
                auto right = parseRepetition(depth);
                if (items.back()->kind != Node::Kind::Alternate) {
                    auto alternate = std::make_unique<Node>();
                    alternate->kind = Node::Kind::Alternate;
                    alternate->children.push_back(std::move(items.back()));
                    items.back() = std::move(alternate);
                }
                items.back()->children.push_back(std::move(right));
                continue;
            }
            items.push_back(parseRepetition(depth));
            noteLetterThenLabel(items);
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

    // `L'key'` is two events, L then any event labelled key: almost always meant as <L.'key'>.
    void noteLetterThenLabel(const std::vector<std::unique_ptr<Node>>& items) {
        if (items.size() < 2) return;
        const Node& label = *items.back();
        const Node& letter = *items[items.size() - 2];
        if (label.kind != Node::Kind::Event || letter.kind != Node::Kind::Event) return;
        if (text_[label.begin] != '\'' || letter.end != label.begin || letter.end - letter.begin != 1) return;
        const char c = text_[letter.begin];
        if (c != '.' && (eventTypeOf(c) || scatterOf(c))) letterThen_.push_back(letter.begin);
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

    void checkDepth(std::size_t open, std::size_t depth) const {
        if (depth >= kMaxNesting) {
            throw LimitError("LPE limit at column " + column(open) + ": groups nested deeper than " +
                             std::to_string(kMaxNesting));
        }
    }

    std::unique_ptr<Node> parseAtom(std::size_t depth) {
        const char c = peek();
        if (c == '(') {
            const std::size_t open = pos_++;
            checkDepth(open, depth);
            auto inner = parseAlternation(depth + 1);
            skipSpace();
            if (atEnd() || peek() != ')') {
                fail(pos_, "expected ')' to close the group opened at column " + column(open));
            }
            ++pos_;
            return inner;
        }
        if (c == '[' && isHeckbertBracket(pos_)) return parseOptional(depth);
        if (c == '[') {
            const std::size_t begin = pos_;
            EventSet set = parseSet();
            return leaf(std::move(set), begin, pos_);
        }
        if (isQuantifier(c)) fail(pos_, "nothing to repeat before '" + std::string(1, c) + "'");
        if (c == kNoScatterAlias) {
            fail(pos_, std::string("'") + kNoScatterAlias +
                           "' (no scattering) is a tuple position, as in OSL: write <L" + kNoScatterAlias +
                           "> or <." + kNoScatterAlias + ">");
        }

        const std::size_t begin = pos_;
        EventSet events;
        events.patterns.push_back(parseMember(kExpectedEvent, Context::TopLevel));
        return leaf(std::move(events), begin, pos_);
    }

    // Does the '[' at `open` hold more than single events (an operator, a group, a nested
    // bracket or '|')? Then it is Heckbert's optional group. Quoted labels and tuples are skipped
    // whole; a negated set `[^..]` is always a set.
    bool isHeckbertBracket(std::size_t open) const {
        std::size_t i = open + 1;
        if (i < text_.size() && text_[i] == '^') return false;
        for (; i < text_.size(); ++i) {
            const char c = text_[i];
            if (c == '\'' || c == '<') {
                const std::size_t close = text_.find(c == '\'' ? '\'' : '>', i + 1);
                if (close == std::string_view::npos) return false;
                i = close;
            } else if (c == ']') {
                return false;
            } else if (c == '[' || c == '(' || c == ')' || c == '|' || isQuantifier(c)) {
                return true;
            }
        }
        return false;
    }

    // Heckbert's [..]: the group, zero times or once.
    std::unique_ptr<Node> parseOptional(std::size_t depth) {
        const std::size_t open = pos_++;
        checkDepth(open, depth);
        ++brackets_;
        auto inner = parseAlternation(depth + 1);
        --brackets_;
        skipSpace();
        if (atEnd() || peek() != ']') {
            fail(pos_, "expected ']' to close the optional group opened at column " + column(open) + kBothBrackets);
        }
        ++pos_;
        heckbert_.push_back(open);
        auto node = std::make_unique<Node>();
        node->kind = Node::Kind::Repeat;
        node->min = 0;
        node->max = 1;
        node->children.push_back(std::move(inner));
        return node;
    }

    // A single event: compact letter, tuple or quoted label (the members a set may hold).
    EventPattern parseMember(const std::string& expected, Context context) {
        const char c = peek();
        if (c == '<') return parseTuple();
        if (c == '\'') {
            EventPattern pattern;
            pattern.labelTests.push_back(LabelTest{{parseLabel()}, false});
            return pattern;
        }
        EventPattern pattern;
        if (compactPattern(c, context, pattern)) {
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
            set.negated ? std::string("a negated set [^...] holds single events: E, L, D, G, S, s, R, T, B, V, O, "
                                      ".,  <...> or '...'; for Heckbert's optional write [...] without ^")
                        : std::string("a set holds single events: E, L, D, G, S, s, R, T, B, V, O, ., <...> or '...'");
        for (;;) {
            skipSpace();
            if (atEnd()) fail(pos_, "expected ']' to close the set opened at column " + column(open) + kBothBrackets);
            if (peek() == ']') break;
            set.patterns.push_back(parseMember(expected, Context::InSet));
        }
        if (set.patterns.empty()) fail(pos_, "empty set: " + expected);
        if (!set.negated && set.patterns.size() == 1) singles_.push_back(open);
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
            fail(pos_, "empty tuple: expected an event type (one of " + typeLetters() + " . [) in " + closeIt);
        }
        if (peek() == '[') {
            pattern.types = parseLetterSet<TypeMask>(tupleType, "event letter", typeLetters(), kAnyType);
        } else if (peek() == '.') {
            ++pos_;
        } else if (tupleType(peek(), pattern.types)) {
            ++pos_;
        } else {
            fail(pos_, (isLetter(peek()) ? "unknown event letter " : "unexpected ") + quoted(peek()) +
                           " in tuple type position; expected one of " + typeLetters() + " . [");
        }

        // Position 2: scattering, unless a label follows the type directly (`<L'key'>`, lightpath's
        // shorthand for OSL's `<L.'key'>`).
        skipSpace();
        if (atEnd()) fail(pos_, "expected '>' to close " + closeIt);
        if (peek() == '[' && !startsLabelSet()) {
            pattern.scatters = parseLetterSet<ScatterMask>(tupleScatter, "scattering letter", scatterLetters(), kAnyScatter);
        } else if (peek() == '.') {
            ++pos_;
        } else if (tupleScatter(peek(), pattern.scatters)) {
            ++pos_;
        } else if (peek() == '\'' || peek() == '[') {
            dots_.push_back(pos_);
        } else if (peek() != '>') {
            fail(pos_, (isLetter(peek()) ? "unknown scattering letter " : "unexpected ") + quoted(peek()) +
                           " in tuple scattering position; expected one of " + scatterLetters() +
                           " . [ or a quoted label");
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
    Mask parseLetterSet(bool (*letterMask)(char, Mask&), const char* what, const std::string& letters, Mask all) {
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
        if (empty) fail(pos_, "empty set: expected one of " + letters);
        ++pos_;
        return negated ? static_cast<Mask>(all & ~mask) : mask;
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
    Precedence precedence_;
    std::size_t pos_ = 0;
    std::size_t brackets_ = 0;  // Heckbert brackets open around pos_
    std::vector<std::string> labels_;
    std::vector<std::size_t> heckbert_, dots_, singles_, letterThen_;
};

// The text of a leaf, with the '.' the shorthand omits put back and whitespace dropped outside
// labels.
std::string leafText(const Node& node, std::string_view text, const std::vector<std::size_t>& dots) {
    std::string out;
    bool inLabel = false;
    for (std::size_t i = node.begin; i < node.end; ++i) {
        for (const std::size_t dot : dots)
            if (dot == i) out += '.';
        if (text[i] == '\'') inLabel = !inLabel;
        if (inLabel || !isSpace(text[i])) out += text[i];
    }
    return out;
}

std::string quantifier(const Node& node) {
    if (node.min == 0 && node.max == kUnbounded) return "*";
    if (node.min == 1 && node.max == kUnbounded) return "+";
    if (node.min == 0 && node.max == 1) return "?";
    std::string count = "{";
    count += std::to_string(node.min);
    if (node.max != node.min) count += ",";
    if (node.max != node.min && node.max != kUnbounded) count += std::to_string(node.max);
    count += "}";
    return count;
}

std::string parenthesised(const std::string& inner) {
    std::string out = "(";
    out += inner;
    out += ')';
    return out;
}

std::string print(const Node& node, std::string_view text, const std::vector<std::size_t>& dots) {
    switch (node.kind) {
        case Node::Kind::Event: return leafText(node, text, dots);
        case Node::Kind::Repeat: {
            const Node& child = *node.children.front();
            const std::string inner = print(child, text, dots);
            std::string out = child.kind == Node::Kind::Event ? inner : parenthesised(inner);
            out += quantifier(node);
            return out;
        }
        case Node::Kind::Concat: {
            std::string out;
            for (const auto& child : node.children) {
                const std::string inner = print(*child, text, dots);
                out += child->kind == Node::Kind::Alternate ? parenthesised(inner) : inner;
            }
            return out;
        }
        case Node::Kind::Alternate: {
            std::string out;
            for (const auto& child : node.children) {
                if (!out.empty()) out.push_back('|');
                out += print(*child, text, dots);
            }
            return out;
        }
    }
    return {};
}

}  // namespace

Expression parseExpression(std::string_view text, Precedence precedence) {
    if (text.size() > kMaxExpressionLength) {
        throw LimitError("LPE limit: the expression is " + std::to_string(text.size()) +
                         " characters long; the limit is " + std::to_string(kMaxExpressionLength));
    }
    return Parser(text, precedence).parse();
}

std::string printExpression(const Expression& expression, std::string_view text) {
    return print(*expression.root, text, expression.shorthandDots);
}

}  // namespace lpe::syntax
