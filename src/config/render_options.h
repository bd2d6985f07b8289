#pragma once
// Every render option, declared once as a schema (name = the command line's flag without "--",
// type, unit, default, range, choices, doc): render and explain generate their flags and
// --help from it, RenderConfig checks values against it, serve's settings check its fields'
// types and ranges against it. Integrators' own parameters are their registry rows' schemas.
#include <string>
#include <vector>

#include "schema/type_schema.h"

namespace lightpath {

inline constexpr int kMaxResolution = 16384;
inline constexpr int kMaxSamplesPerPixel = 1 << 20;

const TypeSchema& renderOptionsSchema();

// The words an option accepts: its schema's choices, or those of a registry (--integrator: the
// integrators; --aovs: the presets and "none"); empty: any value of its type.
std::vector<std::string> optionChoices(const Parameter& option);

// The help line of an option: its doc, and for --integrator each integrator's summary.
std::string optionHelp(const Parameter& option);

}  // namespace lightpath
