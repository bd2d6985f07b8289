#pragma once
// Properties of a set of expressions decided on the automaton itself, not by sampling paths.
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

// The default AOV partition of DESIGN.md, named `classes`.
const std::vector<NamedExpression>& classesSet();
// The lecture's taxonomy of tracing (Magnusson): ray casting, ray tracing, radiosity, path tracing.
const std::vector<NamedExpression>& taxonomySet();

}  // namespace lpe
