#pragma once
#include <vector>

#include "stress/scorecard.h"

namespace lightpath {

// non-finite: TIR, degenerate triangles, zero-length normals, zero direction components and NaN
// rays must leave no NaN or Inf in a pixel or a hit.
void runNonFiniteRow(const StressConfig& config, std::vector<ScoreRow>& rows);

}  // namespace lightpath
