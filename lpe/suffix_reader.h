#pragma once
// The automaton read backwards, from the end of a path: after the last events of a path have been
// read in reverse order, the states from which those events lead to a state accepting one of the
// chosen outputs (the reversed automaton, simulated on sets of the forward automaton's states, so
// nothing is built beyond one bitset per reading). A path's end that leaves no state reachable from
// the start can end no accepted path, whatever comes before it.
#include <cstdint>
#include <vector>

#include "lpe/automaton.h"

namespace lpe {

class SuffixReader {
public:
    // A set of states, one bit per state.
    using StateSet = std::vector<std::uint64_t>;

    SuffixReader(const Automaton& automaton, OutputMask outputs);

    // The empty suffix: the states that accept one of the outputs.
    const StateSet& accepting() const { return accepting_; }
    // `before` = the states from which `symbol`, then the suffix of `after`, leads to acceptance.
    void prepend(const StateSet& after, Automaton::Symbol symbol, StateSet& before) const;
    // Whether some path from the start reaches a state of `states`: whether any prefix can complete
    // the suffix into an accepted path.
    bool completable(const StateSet& states) const;

private:
    const Automaton& automaton_;
    StateSet accepting_, reachable_;
};

}  // namespace lpe
