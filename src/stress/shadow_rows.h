#pragma once
#include <vector>

#include "stress/scorecard.h"

namespace lightpath {

// acne sweep and contact shadows: shadow rays from a tilted floor at scene scales 1e-4 .. 1e6.
void runShadowRows(const StressConfig& config, std::vector<ScoreRow>& rows);

}  // namespace lightpath
