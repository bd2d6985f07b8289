#pragma once
// Emitters against closed-form irradiance (issue #28): sphere lights from radius 1e-12 to 1e6,
// sliver triangle lights, and a receiver 1e-7 from a sphere light's surface. Robust: the
// lights' own sampling (AreaLightSource); naive: the former uniform-by-area sampling in float.
#include <vector>

#include "stress/scorecard.h"

namespace lightpath {

void runEmitterRows(const StressConfig& config, std::vector<ScoreRow>& rows);

}  // namespace lightpath
