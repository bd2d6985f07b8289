#pragma once
#include <CLI/CLI.hpp>

namespace lightpath {

// `lightpath types [FAMILY [NAME]] [--markdown]`: the registered families and types with their
// summaries; with a name, that type's parameter table and events. scenes/README.md's tables are
// what `--markdown` prints (ctest docs/schema-tables).
void addTypesCommand(CLI::App& app);

}  // namespace lightpath
