#pragma once
// The symbols an automaton reads (private to lpe/). A symbol is one (event type, scattering,
// label class) triple, numbered as Automaton::symbol numbers it; every leaf of an expression
// stands for a set of symbols.
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "lpe/event.h"
#include "lpe/syntax.h"

namespace lpe::detail {

using SymbolSet = std::vector<bool>;  // indexed by symbol

class Alphabet {
public:
    // `labels` in order of first appearance, duplicates allowed; class i+1 is the i-th distinct one.
    explicit Alphabet(const std::vector<std::string>& labels);

    std::size_t classCount() const { return labels_.size() + 1; }
    std::size_t symbolCount() const { return classCount() * kEventTypeCount * kScatterCount; }
    const std::vector<std::string>& labels() const { return labels_; }
    std::uint32_t labelClass(std::string_view label) const;

    // The symbols a leaf of the syntax tree matches.
    SymbolSet symbols(const syntax::EventSet& events) const;

    // The scattering a pattern tests: None for the camera, emitters and background.
    static Scatter effectiveScatter(int type, int scatter);

private:
    // The label classes a pattern's label positions let through.
    std::vector<bool> allowedClasses(const syntax::EventPattern& pattern) const;

    std::vector<std::string> labels_;
    std::map<std::string, std::uint32_t, std::less<>> classes_;
};

// The formula of Automaton::symbol.
constexpr std::uint32_t symbolOf(int type, int scatter, std::uint32_t labelClass) {
    return (labelClass * kScatterCount + static_cast<std::uint32_t>(scatter)) * kEventTypeCount +
           static_cast<std::uint32_t>(type);
}

// The inverse of symbolOf: the event symbol `symbol` stands for, its label class named by `labels`
// (class i+1 is labels[i]; class 0 has no label).
Event eventOfSymbol(std::uint32_t symbol, const std::vector<std::string>& labels);

// Every symbol, in the order in which examples should use them: unlabelled before labelled, then
// reflections D G S s, refractions S D G s, camera, emitter, background, then the combinations no
// renderer produces. Shortest-path searches try symbols in this order, so "ESDL" wins over "EDSL"
// and a free position reads D, not E.
std::vector<std::uint32_t> preferenceOrder(std::size_t classCount);

// Alphabet compression (the "character classes" of lex and RE2): symbols that every predicate
// treats alike are one letter, so subset construction and minimisation loop over letters, not
// over every label of every event.
struct Letters {
    std::size_t count = 0;
    std::vector<std::uint32_t> ofSymbol;  // symbol -> letter
    std::vector<std::uint8_t> inPredicate;  // predicate * count + letter -> 0/1
};
Letters compressAlphabet(const std::vector<SymbolSet>& predicates, std::size_t symbolCount);

}  // namespace lpe::detail
