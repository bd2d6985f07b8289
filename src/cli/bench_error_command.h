#pragma once
#include <CLI/CLI.hpp>

namespace lightpath {

// `lightpath bench error`: run time against error (registered under `bench`).
void addBenchErrorCommand(CLI::App& bench);

}  // namespace lightpath
