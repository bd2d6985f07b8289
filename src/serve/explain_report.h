#pragma once
// The JSON of GET /api/explain: every contribution to one pixel, as `lightpath explain` lists
// them, with what the page draws: each path's vertices in world space and projected onto the
// image, and the automaton states the path went through.
#include <nlohmann/json.hpp>

#include <atomic>

#include "serve/session.h"

namespace lightpath::serve {

// Throws RequestError (400) for a pixel outside the job's image, ExplainCancelled once `cancel` is set
// (Session::startExplaining).
nlohmann::json explainPixel(const Job& job, int x, int y, const std::atomic<bool>* cancel = nullptr);

}  // namespace lightpath::serve
