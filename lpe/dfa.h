#pragma once
// A complete deterministic automaton over compressed letters (private to lpe/): the intermediate
// form between subset construction, minimisation and the dense symbol table of Automaton.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "lpe/automaton.h"
#include "lpe/nfa.h"

namespace lpe::detail {

struct Dfa {
    std::size_t letterCount = 0;
    std::vector<std::uint32_t> next;   // state * letterCount + letter -> state
    std::vector<OutputMask> accepts;   // per state: bit i when NFA output i accepts there
    std::uint32_t start = 0;

    std::size_t stateCount() const { return accepts.size(); }
    std::uint32_t step(std::uint32_t state, std::uint32_t letter) const {
        return next[state * letterCount + letter];
    }
};

// Subset construction (Rabin and Scott 1959) of the whole NFA: every output at once. Throws
// LimitError when more than `maxStates` states would be needed.
Dfa determinise(const Nfa& nfa, const Letters& letters, std::size_t maxStates);

// Hopcroft's minimisation (Hopcroft 1971): the coarsest partition of the states that respects
// the accept masks and the transitions; returns the quotient automaton.
Dfa minimise(const Dfa& dfa);

}  // namespace lpe::detail
