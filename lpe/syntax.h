#pragma once
// The syntax tree of one light path expression (private to lpe/). The parser builds it; the
// compiler turns its leaves into sets of symbols and its inner nodes into a Thompson NFA.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "lpe/event.h"

namespace lpe::syntax {

// Limits that keep every input, however hostile, to bounded time and memory (LimitError).
inline constexpr std::size_t kMaxExpressionLength = 10000;  // characters per expression
inline constexpr std::uint32_t kMaxRepetition = 256;         // n and m in {n,m}
inline constexpr std::size_t kMaxNesting = 200;              // depth of ( ) groups
inline constexpr std::uint32_t kUnbounded = UINT32_MAX;      // m of {n,} and *

// Event types and scatterings as bit sets, bit i = enumerator i.
using TypeMask = std::uint8_t;
using ScatterMask = std::uint8_t;
inline constexpr TypeMask kAnyType = (1u << kEventTypeCount) - 1;
inline constexpr ScatterMask kAnyScatter = (1u << kScatterCount) - 1;
constexpr TypeMask bit(EventType type) { return static_cast<TypeMask>(1u << static_cast<int>(type)); }
constexpr ScatterMask bit(Scatter scatter) {
    return static_cast<ScatterMask>(1u << static_cast<int>(scatter));
}

// One label position of a tuple: the event's label must be one of `labels` (or, negated, none of
// them). An event has a single label, so a tuple with two different labels matches nothing.
struct LabelTest {
    std::vector<std::string> labels;
    bool negated = false;
};

// One event pattern, e.g. `D`, `<RS>`, `<L'key'>`, `'floor'`: type AND scattering AND labels.
struct EventPattern {
    TypeMask types = kAnyType;
    ScatterMask scatters = kAnyScatter;
    std::vector<LabelTest> labelTests;
};

// A leaf of the tree: the union of its patterns, or with `negated` every event outside it.
struct EventSet {
    std::vector<EventPattern> patterns;
    bool negated = false;
};

struct Node {
    enum class Kind { Event, Concat, Alternate, Repeat };

    Kind kind = Kind::Event;
    EventSet events;                             // Event
    std::vector<std::unique_ptr<Node>> children; // Concat, Alternate (2 or more), Repeat (1)
    std::uint32_t min = 0, max = 0;              // Repeat: {min,max}, max may be kUnbounded
    std::size_t begin = 0, end = 0;              // Event: where its text is, [begin, end)
};

struct Expression {
    std::unique_ptr<Node> root;
    std::vector<std::string> labels;  // every label named, in order of appearance (may repeat)
    // How the text was read where lightpath's reading is not OSL's spelling:
    std::vector<std::size_t> heckbertBrackets;  // '[' read as Heckbert's optional group
    std::vector<std::size_t> shorthandDots;     // where <L'key'> omits the '.' of <L.'key'>
    std::vector<std::size_t> singleMemberSets;  // '[' of a set of one event, e.g. [S]
    std::vector<std::size_t> letterThenLabel;   // a letter followed at once by a label: L'key'
};

// Where `|` binds: loosest, as in regular expressions (lightpath), or tighter than concatenation,
// as OSL's lpeparse.cpp binds it (`AB|CD` is `A(B|C)D` there). OSL's is read only to explain.
enum class Precedence { Regex, Osl };

// Throws SyntaxError for malformed text and LimitError beyond the limits above.
Expression parseExpression(std::string_view text, Precedence precedence = Precedence::Regex);

// The expression as read, in OSL's spelling: Heckbert's [..] as (..)?, <L'key'> as <L.'key'>,
// groups made explicit; whitespace between events dropped. Parses to the same language.
std::string printExpression(const Expression& expression, std::string_view text);

}  // namespace lpe::syntax
