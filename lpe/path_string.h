#pragma once
// Paths as text, for teaching (`lightpath explain`, `lpe match`) and for tests. Never used in the
// renderer's hot loop.
#include <string>
#include <string_view>

#include "lpe/event.h"

namespace lpe {

// Parses any of the forms below, telling them apart by the presence of whitespace, quotes or '<':
//   compact Heckbert: "ESDL"  -- E camera, D/G/S/s a reflection with that scattering, L light,
//                                O emitting object, B background, R/T/V a reflection/transmission/
//                                volume event with no scattering.
//   tuples:           "C TS TS RD'1' L'key'" -- type letter, scattering letter (`_`, `x` or nothing
//                                for none), optional quoted label; events separated by spaces.
//   expression:       "E <TS> <RD'1'> <L.'key'>" -- what toExpressionString prints.
// Throws SyntaxError naming the position.
Path parsePath(std::string_view text);

// "ESDL": loses transmission vs reflection and labels (a T event prints its scattering letter).
std::string toCompactString(const Path& path);
// "E RS RD'floor' L'key'": lossless, parsePath(toTupleString(p)) == p, for every path a renderer
// records (two events or more). A lone unlabelled event such as "RS" reads back as the compact
// path R S: one word without spaces or quotes is compact. Labels cannot contain '.
std::string toTupleString(const Path& path);
// "E <RS> <RD'floor'> <L.'key'>": an expression that, pasted into --lpe, matches exactly this path
// (each event as an OSL tuple; OSL's <L.'key'> for labelled non-scattering events). Reads back
// through parsePath losslessly for every path a renderer records (camera, lights, object emission
// and background with Scatter::None).
std::string toExpressionString(const Path& path);
// The compact form when it loses nothing, the tuple form otherwise: for reports and examples.
std::string toDisplayString(const Path& path);

}  // namespace lpe
