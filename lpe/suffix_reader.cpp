#include "lpe/suffix_reader.h"

namespace lpe {
namespace {

std::size_t words(std::size_t states) { return (states + 63) / 64; }
bool has(const SuffixReader::StateSet& set, std::size_t s) { return (set[s / 64] >> (s % 64)) & 1u; }
void add(SuffixReader::StateSet& set, std::size_t s) { set[s / 64] |= std::uint64_t{1} << (s % 64); }

}  // namespace

SuffixReader::SuffixReader(const Automaton& automaton, OutputMask outputs)
    : automaton_(automaton), accepting_(words(automaton.stateCount()), 0), reachable_(words(automaton.stateCount()), 0) {
    for (std::size_t s = 0; s < automaton.stateCount(); ++s)
        if ((automaton.accepts(Automaton::State(s)) & outputs) != 0) add(accepting_, s);
    // The states reachable from the start, by a search over every symbol.
    std::vector<Automaton::State> frontier{automaton.start()};
    add(reachable_, automaton.start());
    while (!frontier.empty()) {
        const Automaton::State state = frontier.back();
        frontier.pop_back();
        for (Automaton::Symbol symbol = 0; symbol < automaton.symbolCount(); ++symbol) {
            const Automaton::State next = automaton.step(state, symbol);
            if (!has(reachable_, next)) {
                add(reachable_, next);
                frontier.push_back(next);
            }
        }
    }
}

void SuffixReader::prepend(const StateSet& after, Automaton::Symbol symbol, StateSet& before) const {
    before.assign(after.size(), 0);
    for (std::size_t s = 0; s < automaton_.stateCount(); ++s)
        if (has(after, automaton_.step(Automaton::State(s), symbol))) add(before, s);
}

bool SuffixReader::completable(const StateSet& states) const {
    for (std::size_t w = 0; w < states.size(); ++w)
        if ((states[w] & reachable_[w]) != 0) return true;
    return false;
}

}  // namespace lpe
