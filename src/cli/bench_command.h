#pragma once
#include <CLI/CLI.hpp>

namespace lightpath {

// `lightpath bench ...`: benchmarks that print figures (time ratios measured in one run).
void addBenchCommand(CLI::App& app);

}  // namespace lightpath
