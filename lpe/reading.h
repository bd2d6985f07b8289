#pragma once
// How lightpath reads an expression, said back to its writer: where Heckbert's notation, OSL's and
// lightpath's shorthand meet, the reading used and the spellings another dialect reads otherwise.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lpe {

struct Reading {
    std::string text;                   // the expression as read, in OSL's spelling
    std::vector<std::string> notes;     // why `text` differs from what was written, if it does
    std::vector<std::string> warnings;  // spellings other dialects read differently: both readings
};

// Throws SyntaxError or LimitError for an expression that does not parse.
Reading readExpression(std::string_view expression);

// The expression with `|` bound as OSL binds it (tighter than concatenation), when that reading
// accepts other paths than lightpath's; nothing otherwise or when it does not parse OSL's way.
std::optional<std::string> oslPrecedenceReading(std::string_view expression);

// Every letter followed at once by a label (`L'key'`: L, then any event labelled key) rewritten
// as the one event it almost always means (`<L.'key'>`, `<.D'floor'>`); nothing when there is none.
std::optional<std::string> labelledEventSpelling(std::string_view expression);

}  // namespace lpe
