#pragma once
#include <vector>

#include "stress/scorecard.h"

namespace lightpath {

// BVH = brute force: the accelerated closest hit (t and primitive) against the lecture's loop.
void runBvhRow(const StressConfig& config, std::vector<ScoreRow>& rows);

}  // namespace lightpath
