#pragma once
// The named AOV sets the command line offers (`--aovs classes`, `lpe check --set taxonomy`). They
// live in the renderer, not in lpe/, which knows nothing of AOV names.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "lpe/automaton.h"

namespace lightpath {

// The default AOV partition of docs/design.md, named `classes`. Its bare `L` is Heckbert's (every
// emitter: lights, emitting objects and the background), so it splits the universe E.*L.
const std::vector<lpe::NamedExpression>& classesSet();
// The lecture's taxonomy of tracing (Magnusson): ray casting, ray tracing, radiosity, path tracing.
const std::vector<lpe::NamedExpression>& taxonomySet();
// The light by the number of events between the eye and the emitter: emission, bounce1 .. bounce3,
// bounce4plus. A partition of E.*L, so its AOVs sum to the beauty under every integrator.
const std::vector<lpe::NamedExpression>& bouncesSet();

struct AovPreset {
    const char* name;
    const std::vector<lpe::NamedExpression>& (*expressions)();
    const char* universe;  // what the set is meant to split, for `lpe check`
};
// Every preset, in the order --help lists them.
const std::vector<AovPreset>& aovPresets();
std::optional<AovPreset> findAovPreset(std::string_view name);

}  // namespace lightpath
