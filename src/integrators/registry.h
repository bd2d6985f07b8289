#pragma once
// Every integrator in one table: its name, what it does, and the light paths it can produce (its
// path language, an LPE). The command line's --integrator choices, their did-you-mean and
// makeIntegrator read this table; `lpe check --integrator` and the refusal of AOVs no integrator
// path can reach read the languages.
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "integrators/integrator.h"

namespace lightpath {

struct IntegratorInfo {
    const char* name;
    const char* summary;       // one line for --help
    const char* pathLanguage;  // every path it can emit, as an LPE (bare L: any emitter)
    // Why a path outside pathLanguage is out of reach, for messages: "ray casting follows ...".
    const char* limitation;
    std::unique_ptr<Integrator> (*make)();
};

const std::vector<IntegratorInfo>& integrators();
const IntegratorInfo* findIntegrator(std::string_view name);
std::vector<std::string> integratorNames();

// Every path any lightpath integrator can emit: the camera, then reflections and transmissions
// (D, G, S, s; never a volume event V), then a light, an emitting object or the background.
inline constexpr const char* kRenderedPaths = "E<[RT][DGSs]>*[LOB]";

}  // namespace lightpath
