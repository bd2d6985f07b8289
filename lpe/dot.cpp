// Automaton::toDot: the automaton as a Graphviz graph whose edges are labelled in LPE syntax.
//
// An edge stands for a set of symbols. Its label is the shorter of two descriptions of that set:
// a union `A|B|...` of events, or a negated set `[^AB...]` of its complement, each found by a
// greedy cover with the widest events first (`.`, R, T, V, D, G, S, s, L, E, <L>, B, O, then
// tuples). Camera, emitter, background and object-emission events match as if they did not
// scatter (automaton.h), so the nineteen (type, scattering) pairs below stand for every symbol:
// `E`, `L`, `B` and `O` need no scattering position and `D` is exactly "<RD>, <TD> or <VD>".
// Inside a negated set `[^...]` a bare `L` is OSL's (lights only), so there it is not a candidate.
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "lpe/automaton.h"

namespace lpe {
namespace {

using T = EventType;
using S = Scatter;

struct Pair {
    T type;
    S scatter;
};

// The events of a path a renderer can hold: camera, reflection, transmission, emitter, background.
const std::vector<Pair>& possiblePairs() {
    static const std::vector<Pair> pairs = [] {
        std::vector<Pair> all{{T::Camera, S::None}};
        for (const T type : {T::Reflection, T::Transmission, T::Volume}) {
            for (const S scatter : {S::Diffuse, S::Glossy, S::Specular, S::Straight, S::None}) {
                all.push_back({type, scatter});
            }
        }
        all.push_back({T::Emitter, S::None});
        all.push_back({T::Background, S::None});
        all.push_back({T::ObjectEmission, S::None});
        return all;
    }();
    return pairs;
}

using PairSet = std::vector<bool>;  // indexed like possiblePairs()

// An event a label can be printed for: `plain` without a label; `head` + label + `>` with one.
struct Candidate {
    std::string plain;
    std::string head;  // empty: the label alone is the event (the `.` candidate)
    PairSet pairs;
    std::string types{};  // for whole event types (R, T, E, L, <L>, B): their tuple letters
    Pair single{};        // for a one-pair tuple <RD>: that pair, so that such tuples can merge
    bool isSingle = false;
    bool topLevelOnly = false;  // its plain letter means something else inside a set
};

PairSet pairsWhere(bool (*keep)(const Pair&)) {
    PairSet set;
    for (const Pair& p : possiblePairs()) set.push_back(keep(p));
    return set;
}

// Candidates from the widest to the narrowest; greedy covering tries them in this order.
const std::vector<Candidate>& candidates() {
    static const std::vector<Candidate> list = [] {
        std::vector<Candidate> all;
        all.push_back({".", "", pairsWhere([](const Pair&) { return true; })});
        all.push_back({"R", "<R", pairsWhere([](const Pair& p) { return p.type == T::Reflection; }), "R"});
        all.push_back({"T", "<T", pairsWhere([](const Pair& p) { return p.type == T::Transmission; }), "T"});
        all.push_back({"V", "<V", pairsWhere([](const Pair& p) { return p.type == T::Volume; }), "V"});
        const auto scatterCandidate = [&all](const char* name, const char* head, S s) {
            PairSet set;
            for (const Pair& p : possiblePairs()) set.push_back(p.scatter == s);
            all.push_back({name, head, set});
        };
        scatterCandidate("D", "<.D", S::Diffuse);
        scatterCandidate("G", "<.G", S::Glossy);
        scatterCandidate("S", "<.S", S::Specular);
        scatterCandidate("s", "<.s", S::Straight);
        Candidate emitters{"L", "<[LBO]", pairsWhere([](const Pair& p) {
                               return p.type == T::Emitter || p.type == T::Background || p.type == T::ObjectEmission;
                           }), "LBO"};
        emitters.topLevelOnly = true;
        all.push_back(emitters);
        all.push_back({"E", "<E", pairsWhere([](const Pair& p) { return p.type == T::Camera; }), "E"});
        all.push_back({"<L>", "<L", pairsWhere([](const Pair& p) { return p.type == T::Emitter; }), "L"});
        all.push_back({"B", "<B", pairsWhere([](const Pair& p) { return p.type == T::Background; }), "B"});
        all.push_back({"O", "<O", pairsWhere([](const Pair& p) { return p.type == T::ObjectEmission; }), "O"});
        for (std::size_t i = 0; i < possiblePairs().size(); ++i) {
            const Pair p = possiblePairs()[i];
            if (!scatters(p.type)) continue;
            const std::string tuple = std::string("<") + letter(p.type) + letter(p.scatter);
            PairSet only(possiblePairs().size(), false);
            only[i] = true;
            all.push_back({tuple + ">", tuple, only, "", p, true});
        }
        return all;
    }();
    return list;
}

// The label position for a set of label classes that is not "all of them".
std::string labelSpec(const std::vector<bool>& classes, const std::vector<std::string>& labels) {
    const auto quote = [&](std::size_t c) { return "'" + labels[c - 1] + "'"; };
    std::vector<std::size_t> listed;
    // Class 0 means "any other label": a set containing it is written by the labels it lacks.
    const bool negated = classes[0];
    for (std::size_t c = 1; c < classes.size(); ++c) {
        if (classes[c] != negated) listed.push_back(c);
    }
    if (!negated && listed.size() == 1) return quote(listed.front());
    std::string spec = negated ? "[^" : "[";
    for (const std::size_t c : listed) spec += quote(c);
    return spec + "]";
}

// A greedy set cover of `target` by candidates that lie inside it; pairs outside `target` must
// stay uncovered, so a candidate is used only if it is a subset.
std::vector<const Candidate*> cover(const PairSet& target, bool inSet) {
    std::vector<const Candidate*> chosen;
    PairSet covered(target.size(), false);
    for (;;) {
        const Candidate* best = nullptr;
        std::size_t bestGain = 0;
        for (const Candidate& c : candidates()) {
            if (inSet && c.topLevelOnly) continue;
            std::size_t gain = 0;
            bool inside = true;
            for (std::size_t i = 0; i < target.size(); ++i) {
                if (c.pairs[i] && !target[i]) inside = false;
                if (c.pairs[i] && target[i] && !covered[i]) ++gain;
            }
            if (inside && gain > bestGain) {
                best = &c;
                bestGain = gain;
            }
        }
        if (!best) return chosen;
        chosen.push_back(best);
        for (std::size_t i = 0; i < target.size(); ++i) covered[i] = covered[i] || best->pairs[i];
    }
}

// The events of a symbol set, each a single-event atom of LPE syntax.
// `inSet`: the atoms go inside `[^...]`, where a bare `L` reads as OSL's.
std::vector<std::string> atoms(const std::vector<bool>& symbols, const Automaton& automaton, bool inSet) {
    const std::size_t classCount = automaton.labels().size() + 1;
    // Group the possible pairs by the label classes present with them; all classes = no label.
    std::map<std::vector<bool>, PairSet> groups;
    for (std::size_t i = 0; i < possiblePairs().size(); ++i) {
        const Pair p = possiblePairs()[i];
        std::vector<bool> classes(classCount);
        bool any = false;
        for (std::size_t c = 0; c < classCount; ++c) {
            classes[c] = symbols[automaton.symbol(p.type, p.scatter, static_cast<Automaton::LabelClass>(c))];
            any = any || classes[c];
        }
        if (!any) continue;
        auto& group = groups[classes];
        group.resize(possiblePairs().size(), false);
        group[i] = true;
    }

    std::vector<std::string> result;
    const std::vector<bool> all(classCount, true);
    const auto emit = [&](const std::vector<bool>& classes, const PairSet& pairs) {
        const bool plain = classes == all;
        const std::string spec = plain ? "" : labelSpec(classes, automaton.labels());
        const auto text = [&](const Candidate& c) {
            // A type-only tuple writes OSL's '.' in the scattering position before its label.
            return plain ? c.plain : c.head.empty() ? spec : c.head + (c.types.empty() ? "" : ".") + spec + ">";
        };
        // Single-pair tuples of one type merge into one tuple with a scattering set: <R[DG]>.
        std::map<char, std::string> scatterSets;
        // Whole event types may merge into one tuple with a type set: <[^L]'key'>.
        std::vector<std::string> typeAtoms;
        std::string types;
        for (const Candidate* c : cover(pairs, inSet)) {
            if (c->isSingle) {
                scatterSets[letter(c->single.type)] += letter(c->single.scatter);
            } else if (!c->types.empty()) {
                typeAtoms.push_back(text(*c));
                types += c->types;
            } else {
                result.push_back(text(*c));
            }
        }
        for (const auto& [type, scatters] : scatterSets) {
            const std::string scatter = scatters.size() == 1 ? scatters : "[" + scatters + "]";
            result.push_back(std::string("<") + type + scatter + spec + ">");
        }
        std::size_t separate = 0;
        for (const std::string& atom : typeAtoms) separate += atom.size() + 1;
        std::string missing;
        for (const char t : std::string(kEventTypeLetters.begin(), kEventTypeLetters.end())) {
            if (types.find(t) == std::string::npos) missing += t;
        }
        const std::string position = plain ? "" : "." + spec;
        const std::string merged = types.size() < missing.size() + 1 ? "<[" + types + "]" + position + ">"
                                                                     : "<[^" + missing + "]" + position + ">";
        if (typeAtoms.size() > 1 && merged.size() < separate) {
            result.push_back(merged);
        } else {
            result.insert(result.end(), typeAtoms.begin(), typeAtoms.end());
        }
    };
    if (groups.count(all)) emit(all, groups[all]);
    for (const auto& [classes, pairs] : groups) {
        if (classes != all) emit(classes, pairs);
    }
    return result;
}

std::string describe(const std::vector<bool>& symbols, const Automaton& automaton) {
    std::string positive;
    for (const std::string& atom : atoms(symbols, automaton, false)) {
        positive += (positive.empty() ? "" : "|") + atom;
    }
    std::vector<bool> complement(symbols);
    complement.flip();
    const std::vector<std::string> excluded = atoms(complement, automaton, true);
    if (excluded.empty()) return positive;
    std::string negative = "[^";
    for (const std::string& atom : excluded) negative += atom;
    negative += "]";
    return negative.size() < positive.size() ? negative : positive;
}

// Text inside a DOT double-quoted string: quotes and backslashes escaped, control bytes blanked.
std::string escaped(std::string_view text) {
    std::string out;
    for (const char c : text) {
        if (c == '"' || c == '\\') out += '\\';
        out += static_cast<unsigned char>(c) < 0x20 ? ' ' : c;
    }
    return out;
}

std::string quoted(std::string_view text) {
    std::string out(1, '"');
    out += escaped(text);
    out += '"';
    return out;
}

}  // namespace

std::string Automaton::toDot(std::string_view title) const {
    const auto dead = [this](State s) { return canAccept_[s] == 0 && s != start_; };
    std::string dot = "digraph " + quoted(title.empty() ? "lpe" : title) + " {\n";
    dot += "  rankdir=LR;\n";
    if (!title.empty()) dot += "  label=" + quoted(title) + ";\n  labelloc=t;\n";
    dot += "  node [shape=circle];\n";
    dot += "  start [shape=point, style=invis];\n";
    dot += "  start -> " + std::to_string(start_) + ";\n";

    for (State s = 0; s < stateCount(); ++s) {
        if (dead(s)) continue;
        std::string label = std::to_string(s);
        std::string names;
        for (std::size_t o = 0; o < outputCount(); ++o) {
            if ((accepts_[s] >> o) & 1u) names += (names.empty() ? "" : ", ") + outputNames_[o];
        }
        if (names.empty()) {
            dot += "  " + label + ";\n";
        } else {
            dot += "  " + label + " [shape=doublecircle, label=" + "\"" + label + "\\n" + escaped(names) +
                   "\"" + "];\n";
        }
    }
    for (State s = 0; s < stateCount(); ++s) {
        if (dead(s)) continue;
        std::map<State, std::vector<bool>> edges;
        for (Symbol symbol = 0; symbol < symbolCount_; ++symbol) {
            const State target = step(s, symbol);
            if (dead(target)) continue;
            auto& symbols = edges[target];
            symbols.resize(symbolCount_, false);
            symbols[symbol] = true;
        }
        for (const auto& [target, symbols] : edges) {
            dot += "  " + std::to_string(s) + " -> " + std::to_string(target) +
                   " [label=" + quoted(describe(symbols, *this)) + "];\n";
        }
    }
    dot += "}\n";
    return dot;
}

}  // namespace lpe
