#pragma once
#include <CLI/CLI.hpp>

namespace lightpath {

// `lightpath explain SCENE --pixel X,Y`: every contribution of one pixel with its light path.
void addExplainCommand(CLI::App& app);

}  // namespace lightpath
