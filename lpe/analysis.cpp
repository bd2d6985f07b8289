// Set properties decided on one automaton holding the set and its universe: a pair overlaps when
// some universe path reaches a state accepting both; the set leaves a gap when some universe path
// reaches a state accepting none. Breadth-first search makes every example a shortest one.
#include "lpe/analysis.h"

#include "lpe/error.h"

namespace lpe {

SetReport analyse(const std::vector<NamedExpression>& expressions, const std::string& universe) {
    if (expressions.size() >= kMaxOutputs) {
        throw LimitError("LPE limit: analyse takes at most " + std::to_string(kMaxOutputs - 1) +
                         " expressions (one output is the universe)");
    }
    std::vector<NamedExpression> all = expressions;
    all.push_back({"universe", universe});
    const Automaton automaton = Automaton::compile(all);

    const OutputMask inUniverse = OutputMask{1} << expressions.size();
    const OutputMask named = inUniverse - 1;
    SetReport report;
    for (std::size_t i = 0; i < expressions.size(); ++i) {
        for (std::size_t j = i + 1; j < expressions.size(); ++j) {
            const OutputMask both = (OutputMask{1} << i) | (OutputMask{1} << j) | inUniverse;
            auto example = automaton.findShortestPath([both](OutputMask m) { return (m & both) == both; });
            if (example) report.overlaps.push_back({i, j, std::move(*example)});
        }
    }
    report.gap = automaton.findShortestPath(
        [named, inUniverse](OutputMask m) { return (m & inUniverse) && !(m & named); });
    return report;
}

const std::vector<NamedExpression>& classesSet() {
    static const std::vector<NamedExpression> set = {
        {"raycast", "E(D|G)L"},
        {"raytrace", "ES+(D|G)L"},
        {"mirror", "ES+L"},
        {"emission", "EL"},
        {"indirect", "ES*(D|G)(D|G|S)+L"},
    };
    return set;
}

const std::vector<NamedExpression>& taxonomySet() {
    static const std::vector<NamedExpression> set = {
        {"raycasting", "E(D|G)L"},
        {"raytracing", "E(S*)(D|G)L"},
        {"radiosity", "ED*L"},
        {"pathtracing", "E(D|G|S)*L"},
    };
    return set;
}

}  // namespace lpe
