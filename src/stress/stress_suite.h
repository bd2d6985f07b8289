#pragma once
#include <vector>

#include "stress/scorecard.h"

namespace lightpath {

// Every row of the numerical stress suite, robust and naive side by side, with fixed seeds.
std::vector<ScoreRow> runStressSuite(const StressConfig& config);

}  // namespace lightpath
