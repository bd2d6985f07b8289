#pragma once
#include <CLI/CLI.hpp>

namespace lightpath {

// `lightpath stress [--quick] [--json FILE]`: the numerical robustness scorecard. Exits 1 when a
// robust row misses its target.
void addStressCommand(CLI::App& app);

}  // namespace lightpath
