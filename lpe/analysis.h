#pragma once
// Properties of a set of expressions decided on the automaton itself, not by sampling paths.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "lpe/automaton.h"
#include "lpe/event.h"

namespace lpe {

struct Overlap {
    std::size_t first = 0, second = 0;  // indices into the expression set
    Path example;                       // a shortest path both accept
};

struct SetReport {
    std::vector<Overlap> overlaps;      // every overlapping pair, with its shortest example
    std::optional<Path> gap;            // a shortest path of the universe that no expression accepts
    bool partition() const { return overlaps.empty() && !gap; }
};

// Overlaps are searched among paths of the universe (the only ones a set is asked to split).
SetReport analyse(const std::vector<NamedExpression>& expressions,
                  const std::string& universe = "E.*L");

// Containment of languages within the universe: onlyIn[i][j] is a shortest universe path that
// expression i accepts and expression j does not, or nothing when every universe path of i is one
// of j (i is contained in j).
struct Containment {
    std::vector<std::vector<std::optional<Path>>> onlyIn;
    bool contains(std::size_t larger, std::size_t smaller) const { return !onlyIn[smaller][larger]; }
    bool strictlyContains(std::size_t larger, std::size_t smaller) const {
        return contains(larger, smaller) && !contains(smaller, larger);
    }
};
Containment compareLanguages(const std::vector<NamedExpression>& expressions,
                             const std::string& universe = "E.*L");

// The event types that may carry each label, as the caller (a renderer) knows them, e.g. a light's
// name only on L events. A label not listed may be on any event, as may events with no label.
using LabelPlacement = std::map<std::string, std::vector<EventType>, std::less<>>;

// A shortest path that every one of `expressions` accepts, built only of events `placement`
// allows; nothing when they have no such path in common. Throws SyntaxError or LimitError.
std::optional<Path> commonPath(const std::vector<std::string>& expressions, const LabelPlacement& placement = {});
// Whether some path matches every one of `expressions` (commonPath finds one).
inline bool haveCommonPath(const std::vector<std::string>& expressions, const LabelPlacement& placement = {}) {
    return commonPath(expressions, placement).has_value();
}

}  // namespace lpe
