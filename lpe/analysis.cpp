// Set properties decided on one automaton holding the set and its universe: a pair overlaps when
// some universe path reaches a state accepting both; the set leaves a gap when some universe path
// reaches a state accepting none; i is contained in j when no universe path reaches a state that
// accepts i and not j. Breadth-first search makes every example a shortest one.
#include "lpe/analysis.h"

#include "lpe/error.h"

namespace lpe {
namespace {

Automaton compileWithUniverse(const std::vector<NamedExpression>& expressions, const std::string& universe,
                              const char* what) {
    if (expressions.size() >= kMaxOutputs) {
        throw LimitError(std::string("LPE limit: ") + what + " takes at most " + std::to_string(kMaxOutputs - 1) +
                         " expressions (one output is the universe)");
    }
    std::vector<NamedExpression> all = expressions;
    all.push_back({"universe", universe});
    return Automaton::compile(all);
}

}  // namespace

SetReport analyse(const std::vector<NamedExpression>& expressions, const std::string& universe) {
    const Automaton automaton = compileWithUniverse(expressions, universe, "analyse");
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

Containment compareLanguages(const std::vector<NamedExpression>& expressions, const std::string& universe) {
    const Automaton automaton = compileWithUniverse(expressions, universe, "compareLanguages");
    const OutputMask inUniverse = OutputMask{1} << expressions.size();
    Containment result;
    result.onlyIn.assign(expressions.size(), std::vector<std::optional<Path>>(expressions.size()));
    for (std::size_t i = 0; i < expressions.size(); ++i) {
        for (std::size_t j = 0; j < expressions.size(); ++j) {
            if (i == j) continue;
            const OutputMask wanted = (OutputMask{1} << i) | inUniverse, unwanted = OutputMask{1} << j;
            result.onlyIn[i][j] = automaton.findShortestPath(
                [wanted, unwanted](OutputMask m) { return (m & wanted) == wanted && !(m & unwanted); });
        }
    }
    return result;
}

}  // namespace lpe
