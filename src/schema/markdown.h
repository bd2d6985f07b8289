#pragma once
// One type's parameter table as Markdown, the table scenes/README.md shows for it (a ctest keeps
// the two equal).
#include <string>

#include "schema/type_schema.h"

namespace lightpath {

// "| key | type | unit | default | allowed | meaning |" and one row per parameter.
std::string markdownTable(const TypeSchema& schema);
// What a parameter allows, as the table says it: "each channel `>= 0`", "`> 0`", "any".
std::string allowedText(const Parameter& parameter);
// Its default as the table says it: "`0`", "**required**", "none".
std::string defaultCell(const Parameter& parameter);

}  // namespace lightpath
