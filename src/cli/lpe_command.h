#pragma once
// `lightpath lpe`: the LPE engine on the command line (match paths, check AOV sets, draw automata).
#include <CLI/CLI.hpp>

namespace lightpath {

// Registers `lpe` and its subcommands `match`, `check` and `dot`. Errors in expressions or paths
// are thrown as CLI::RuntimeError carrying the engine's message, with exit code 2 (bad input).
void addLpeCommand(CLI::App& app);

// Registers `lpe exercise` under `lpe` (lpe_exercise_command.cpp).
void addLpeExerciseCommand(CLI::App& lpe);

}  // namespace lightpath
