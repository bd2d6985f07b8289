#pragma once
// Thompson's construction (Thompson 1968): a syntax tree becomes a nondeterministic automaton with
// epsilon moves, linear in the size of the tree. Several expressions share one NFA, each with its
// own start and accepting state, so that one subset construction serves every output.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "lpe/alphabet.h"
#include "lpe/syntax.h"

namespace lpe::detail {

inline constexpr std::uint32_t kNone = UINT32_MAX;

// Bounds the work of every later stage: the NFA has at most a few states per expanded node.
inline constexpr std::size_t kMaxExpandedNodes = 100000;

struct NfaState {
    std::vector<std::uint32_t> epsilon;  // moves that read nothing
    std::uint32_t predicate = kNone;     // index into Nfa::predicates: the one symbol edge, if any
    std::uint32_t target = kNone;        // where that edge leads
    std::uint32_t output = kNone;        // the output this state accepts, if any
};

struct Nfa {
    std::vector<NfaState> states;
    std::vector<std::uint32_t> starts;   // one per output
    std::vector<SymbolSet> predicates;   // the distinct symbol sets found on edges
};

// A set of NFA states, sorted so that equal sets compare equal: a state of subset construction.
using StateSet = std::vector<std::uint32_t>;

struct StateSetHash {
    std::size_t operator()(const StateSet& set) const {
        std::size_t hash = 1469598103934665603ull;  // FNV-1a over the state numbers
        for (const std::uint32_t s : set) hash = (hash ^ s) * 1099511628211ull;
        return hash;
    }
};

// The front of the compiler, shared by Automaton::compile and commonPath: each text parsed (labels
// get their classes in order of first appearance), one Thompson NFA with an output per text in
// order, and its compressed alphabet. Throws SyntaxError or LimitError.
struct TextsAsNfa {
    Alphabet alphabet;
    Nfa nfa;
    Letters letters;
};
TextsAsNfa buildNfaOfTexts(const std::vector<std::string>& texts);

// Epsilon closures in one NFA, for subset construction (Rabin and Scott 1959), which takes one per
// step: the marks and buffers are kept from call to call.
class EpsilonClosure {
public:
    explicit EpsilonClosure(const Nfa& nfa) : nfa_(nfa), seen_(nfa.states.size(), 0) {}
    // The states `seeds` reach by epsilon moves, themselves included; valid until the next call.
    const StateSet& operator()(const StateSet& seeds);

private:
    const Nfa& nfa_;
    std::vector<std::uint32_t> seen_;  // == generation_: already in this closure
    std::uint32_t generation_ = 0;
    StateSet stack_, closure_;
};

// The size of a tree once every {n,m} is written out, saturating just above `cap`.
std::size_t expandedSize(const syntax::Node& node, std::size_t cap);

// One output per root, in order. Throws LimitError when the expanded trees are too large.
Nfa buildNfa(const std::vector<const syntax::Node*>& roots, const Alphabet& alphabet);

}  // namespace lpe::detail
