#pragma once
// What the page can change: the integrator and its parameters, the progressive render's sample
// target, the resolution, the depth and the list of LPEs: a subset of the render configuration
// (config/render_config.h) in JSON. Parsed from PUT /api/settings (docs/serve.md), each field's
// type and range read from the render options' schema and narrowed by the session's limits below,
// then checked by the configuration's one validate() before anything is rendered.
#include <nlohmann/json.hpp>

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "config/render_config.h"
#include "lpe/automaton.h"
#include "scene/scene.h"
#include "serve/request_error.h"

namespace lightpath::serve {

// Bounds on one session's work: each side at most kMaxSide pixels, at most kMaxPixelLayers
// pixels times layers (beauty, AOVs, rest: 200 MB of RGB floats per image the session holds), at
// most kMaxSamples samples per pixel.
inline constexpr int kMaxSide = 4096;
inline constexpr std::int64_t kMaxPixelLayers = std::int64_t{2048} * 2048 * 4;
inline constexpr int kMaxSamples = 4096;
inline constexpr std::size_t kMaxExpressions = 16;
inline constexpr std::size_t kMaxExpressionLength = 400;

struct Settings {
    std::string integrator = "whitted";
    int samplesPerPixel = 16;  // the progressive render stops here
    int width = 0, height = 0;
    int maxDepth = 5;
    std::vector<lpe::NamedExpression> lpes;
    // The integrators' own parameters given (integrators/registry.h schemas), by name, as text:
    // those of the chosen integrator reach it, as `--NAME` does on the command line.
    std::map<std::string, std::string, std::less<>> parameters;

    bool operator==(const Settings& other) const;
};

// The scene's resolution and the `classes` set.
Settings defaultSettings(const Scene& scene);

// `current` with the fields of `body` (a JSON object; absent fields keep their value) applied.
// Throws RequestError (400) for malformed JSON, an unknown field, a wrong type or a value out of
// range, naming the field and what was expected. A value that an integrator cannot use but has one
// answer for (spp for the rasteriser, which samples pixel centres) is replaced, and `notices`
// (when given) says so.
Settings applySettings(const Settings& current, const std::string& body,
                       std::vector<std::string>* notices = nullptr);

nlohmann::json toJson(const Settings& settings);

// Every integrator's parameters as the page builds its controls from them: name, type, unit,
// default, range, choices, doc and what each excludes (the integrators' schemas).
nlohmann::json integratorParametersJson();

// The render configuration of `settings` on the scene file `scenePath`: no preset but the lpes,
// quiet (warnings are collected for the page).
RenderConfig renderConfig(const Settings& settings, const std::string& scenePath);

// A ConfigError as a 400 naming its field as the JSON spells it ("maxDepth", "lpes[1].expression",
// "width,height" for the resolution, "parameters.NAME" for an integrator's parameter), read from ConfigError::field(); its message after that field's
// label ("spp: ...", the AOV's name for an expression).
RequestError requestError(const ConfigError& error, const Settings& settings);

}  // namespace lightpath::serve
