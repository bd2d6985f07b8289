#pragma once
// Graphviz's `dot -Tsvg` as a filter: DOT text in, SVG out, in a child process bounded in time.
#include <stdexcept>
#include <string>

namespace lightpath::serve {

class GraphvizError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Throws GraphvizError when `dot` is missing, fails, or runs longer than `timeoutSeconds`
// (it is then killed).
std::string dotToSvg(const std::string& dot, double timeoutSeconds = 5.0);

}  // namespace lightpath::serve
