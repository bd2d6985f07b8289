#pragma once
// The stress suite's result: one row per (check, method), each a measured value against the
// issue's target in float. Robust rows must meet their target; naive rows show what fails.
#include <filesystem>
#include <string>
#include <vector>

namespace lightpath {

struct ScoreRow {
    std::string row;        // "sphere silhouette"
    std::string method;     // "robust" or "naive"
    std::string precision;  // arithmetic of the rays and primitives: "float"
    std::string metric;     // what value counts, with its unit
    double value = 0.0;
    double target = 0.0;    // value <= target is at target
    std::string detail;     // the value per scale or per case, for the lecture

    bool atTarget() const { return value <= target; }
};

struct StressConfig {
    bool quick = false;  // fewer rays and scales, for CI
};

// Prints the table; a robust row above target is marked FAIL, a naive row above it "fails".
void printScorecard(const std::vector<ScoreRow>& rows, const std::string& header);

// [{"row", "method", "precision", "metric", "value", "target", "detail"}, ...]
std::string scorecardJson(const std::vector<ScoreRow>& rows);

// True when every robust row is at target.
bool robustRowsAtTarget(const std::vector<ScoreRow>& rows);

}  // namespace lightpath
