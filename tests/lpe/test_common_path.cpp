// commonPath searches the expressions' product lazily (lpe/common_path.cpp). The reference is the
// other algorithm the engine has: compile the whole set into one minimal automaton and search it
// for a state accepting every output, honouring the same label placement. Both must give the same
// shortest path, event for event, on random sets of expressions (fixed seed).
#include <doctest/doctest.h>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include "lpe/analysis.h"
#include "lpe/automaton.h"
#include "lpe/path_string.h"

namespace {

std::optional<lpe::Path> commonPathByCompiling(const std::vector<std::string>& expressions,
                                               const lpe::LabelPlacement& placement) {
    std::vector<lpe::NamedExpression> named;
    for (const std::string& e : expressions) named.push_back({"e" + std::to_string(named.size()), e});
    const lpe::Automaton automaton = lpe::Automaton::compile(named);
    std::vector<bool> allowed(automaton.symbolCount(), true);
    for (lpe::Automaton::Symbol symbol = 0; symbol < automaton.symbolCount(); ++symbol) {
        const lpe::Event event = automaton.eventOf(symbol);
        const auto placed = placement.find(event.label);
        if (event.label.empty() || placed == placement.end()) continue;
        allowed[symbol] = std::find(placed->second.begin(), placed->second.end(), event.type) != placed->second.end();
    }
    const lpe::OutputMask all = automaton.allOutputs();
    return automaton.findShortestPath([all](lpe::OutputMask m) { return m == all; }, allowed);
}

// A random expression over events with and without labels, wildcards, sets and every repetition.
class CommonPathExpressions {
public:
    explicit CommonPathExpressions(unsigned seed) : rng_(seed) {}

    std::string expression(int depth) {
        const int choice = depth == 0 ? 0 : pick(0, 5);
        if (choice <= 1) return atom();
        if (choice == 2) return expression(depth - 1) + expression(depth - 1);
        if (choice == 3) return "(" + expression(depth - 1) + "|" + expression(depth - 1) + ")";
        static const char* const kRepeats[] = {"*", "+", "?", "{2}", "{1,3}", "{0,}"};
        return "(" + expression(depth - 1) + ")" + kRepeats[pick(0, 5)];
    }

private:
    std::string atom() {
        static const char* const kAtoms[] = {"E", "L", "D", "G", "S", "O", "B", ".", "[DG]", "[^S]", "<RD'a'>",
                                             "<L'k'>", "<.'a'>", "<..'k'>", "<T.>", "<R[DG]>", "<[^L].'a'>"};
        return kAtoms[pick(0, std::size(kAtoms) - 1)];
    }
    int pick(int low, int high) { return std::uniform_int_distribution<int>(low, high)(rng_); }

    std::mt19937 rng_;
};

}  // namespace

TEST_CASE("commonPath finds the path a compiled automaton's search finds, on random expression sets") {
    CommonPathExpressions random(20261126);
    const lpe::LabelPlacement lightsOnly{{"k", {lpe::EventType::Emitter}}};
    const lpe::LabelPlacement objectsOnly{{"a", {lpe::EventType::Reflection, lpe::EventType::Transmission}},
                                          {"k", {lpe::EventType::Emitter}}};
    int found = 0, none = 0;
    for (int trial = 0; trial < 600; ++trial) {
        std::vector<std::string> set;
        const int count = 1 + trial % 3;
        for (int i = 0; i < count; ++i) set.push_back(random.expression(3));
        if (trial % 2 == 0) set.push_back("E.*[LOB]");
        for (const lpe::LabelPlacement* placement : {&lightsOnly, &objectsOnly}) {
            const auto expected = commonPathByCompiling(set, *placement);
            const auto actual = lpe::commonPath(set, *placement);
            std::string shown;
            for (const std::string& e : set) shown += e + "  ";
            INFO("expressions: ", shown);
            REQUIRE(actual.has_value() == expected.has_value());
            if (!expected) {
                ++none;
                continue;
            }
            ++found;
            CHECK(lpe::toExpressionString(*actual) == lpe::toExpressionString(*expected));
        }
    }
    // Both answers occur often enough for the comparison to mean something.
    CHECK(found > 200);
    CHECK(none > 100);
}
