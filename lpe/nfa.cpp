#include "lpe/nfa.h"

#include <algorithm>
#include <map>
#include <string>

#include "lpe/error.h"

namespace lpe::detail {
namespace {

using syntax::Node;

// A partly built automaton: enter at `start`, leave from `end` (which has no moves yet).
struct Fragment {
    std::uint32_t start;
    std::uint32_t end;
};

class ThompsonBuilder {
public:
    explicit ThompsonBuilder(const Alphabet& alphabet) : alphabet_(alphabet) {}

    Nfa take(std::vector<std::uint32_t> starts) {
        Nfa nfa;
        nfa.states = std::move(states_);
        nfa.starts = std::move(starts);
        nfa.predicates = std::move(predicates_);
        return nfa;
    }

    std::uint32_t newState() {
        states_.emplace_back();
        return static_cast<std::uint32_t>(states_.size() - 1);
    }

    void link(std::uint32_t from, std::uint32_t to) { states_[from].epsilon.push_back(to); }

    void markAccepting(std::uint32_t state, std::uint32_t output) { states_[state].output = output; }

    Fragment build(const Node& node) {
        switch (node.kind) {
            case Node::Kind::Event: return buildEvent(node);
            case Node::Kind::Concat: return buildConcat(node);
            case Node::Kind::Alternate: return buildAlternate(node);
            case Node::Kind::Repeat: return buildRepeat(node);
        }
        return buildEvent(node);
    }

private:
    Fragment buildEvent(const Node& node) {
        const std::uint32_t start = newState();
        const std::uint32_t end = newState();
        states_[start].predicate = intern(alphabet_.symbols(node.events));
        states_[start].target = end;
        return {start, end};
    }

    Fragment buildConcat(const Node& node) {
        Fragment whole = build(*node.children.front());
        for (std::size_t i = 1; i < node.children.size(); ++i) {
            const Fragment next = build(*node.children[i]);
            link(whole.end, next.start);
            whole.end = next.end;
        }
        return whole;
    }

    Fragment buildAlternate(const Node& node) {
        const Fragment whole{newState(), newState()};
        for (const auto& child : node.children) {
            const Fragment branch = build(*child);
            link(whole.start, branch.start);
            link(branch.end, whole.end);
        }
        return whole;
    }

    // x{n,m} is n copies of x followed by m-n optional ones, each a chance to leave; x{n,} is n
    // copies followed by Thompson's loop for x*.
    Fragment buildRepeat(const Node& node) {
        const Node& child = *node.children.front();
        const std::uint32_t start = newState();
        std::uint32_t at = start;
        for (std::uint32_t i = 0; i < node.min; ++i) {
            const Fragment copy = build(child);
            link(at, copy.start);
            at = copy.end;
        }
        if (node.max == syntax::kUnbounded) {
            const std::uint32_t loop = newState();
            link(at, loop);
            const Fragment body = build(child);
            link(loop, body.start);
            link(body.end, loop);
            return {start, loop};
        }
        const std::uint32_t end = newState();
        link(at, end);
        for (std::uint32_t i = node.min; i < node.max; ++i) {
            const Fragment copy = build(child);
            link(at, copy.start);
            at = copy.end;
            link(at, end);
        }
        return {start, end};
    }

    std::uint32_t intern(SymbolSet symbols) {
        const auto [found, added] =
            ids_.emplace(std::move(symbols), static_cast<std::uint32_t>(predicates_.size()));
        if (added) predicates_.push_back(found->first);
        return found->second;
    }

    const Alphabet& alphabet_;
    std::vector<NfaState> states_;
    std::vector<SymbolSet> predicates_;
    std::map<SymbolSet, std::uint32_t> ids_;
};

}  // namespace

std::size_t expandedSize(const Node& node, std::size_t cap) {
    const auto saturate = [cap](std::size_t n) { return n > cap ? cap + 1 : n; };
    switch (node.kind) {
        case Node::Kind::Event: return 1;
        case Node::Kind::Concat:
        case Node::Kind::Alternate: {
            std::size_t total = 1;
            for (const auto& child : node.children) total = saturate(total + expandedSize(*child, cap));
            return total;
        }
        case Node::Kind::Repeat: {
            // Both counts are at most kMaxRepetition, so this product cannot overflow.
            const std::size_t copies =
                node.max == syntax::kUnbounded ? std::size_t{node.min} + 1 : std::size_t{node.max};
            return saturate(1 + copies * expandedSize(*node.children.front(), cap));
        }
    }
    return 1;
}

TextsAsNfa buildNfaOfTexts(const std::vector<std::string>& texts) {
    std::vector<syntax::Expression> parsed;
    std::vector<std::string> labels;
    for (const std::string& text : texts) {
        parsed.push_back(syntax::parseExpression(text));
        labels.insert(labels.end(), parsed.back().labels.begin(), parsed.back().labels.end());
    }
    Alphabet alphabet(labels);
    std::vector<const Node*> roots;
    for (const auto& expression : parsed) roots.push_back(expression.root.get());
    Nfa nfa = buildNfa(roots, alphabet);
    Letters letters = compressAlphabet(nfa.predicates, alphabet.symbolCount());
    return {std::move(alphabet), std::move(nfa), std::move(letters)};
}

const StateSet& EpsilonClosure::operator()(const StateSet& seeds) {
    ++generation_;
    closure_.clear();
    stack_.assign(seeds.begin(), seeds.end());
    while (!stack_.empty()) {
        const std::uint32_t s = stack_.back();
        stack_.pop_back();
        if (seen_[s] == generation_) continue;
        seen_[s] = generation_;
        closure_.push_back(s);
        for (const std::uint32_t t : nfa_.states[s].epsilon) stack_.push_back(t);
    }
    std::sort(closure_.begin(), closure_.end());
    return closure_;
}

Nfa buildNfa(const std::vector<const Node*>& roots, const Alphabet& alphabet) {
    std::size_t total = 0;
    for (const Node* root : roots) total += expandedSize(*root, kMaxExpandedNodes);
    if (total > kMaxExpandedNodes) {
        throw LimitError("LPE limit: the expressions expand to more than " +
                         std::to_string(kMaxExpandedNodes) +
                         " events and operators once every repetition {n,m} is written out");
    }

    ThompsonBuilder builder(alphabet);
    std::vector<std::uint32_t> starts;
    for (std::uint32_t output = 0; output < roots.size(); ++output) {
        const Fragment whole = builder.build(*roots[output]);
        builder.markAccepting(whole.end, output);
        starts.push_back(whole.start);
    }
    return builder.take(std::move(starts));
}

}  // namespace lpe::detail
