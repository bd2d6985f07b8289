// commonPath: a shortest path that every expression accepts, found without compiling them.
// Automaton::compile determinises and minimises the whole product of the expressions, every state
// of it; deciding that the languages meet needs only the states a breadth-first search visits
// before it reaches one accepting all of them. So subsets of the Thompson NFA are built on the fly
// (subset construction, Rabin and Scott 1959, done lazily as in RE2 and grep), and a subset from
// which some expression can no longer accept is dropped at once: the judge asks this question many
// times per render, mostly of expressions that do meet, near the start.
//
// The answer is the one the compiled automaton's shortest-path search gives: breadth-first, trying
// symbols in the same preferred order, finds the shortest path that comes first in that order, and
// neither minimisation nor dropping subsets that cannot accept changes which path that is.
#include <algorithm>
#include <deque>
#include <string>
#include <unordered_map>

#include "lpe/alphabet.h"
#include "lpe/analysis.h"
#include "lpe/error.h"
#include "lpe/nfa.h"
#include "lpe/syntax.h"

namespace lpe {
namespace {

using detail::kNone;
using detail::StateSet;
using detail::StateSetHash;

// Per NFA state, the outputs whose accepting state can still be reached from it: a backward
// search over epsilon and symbol moves from each accepting state.
std::vector<OutputMask> outputsReachable(const detail::Nfa& nfa) {
    // Predecessor lists in one array (compressed rows): first[t] .. first[t + 1] in `from`.
    const std::size_t n = nfa.states.size();
    std::vector<std::uint32_t> first(n + 1, 0), from;
    const auto forEachMove = [&nfa](auto&& visit) {
        for (std::uint32_t s = 0; s < nfa.states.size(); ++s) {
            for (const std::uint32_t t : nfa.states[s].epsilon) visit(s, t);
            if (nfa.states[s].target != kNone) visit(s, nfa.states[s].target);
        }
    };
    forEachMove([&](std::uint32_t, std::uint32_t t) { ++first[t + 1]; });
    for (std::size_t t = 0; t < n; ++t) first[t + 1] += first[t];
    from.resize(first[n]);
    std::vector<std::uint32_t> filled(first.begin(), first.end() - 1);
    forEachMove([&](std::uint32_t s, std::uint32_t t) { from[filled[t]++] = s; });

    std::vector<OutputMask> reachable(n, 0);
    std::vector<std::uint32_t> work;
    for (std::uint32_t s = 0; s < n; ++s) {
        if (nfa.states[s].output == kNone) continue;
        reachable[s] |= OutputMask{1} << nfa.states[s].output;
        work.push_back(s);
    }
    while (!work.empty()) {
        const std::uint32_t t = work.back();
        work.pop_back();
        for (std::uint32_t i = first[t]; i < first[t + 1]; ++i) {
            const std::uint32_t s = from[i];
            if ((reachable[s] | reachable[t]) == reachable[s]) continue;
            reachable[s] |= reachable[t];
            work.push_back(s);
        }
    }
    return reachable;
}

class LazySubsets {
public:
    static constexpr std::uint32_t kDropped = UINT32_MAX;

    LazySubsets(const detail::Nfa& nfa, const detail::Letters& letters, OutputMask all, std::size_t maxStates)
        : nfa_(nfa), letters_(letters), all_(all), maxStates_(maxStates), reachable_(outputsReachable(nfa)),
          closure_(nfa) {}

    std::uint32_t start() { return intern(closure_(nfa_.starts)); }
    bool acceptsAll(std::uint32_t id) const { return accepts_[id] == all_; }

    // The subset reached from `id` by `letter`; kDropped when some output can no longer accept.
    std::uint32_t step(std::uint32_t id, std::uint32_t letter) {
        moved_.clear();
        for (const std::uint32_t s : sets_[id]) {
            const detail::NfaState& state = nfa_.states[s];
            if (state.predicate != kNone && letters_.inPredicate[state.predicate * letters_.count + letter])
                moved_.push_back(state.target);
        }
        return intern(closure_(moved_));
    }

private:
    // The id of `set`, numbered on first sight.
    std::uint32_t intern(const StateSet& set) {
        OutputMask reachable = 0, accepts = 0;
        for (const std::uint32_t s : set) {
            reachable |= reachable_[s];
            if (nfa_.states[s].output != kNone) accepts |= OutputMask{1} << nfa_.states[s].output;
        }
        if (reachable != all_) return kDropped;
        const auto found = ids_.find(set);
        if (found != ids_.end()) return found->second;
        if (sets_.size() >= maxStates_) {
            throw LimitError("LPE limit: the search for a common path needs more than " + std::to_string(maxStates_) +
                             " states (CompileOptions::maxStates); simplify the expressions");
        }
        const auto id = static_cast<std::uint32_t>(sets_.size());
        ids_.emplace(set, id);
        sets_.push_back(set);
        accepts_.push_back(accepts);
        return id;
    }

