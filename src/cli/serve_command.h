#pragma once
#include <CLI/CLI.hpp>

namespace lightpath {

// `lightpath serve SCENE [--port N] [--host H] [--open]`: the light-path explorer in the browser
// (docs/serve.md).
void addServeCommand(CLI::App& app);

}  // namespace lightpath
