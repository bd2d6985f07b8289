// Automaton::compile: the pipeline of OSL's lpexp, written out stage by stage.
//   text --parser--> syntax tree --Thompson--> NFA --subset construction--> DFA
//        --Hopcroft--> minimal DFA --renumber, expand letters--> dense table of symbols
#include <deque>
#include <string>

#include "lpe/alphabet.h"
#include "lpe/automaton.h"
#include "lpe/dfa.h"
#include "lpe/error.h"
#include "lpe/nfa.h"
#include "lpe/syntax.h"

namespace lpe {
namespace {

using detail::Dfa;

// The dense table holds stateCount x symbolCount entries; refuse to allocate beyond this.
constexpr std::size_t kMaxTableEntries = std::size_t{1} << 25;

OutputMask lowBits(std::size_t count) {
    return count >= kMaxOutputs ? ~OutputMask{0} : (OutputMask{1} << count) - 1;
}

// The `rest` output: the NFA's last output is the universe, hidden; in its place the automaton
// gets "universe and no named output". Done before minimisation, so the hidden output never
// splits a state the visible outputs cannot tell apart.
void replaceUniverseByComplement(Dfa& dfa, std::size_t namedCount) {
    const OutputMask named = lowBits(namedCount);
    const OutputMask rest = OutputMask{1} << namedCount;
    for (OutputMask& accepts : dfa.accepts) {
        const bool inUniverse = (accepts & rest) != 0;
        accepts &= named;
        if (inUniverse && accepts == 0) accepts = rest;
    }
}

// Per state, the outputs that accept in some state reachable from it: a backward fixpoint over
// the predecessor graph with a worklist (each mask only grows, at most 64 times).
std::vector<OutputMask> reachableAccepts(const Dfa& dfa) {
    std::vector<std::vector<std::uint32_t>> predecessors(dfa.stateCount());
    for (std::uint32_t s = 0; s < dfa.stateCount(); ++s) {
        for (std::uint32_t a = 0; a < dfa.letterCount; ++a) predecessors[dfa.step(s, a)].push_back(s);
    }
    std::vector<OutputMask> canAccept = dfa.accepts;
    std::vector<std::uint32_t> work(dfa.stateCount());
    for (std::uint32_t s = 0; s < dfa.stateCount(); ++s) work[s] = s;
    while (!work.empty()) {
        const std::uint32_t t = work.back();
        work.pop_back();
        for (const std::uint32_t s : predecessors[t]) {
            if ((canAccept[s] | canAccept[t]) != canAccept[s]) {
                canAccept[s] |= canAccept[t];
                work.push_back(s);
            }
        }
    }
    return canAccept;
}

// New state numbers: breadth-first from the start (which becomes 0) along preferred symbols, so
// DOT drawings read left to right; the dead state, if any, goes last.
std::vector<std::uint32_t> renumbering(const Dfa& dfa, const detail::Letters& letters,
                                       const std::vector<std::uint32_t>& preferred,
                                       const std::vector<OutputMask>& canAccept) {
    constexpr std::uint32_t kUnset = UINT32_MAX;
    std::vector<std::uint32_t> number(dfa.stateCount(), kUnset);
    std::uint32_t next = 0;
    std::deque<std::uint32_t> queue;
    const auto visit = [&](std::uint32_t s) {
        if (number[s] != kUnset || canAccept[s] == 0) return;
        number[s] = next++;
        queue.push_back(s);
    };
    number[dfa.start] = next++;
    queue.push_back(dfa.start);
    while (!queue.empty()) {
        const std::uint32_t s = queue.front();
        queue.pop_front();
        for (const std::uint32_t symbol : preferred) visit(dfa.step(s, letters.ofSymbol[symbol]));
    }
    // Minimisation leaves at most one state from which nothing accepts (the dead state); every
    // other state is reachable, because subset construction only creates reachable subsets.
    for (std::uint32_t s = 0; s < dfa.stateCount(); ++s) {
        if (number[s] == kUnset) number[s] = next++;
    }
    return number;
}

}  // namespace

Automaton Automaton::compile(const std::vector<NamedExpression>& expressions,
                             const CompileOptions& options) {
    const bool complement = !options.complementName.empty();
    const std::size_t outputCount = expressions.size() + (complement ? 1 : 0);
    if (outputCount > kMaxOutputs) {
        throw LimitError("LPE limit: " + std::to_string(outputCount) +
                         " outputs requested; an automaton has at most " + std::to_string(kMaxOutputs) +
                         (complement ? " (including the complement output)" : ""));
    }

    // 1, 2. Parse (labels numbered by first appearance, the universe's last); Thompson NFA, one
    // output per tree (the universe last), and its compressed alphabet.
    std::vector<std::string> texts;
    for (const NamedExpression& e : expressions) texts.push_back(e.expression);
    if (complement) texts.push_back(options.universe);
    const detail::TextsAsNfa front = detail::buildNfaOfTexts(texts);
    const detail::Alphabet& alphabet = front.alphabet;
    const detail::Nfa& nfa = front.nfa;
    const detail::Letters& letters = front.letters;

    // 3. Subset construction, complement, minimisation.
    Dfa dfa = detail::determinise(nfa, letters, options.maxStates);
    if (complement) replaceUniverseByComplement(dfa, expressions.size());
    dfa = detail::minimise(dfa);

    if (dfa.stateCount() * alphabet.symbolCount() > kMaxTableEntries) {
        throw LimitError("LPE limit: the transition table would have " + std::to_string(dfa.stateCount()) +
                         " states x " + std::to_string(alphabet.symbolCount()) + " symbols");
    }

    // 4. The automaton the renderer steps: states renumbered, letters expanded back to symbols.
    Automaton automaton;
    automaton.symbolCount_ = alphabet.symbolCount();
    automaton.preferred_ = detail::preferenceOrder(alphabet.classCount());
    automaton.labels_ = alphabet.labels();
    for (std::size_t i = 0; i < automaton.labels_.size(); ++i) {
        automaton.labelClasses_.emplace(automaton.labels_[i], static_cast<LabelClass>(i + 1));
    }
    for (const NamedExpression& e : expressions) automaton.outputNames_.push_back(e.name);
    if (complement) automaton.outputNames_.push_back(options.complementName);

    const std::vector<OutputMask> canAccept = reachableAccepts(dfa);
    const std::vector<std::uint32_t> number = renumbering(dfa, letters, automaton.preferred_, canAccept);
    const std::size_t states = dfa.stateCount();
    automaton.start_ = number[dfa.start];
    automaton.accepts_.resize(states);
    automaton.canAccept_.resize(states);
    automaton.table_.resize(states * automaton.symbolCount_);
    for (std::uint32_t s = 0; s < states; ++s) {
        const std::uint32_t n = number[s];
        automaton.accepts_[n] = dfa.accepts[s];
        automaton.canAccept_[n] = canAccept[s];
        for (std::size_t symbol = 0; symbol < automaton.symbolCount_; ++symbol) {
            automaton.table_[n * automaton.symbolCount_ + symbol] =
                number[dfa.step(s, letters.ofSymbol[symbol])];
        }
    }
    return automaton;
}

}  // namespace lpe
