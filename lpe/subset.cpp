#include <algorithm>
#include <string>
#include <unordered_map>

#include "lpe/dfa.h"
#include "lpe/error.h"

namespace lpe::detail {
namespace {

class SubsetBuilder {
public:
    SubsetBuilder(const Nfa& nfa, const Letters& letters, std::size_t maxStates)
        : nfa_(nfa), letters_(letters), maxStates_(maxStates), closure_(nfa) {}

    Dfa build() {
        dfa_.letterCount = letters_.count;
        dfa_.start = intern(closure_(nfa_.starts));
        // sets_ grows while we walk it: every new subset is explored once, in discovery order.
        for (std::size_t state = 0; state < sets_.size(); ++state) {
            for (std::uint32_t letter = 0; letter < letters_.count; ++letter) {
                StateSet moved;
                for (const std::uint32_t s : sets_[state]) {
                    const NfaState& nfaState = nfa_.states[s];
                    if (nfaState.predicate != kNone &&
                        letters_.inPredicate[nfaState.predicate * letters_.count + letter]) {
                        moved.push_back(nfaState.target);
                    }
                }
                const std::uint32_t target = intern(closure_(moved));
                dfa_.next[state * letters_.count + letter] = target;
            }
        }
        return std::move(dfa_);
    }

private:
    std::uint32_t intern(StateSet set) {
        const auto found = ids_.find(set);
        if (found != ids_.end()) return found->second;
        if (sets_.size() >= maxStates_) {
            throw LimitError("LPE limit: the automaton needs more than " + std::to_string(maxStates_) +
                             " states (CompileOptions::maxStates); simplify the expressions or "
                             "compile them separately");
        }
        const auto id = static_cast<std::uint32_t>(sets_.size());
        OutputMask accepts = 0;
        for (const std::uint32_t s : set) {
            if (nfa_.states[s].output != kNone) accepts |= OutputMask{1} << nfa_.states[s].output;
        }
        dfa_.accepts.push_back(accepts);
        dfa_.next.resize(dfa_.next.size() + letters_.count, 0);
        ids_.emplace(set, id);
        sets_.push_back(std::move(set));
        return id;
    }

    const Nfa& nfa_;
    const Letters& letters_;
    std::size_t maxStates_;
    EpsilonClosure closure_;
    std::vector<StateSet> sets_;
    std::unordered_map<StateSet, std::uint32_t, StateSetHash> ids_;
    Dfa dfa_;
};

}  // namespace

Dfa determinise(const Nfa& nfa, const Letters& letters, std::size_t maxStates) {
    return SubsetBuilder(nfa, letters, maxStates).build();
}

}  // namespace lpe::detail
