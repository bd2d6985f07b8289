#pragma once
// Every integrator in one table: its name, what it does, and the light paths it can produce (its
// path language, an LPE). Each integrator's .cpp registers its own row (LIGHTPATH_REGISTER_INTEGRATOR);
// the table lists them by rank, the lecture's order. The command line's --integrator choices, their did-you-mean and
// makeIntegrator read this table; `lpe check --integrator` and the refusal of AOVs no integrator
// path can reach read the languages.
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "integrators/integrator.h"
#include "schema/registry.h"
#include "schema/type_schema.h"

namespace lightpath {

// Whether an integrator's direct light may skip its shadow rays (`--shadows off`).
enum class ShadowRays : std::uint8_t {
    Always,    // light its scattered rays find is blocked like any ray: without shadow rays it would
               // be counted unblocked once and blocked once (path, bdpt, radiosity)
    Optional,  // Szymczak's formula, whose shadow term can be set to 1 (raycast, whitted)
    Never,     // no rays to cast (the rasteriser)
};

// A point light is reached only by a shadow ray from a diffuse or glossy vertex.
inline constexpr const char* kReachedByShadowRays = "E.*(D|G)L";

struct IntegratorInfo {
    const char* name;
    const char* summary;       // one line for --help
    const char* pathLanguage;  // every path it can emit, as an LPE (bare L: any emitter)
    // Why a path outside pathLanguage is out of reach, for messages: "ray casting follows ...".
    const char* limitation;
    std::unique_ptr<Integrator> (*make)();
    ShadowRays shadowRays = ShadowRays::Always;
    // The same name, summary and path language (as its events), and the integrator's own parameters:
    // each is a flag of render and explain (--NAME) and a key of `lightpath types integrator`.
    TypeSchema schema;
    int rank = 0;  // listing order; rank 0 is the default
    // Whether it renders participating media (src/media/): a scene with media is refused under an
    // integrator that would show it as in vacuum (RenderConfig::judge).
    bool rendersMedia = false;
    // The paths it can produce when every light is a point light (a delta in position, which no
    // ray can hit), within pathLanguage: by default only those whose last event before the light
    // is diffuse or glossy, where a shadow ray finds the light (next-event estimation). Methods
    // that walk from the lights say more (bdpt, photon).
    const char* pointLightLanguage = kReachedByShadowRays;
};

using IntegratorRegistry = TypeRegistry<IntegratorInfo>;

// A row whose schema repeats its name, summary and path language, with the integrator's parameters
// (read in preprocess from RenderContext::parameters).
inline IntegratorInfo integratorRow(const char* name, const char* summary, const char* pathLanguage,
                                    const char* limitation, std::unique_ptr<Integrator> (*make)(),
                                    ShadowRays shadowRays, int rank, std::vector<Parameter> parameters = {}) {
    return {name,       summary,
            pathLanguage, limitation,
            make,       shadowRays,
            TypeSchema{"integrator", name, summary, std::move(parameters), pathLanguage},
            rank};
}

// The row, marked as rendering participating media.
inline IntegratorInfo rendersMedia(IntegratorInfo row) {
    row.rendersMedia = true;
    return row;
}

// The row, with the paths it produces under point lights alone.
inline IntegratorInfo underPointLights(IntegratorInfo row, const char* language) {
    row.pointLightLanguage = language;
    return row;
}

// Every registered integrator, by rank.
const std::vector<IntegratorInfo>& integrators();
const IntegratorInfo* findIntegrator(std::string_view name);
std::vector<std::string> integratorNames();
// The integrators that render participating media, by rank: "raycast, whitted, path".
std::string mediaRenderers();

// Every path any lightpath integrator can emit in a scene without media: the camera, then
// reflections and transmissions (D, G, S, s), then a light, an emitting object or the background.
// With media raycast, whitted and path add volume events V (config/lpe_feasibility.h, kPathsWithVolumes).
inline constexpr const char* kRenderedPaths = "E<[RT][DGSs]>*[LOB]";

}  // namespace lightpath

#define LIGHTPATH_REGISTER_INTEGRATOR(...) \
    namespace { const ::lightpath::Registrar<::lightpath::IntegratorInfo> LIGHTPATH_SCHEMA_CONCAT(kIntegratorRegistrar, __COUNTER__){__VA_ARGS__}; }
