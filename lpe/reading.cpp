#include "lpe/reading.h"

#include <algorithm>

#include "lpe/automaton.h"
#include "lpe/syntax.h"

namespace lpe {
namespace {

// Do two expressions accept different paths? Decided on one automaton holding both.
bool differ(const std::string& a, const std::string& b) {
    const Automaton automaton = Automaton::compile({{"a", a}, {"b", b}});
    return automaton.findShortestPath([](OutputMask m) { return m == 1 || m == 2; }).has_value();
}

// The first '[' .. matching ']' of a set of one event, as written.
std::string bracketText(std::string_view text, std::size_t open) {
    const std::size_t close = text.find(']', open);
    return std::string(text.substr(open, close == std::string_view::npos ? std::string_view::npos : close - open + 1));
}

}  // namespace

Reading readExpression(std::string_view text) {
    const syntax::Expression expression = syntax::parseExpression(text);
    Reading reading;
    reading.text = syntax::printExpression(expression, text);
    if (!expression.heckbertBrackets.empty())
        reading.notes.push_back("Heckbert: [ ] = optional");
    if (!expression.shorthandDots.empty())
        reading.notes.push_back("lightpath shorthand: <X'label'> = OSL's <X.'label'>");
    for (const std::size_t open : expression.singleMemberSets) {
        const std::string set = bracketText(text, open);
        const std::string inner = set.substr(1, set.size() - 2);
        reading.warnings.push_back(set + " is read as OSL's set (exactly one " + inner + "); Heckbert's optional " +
                                   inner + " is written (" + inner + ")?");
    }
    if (const auto osl = oslPrecedenceReading(text)) {
        reading.warnings.push_back("| binds loosest, as in regular expressions: read as " + reading.text +
                                   "; OSL binds | tighter and would read " + *osl +
                                   "; add parentheses to say which");
    }
    return reading;
}

std::optional<std::string> oslPrecedenceReading(std::string_view text) {
    if (std::find(text.begin(), text.end(), '|') == text.end()) return std::nullopt;
    const syntax::Expression ours = syntax::parseExpression(text);
    std::optional<syntax::Expression> theirs;
    try {
        theirs.emplace(syntax::parseExpression(text, syntax::Precedence::Osl));
    } catch (const std::exception&) {
        return std::nullopt;
    }
    const std::string read = syntax::printExpression(ours, text), osl = syntax::printExpression(*theirs, text);
    if (read == osl || !differ(read, osl)) return std::nullopt;
    return osl;
}

std::optional<std::string> labelledEventSpelling(std::string_view text) {
    const syntax::Expression expression = syntax::parseExpression(text);
    if (expression.letterThenLabel.empty()) return std::nullopt;
    std::string out;
    std::size_t copied = 0;
    for (const std::size_t at : expression.letterThenLabel) {
        const std::size_t close = text.find('\'', at + 2);
        const char c = text[at];
        out += text.substr(copied, at - copied);
        const std::string label(text.substr(at + 1, close - at));
        out += eventTypeOf(c) ? std::string("<") + c + "." + label + ">" : std::string("<.") + c + label + ">";
        copied = close + 1;
    }
    out += text.substr(copied);
    return out;
}

}  // namespace lpe
