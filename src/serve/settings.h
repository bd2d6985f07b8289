#pragma once
// What the page can change: the integrator, the progressive render's sample target, the
// resolution, the depth and the list of LPEs. Parsed from the JSON of PUT /api/settings
// (docs/serve.md) and checked against the limits below before anything is rendered.
#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

#include "lpe/automaton.h"
#include "scene/scene.h"

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

}  // namespace lightpath::serve
