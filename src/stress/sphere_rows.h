#pragma once
#include <vector>

#include "stress/scorecard.h"

namespace lightpath {

// sphere silhouette, sphere t, sphere spawn: the stable quadratic against b^2 - 4ac, and robust
// spawning against a fixed epsilon, each checked against long-double references.
void runSphereRows(const StressConfig& config, std::vector<ScoreRow>& rows);

}  // namespace lightpath
