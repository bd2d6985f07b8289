#pragma once
// The named AOV sets (`--aovs classes`, `lpe check --set taxonomy`, serve's preset menu): one
// registry, each preset declared and registered in its own file (film/*_preset.cpp) with its name,
// a one-line summary (the help text), the universe it splits and how it makes its AOVs. The command
// line's choices and help, `lpe`'s --set, serve's menu and `lightpath types preset` read the
// registry. They live in the renderer, not in lpe/, which knows nothing of AOV names.
#include <string>
#include <string_view>
#include <vector>

#include "lpe/automaton.h"
#include "schema/registry.h"
#include "schema/type_schema.h"

namespace lightpath {

struct Scene;

struct AovPreset {
    // Family "preset"; summary: the help text; events: the universe it is meant to split (`lpe check`).
    TypeSchema schema;
    int rank = 0;  // listing order; rank 0 is the default set
    // Its AOVs. `scene` is read only by a preset made from the scene (fromScene); null elsewhere.
    std::vector<lpe::NamedExpression> (*make)(const Scene* scene) = nullptr;
    // Its AOVs come from a scene (one per light): none without one (`lpe check` has no scene).
    bool fromScene = false;

    std::vector<lpe::NamedExpression> expressions(const Scene* scene = nullptr) const { return make(scene); }
};

using AovPresetRegistry = TypeRegistry<AovPreset>;

// The default AOV partition of docs/design.md, named `classes`. Its bare `L` is Heckbert's (every
// emitter: lights, emitting objects and the background), so it splits the universe E.*L.
const std::vector<lpe::NamedExpression>& classesSet();
// The lecture's taxonomy of tracing (Magnusson): ray casting, ray tracing, radiosity, path tracing.
const std::vector<lpe::NamedExpression>& taxonomySet();
// The light by the number of events between the eye and the emitter: emission, bounce1 .. bounce3,
// bounce4plus. A partition of E.*L, so its AOVs sum to the beauty under every integrator.
const std::vector<lpe::NamedExpression>& bouncesSet();

// Every registered preset, by rank.
std::vector<const AovPreset*> aovPresets();
const AovPreset* findAovPreset(std::string_view name);
// Their names; without the presets made from a scene when `withSceneOnly` is false (`lpe`).
std::vector<std::string> aovPresetNames(bool withSceneOnly = true);
// "classes (...), taxonomy (...), ... or none": the --aovs help, from the summaries.
std::string aovPresetHelp();

}  // namespace lightpath

#define LIGHTPATH_REGISTER_PRESET(...) \
    namespace { const ::lightpath::Registrar<::lightpath::AovPreset> LIGHTPATH_SCHEMA_CONCAT(kPresetRegistrar, __COUNTER__){__VA_ARGS__}; }
