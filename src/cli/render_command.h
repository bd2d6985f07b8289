#pragma once
#include <CLI/CLI.hpp>

namespace lightpath {

// `lightpath render SCENE -o OUT ...`: renders the beauty and its AOVs.
void addRenderCommand(CLI::App& app);

}  // namespace lightpath
