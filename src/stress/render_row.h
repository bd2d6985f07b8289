#pragma once
#include <vector>

#include "stress/scorecard.h"

namespace lightpath {

// render-level acne: a Cornell-style room rendered at scales 1e-3 .. 1e5 against scale 1.
void runRenderRow(const StressConfig& config, std::vector<ScoreRow>& rows);

}  // namespace lightpath