    const detail::Nfa& nfa_;
    const detail::Letters& letters_;
    OutputMask all_;
    std::size_t maxStates_;
    std::vector<OutputMask> reachable_;
    detail::EpsilonClosure closure_;
    StateSet moved_;  // kept between steps: allocation would dominate them
    std::vector<StateSet> sets_;
    std::vector<OutputMask> accepts_;
    std::unordered_map<StateSet, std::uint32_t, StateSetHash> ids_;
};

// The letters in the order breadth-first search tries them, each with the first symbol (in the
// preferred order) that stands for it and that `placement` allows: all symbols but those of a
// placed label on event types it does not list. Symbols of one letter step to the same subset, so
// only that first one can discover it.
std::vector<std::pair<std::uint32_t, std::uint32_t>> lettersToTry(const detail::Alphabet& alphabet,
                                                                  const detail::Letters& letters,
                                                                  const LabelPlacement& placement) {
    std::vector<std::uint32_t> placedTypes(alphabet.classCount(), ~0u);  // per class, a bit per EventType
    for (std::uint32_t c = 1; c < alphabet.classCount(); ++c) {
        const auto placed = placement.find(alphabet.labels()[c - 1]);
        if (placed == placement.end()) continue;
        placedTypes[c] = 0;
        for (const EventType type : placed->second) placedTypes[c] |= 1u << static_cast<int>(type);
    }
    std::vector<std::pair<std::uint32_t, std::uint32_t>> order;
    std::vector<bool> listed(letters.count, false);
    for (const std::uint32_t symbol : detail::preferenceOrder(alphabet.classCount())) {
        const std::uint32_t type = symbol % kEventTypeCount, labelClass = symbol / (kEventTypeCount * kScatterCount);
        const std::uint32_t letter = letters.ofSymbol[symbol];
        if (!(placedTypes[labelClass] >> type & 1u) || listed[letter]) continue;
        listed[letter] = true;
        order.emplace_back(letter, symbol);
    }
    return order;
}

}  // namespace

std::optional<Path> commonPath(const std::vector<std::string>& expressions, const LabelPlacement& placement) {
    if (expressions.empty() || expressions.size() > kMaxOutputs) {
        throw LimitError("LPE limit: commonPath takes 1 to " + std::to_string(kMaxOutputs) + " expressions");
    }
    const detail::TextsAsNfa front = detail::buildNfaOfTexts(expressions);
    const detail::Alphabet& alphabet = front.alphabet;
    const detail::Letters& letters = front.letters;
    const auto order = lettersToTry(alphabet, letters, placement);

    const OutputMask all = expressions.size() >= kMaxOutputs ? ~OutputMask{0}
                                                             : (OutputMask{1} << expressions.size()) - 1;
    LazySubsets subsets(front.nfa, letters, all, CompileOptions{}.maxStates);
    const std::uint32_t start = subsets.start();
    if (start == LazySubsets::kDropped) return std::nullopt;

    // Breadth-first; a subset's parent and the symbol that reached it give back the path.
    std::vector<std::uint32_t> parent{start};
    std::vector<std::uint32_t> via{0};
    std::deque<std::uint32_t> queue{start};
    while (!queue.empty()) {
        const std::uint32_t id = queue.front();
        queue.pop_front();
        if (subsets.acceptsAll(id)) {
            Path path;
            for (std::uint32_t s = id; s != start; s = parent[s])
                path.push_back(detail::eventOfSymbol(via[s], alphabet.labels()));
            return Path(path.rbegin(), path.rend());
        }
        for (const auto& [letter, symbol] : order) {
            const std::uint32_t next = subsets.step(id, letter);
            if (next == LazySubsets::kDropped || next < parent.size()) continue;  // dropped, or seen before
            parent.push_back(id);
            via.push_back(symbol);
            queue.push_back(next);
        }
    }
    return std::nullopt;
}

}  // namespace lpe
