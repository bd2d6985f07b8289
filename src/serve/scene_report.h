#pragma once
// The JSON of GET /api/scene: what the page needs to know about the scene once — its camera, its
// objects' bounds and planes and its lights for the top view, the integrators, the limits, and
// the ready-made LPE sets a lecturer switches between.
#include <nlohmann/json.hpp>

#include "lpe/automaton.h"
#include "scene/scene.h"

namespace lightpath::serve {

// The presets offered by the page: the command line's (classes, taxonomy: film/aov_presets.h), one
// AOV per light, and one per number of bounces.
std::vector<std::pair<std::string, std::vector<lpe::NamedExpression>>> presets(const Scene& scene);

nlohmann::json describeScene(const Scene& scene, const std::string& scenePath);

}  // namespace lightpath::serve
