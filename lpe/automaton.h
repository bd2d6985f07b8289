#pragma once
// A set of named light path expressions compiled into one deterministic, minimised automaton
// over events (the approach of OSL's lpexp/automata/accum split). Each state carries the set of
// outputs that accept there; stepping an event is one table lookup.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "lpe/event.h"

namespace lpe {

struct NamedExpression {
    std::string name;
    std::string expression;
};

// Bit i is output i. At most kMaxOutputs outputs per automaton.
using OutputMask = std::uint64_t;
inline constexpr std::size_t kMaxOutputs = 64;

struct CompileOptions {
    // When non-empty, one extra output of this name is appended after the named ones: it accepts
    // the paths of `universe` that no named expression accepts (the `rest` AOV, docs/design.md).
    std::string complementName;
    std::string universe = "E.*L";
    // Guards against exponential subset construction (states counted before minimisation);
    // exceeding it throws LimitError.
    std::size_t maxStates = 100000;
};

class Automaton {
public:
    using State = std::uint32_t;
    using Symbol = std::uint32_t;
    // A label class: 0 is every label that no expression names (and "no label"); 1..n are the
    // labels the expressions name. An automaton compiled once therefore works for any scene.
    using LabelClass = std::uint32_t;

    // Parses and compiles; throws SyntaxError (with the offending expression) or LimitError.
    static Automaton compile(const std::vector<NamedExpression>& expressions,
                             const CompileOptions& options = {});

    State start() const { return start_; }
    State step(State state, Symbol symbol) const { return table_[state * symbolCount_ + symbol]; }
    OutputMask accepts(State state) const { return accepts_[state]; }
    // True when no state reachable from `state` accepts any output in `outputs`: a tracer branch
    // in this state can stop, it can never contribute to those outputs.
    bool isDead(State state, OutputMask outputs) const { return (canAccept_[state] & outputs) == 0; }

    LabelClass labelClass(std::string_view label) const;
    // Camera, emitter and background events do not scatter: whatever their `scatter`, they are
    // matched as if it were Scatter::None (so `D` never matches an emitter).
    Symbol symbol(EventType type, Scatter scatter, LabelClass label) const {
        return (label * kScatterCount + static_cast<Symbol>(scatter)) * kEventTypeCount +
               static_cast<Symbol>(type);
    }
    Symbol symbol(const Event& event) const {
        return symbol(event.type, event.scatter, labelClass(event.label));
    }

    // Runs a whole path from the start state; the outputs accepting at its end.
    OutputMask run(const Path& path) const;
    bool matches(const Path& path, std::size_t output) const { return (run(path) >> output) & 1u; }

    std::size_t stateCount() const { return accepts_.size(); }
    std::size_t symbolCount() const { return symbolCount_; }
    std::size_t outputCount() const { return outputNames_.size(); }
    const std::string& outputName(std::size_t output) const { return outputNames_[output]; }
    const std::vector<std::string>& labels() const { return labels_; }  // class i+1 is labels_[i]
    OutputMask allOutputs() const;

    // Shortest path (fewest events) from the start to a state where `predicate(acceptMask)` is
    // true; empty when there is none. Among shortest paths, prefers unlabelled reflection events
    // in the order D, G, S, s so examples read naturally ("ESDL").
    template <class Predicate>
    Path shortestPath(Predicate predicate) const;
    // The same search, but tells "no such path" (nullopt) from "the empty path" (start state).
    template <class Predicate>
    std::optional<Path> findShortestPath(Predicate predicate) const;
    // The same search through the symbols `allowed` lets through only (indexed by symbol).
    template <class Predicate>
    std::optional<Path> findShortestPath(Predicate predicate, const std::vector<bool>& allowed) const;

    // Graphviz DOT: states as circles (accepting ones double, labelled with their outputs), edges
    // labelled with the events that take them, in LPE syntax. The dead state is left out.
    std::string toDot(std::string_view title = {}) const;

    // A representative event for a symbol (label class 0 prints as no label).
    Event eventOf(Symbol symbol) const;

private:
    std::optional<Path> shortestPathImpl(const std::vector<bool>& goal, const std::vector<bool>* allowed) const;

    State start_ = 0;
    std::size_t symbolCount_ = 0;
    std::vector<State> table_;          // stateCount x symbolCount
    std::vector<OutputMask> accepts_;   // per state
    std::vector<OutputMask> canAccept_; // per state: outputs accepting in some reachable state
    std::vector<std::string> outputNames_;
    std::vector<std::string> labels_;
    std::map<std::string, LabelClass, std::less<>> labelClasses_;
    std::vector<Symbol> preferred_;     // every symbol, in the order shortest paths prefer them
};

template <class Predicate>
std::optional<Path> Automaton::findShortestPath(Predicate predicate) const {
    std::vector<bool> goal(stateCount());
    for (std::size_t s = 0; s < goal.size(); ++s) goal[s] = predicate(accepts_[s]);
    return shortestPathImpl(goal, nullptr);
}

template <class Predicate>
std::optional<Path> Automaton::findShortestPath(Predicate predicate, const std::vector<bool>& allowed) const {
    std::vector<bool> goal(stateCount());
    for (std::size_t s = 0; s < goal.size(); ++s) goal[s] = predicate(accepts_[s]);
    return shortestPathImpl(goal, &allowed);
}

template <class Predicate>
Path Automaton::shortestPath(Predicate predicate) const {
    return findShortestPath(predicate).value_or(Path{});
}

}  // namespace lpe
