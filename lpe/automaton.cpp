// Running a compiled automaton: label classes, whole paths, shortest examples.
#include "lpe/automaton.h"

#include <deque>

#include "lpe/alphabet.h"

namespace lpe {

Automaton::LabelClass Automaton::labelClass(std::string_view label) const {
    const auto found = labelClasses_.find(label);
    return found == labelClasses_.end() ? 0 : found->second;
}

OutputMask Automaton::run(const Path& path) const {
    State state = start_;
    for (const Event& event : path) state = step(state, symbol(event));
    return accepts(state);
}

OutputMask Automaton::allOutputs() const {
    return outputCount() >= kMaxOutputs ? ~OutputMask{0} : (OutputMask{1} << outputCount()) - 1;
}

Event Automaton::eventOf(Symbol symbol) const { return detail::eventOfSymbol(symbol, labels_); }

// Breadth-first search, trying symbols in the preferred order: the first path found to a state is
// a shortest one, and among those the one whose events come first in that order.
std::optional<Path> Automaton::shortestPathImpl(const std::vector<bool>& goal, const std::vector<bool>* allowed) const {
    constexpr State kUnvisited = UINT32_MAX;
    std::vector<State> parent(stateCount(), kUnvisited);
    std::vector<Symbol> via(stateCount(), 0);
    std::deque<State> queue{start_};
    parent[start_] = start_;
    while (!queue.empty()) {
        const State state = queue.front();
        queue.pop_front();
        if (goal[state]) {
            Path path;
            for (State s = state; s != start_; s = parent[s]) path.push_back(eventOf(via[s]));
            return Path(path.rbegin(), path.rend());
        }
        for (const Symbol symbol : preferred_) {
            if (allowed && !(*allowed)[symbol]) continue;
            const State next = step(state, symbol);
            // A dead state leads nowhere else; it is entered only when it is itself a goal.
            if (parent[next] != kUnvisited || (canAccept_[next] == 0 && !goal[next])) continue;
            parent[next] = state;
            via[next] = symbol;
            queue.push_back(next);
        }
    }
    return std::nullopt;
}

}  // namespace lpe
