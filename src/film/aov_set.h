#pragma once
// The outputs of a render: the beauty, the requested AOVs (each a named light path expression)
// and `rest`, everything no requested expression accepts. All expressions are compiled once into
// one automaton whose output i is AOV i.
#include <string>
#include <string_view>
#include <vector>

#include "lpe/automaton.h"

namespace lightpath {

class AovSet {
public:
    // Throws lpe::SyntaxError / lpe::LimitError for a bad expression, std::invalid_argument for a
    // bad or repeated name.
    explicit AovSet(std::vector<lpe::NamedExpression> expressions);

    const lpe::Automaton& automaton() const { return automaton_; }
    const std::vector<lpe::NamedExpression>& expressions() const { return expressions_; }

    // Image layers in order: "beauty", the AOVs, "rest".
    std::vector<std::string> layerNames() const;
    std::size_t layerCount() const { return expressions_.size() + 2; }

private:
    std::vector<lpe::NamedExpression> expressions_;
    lpe::Automaton automaton_;
};

// "name=EXPR" or "EXPR" (named lpe<index>). Names are identifiers: [A-Za-z_][A-Za-z0-9_]*.
lpe::NamedExpression parseNamedExpression(std::string_view argument, std::size_t index);

}  // namespace lightpath
