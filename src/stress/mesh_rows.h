#pragma once
#include <vector>

#include "stress/scorecard.h"

namespace lightpath {

// watertight mesh: rays into a closed mesh, many aimed exactly at its vertices and edges.
void runMeshRows(const StressConfig& config, std::vector<ScoreRow>& rows);

}  // namespace lightpath
