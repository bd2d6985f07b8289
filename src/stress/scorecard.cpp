#include "stress/scorecard.h"

#include <cstdio>
#include <sstream>

#include "io/text_file.h"

namespace lightpath {
namespace {

std::string formatValue(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.4g", v);
    return buffer;
}

std::string verdict(const ScoreRow& r) {
    if (r.atTarget()) return "ok";
    return r.method == "robust" ? "FAIL" : "fails";
}

}  // namespace

void printScorecard(const std::vector<ScoreRow>& rows, const std::string& header) {
    std::printf("%s\n\n", header.c_str());
    std::printf("%-18s %-14s %-6s %-37s %10s %7s %-6s %s\n", "row", "method", "prec", "metric", "value", "target",
                "", "detail");
    for (const ScoreRow& r : rows)
        std::printf("%-18s %-14s %-6s %-37s %10s %7s %-6s %s\n", r.row.c_str(), r.method.c_str(),
                    r.precision.c_str(), r.metric.c_str(), formatValue(r.value).c_str(),
                    formatValue(r.target).c_str(), verdict(r).c_str(), r.detail.c_str());
    std::printf("\nrobust rows at target: %s\n", robustRowsAtTarget(rows) ? "all" : "NOT ALL");
}

std::string scorecardJson(const std::vector<ScoreRow>& rows) {
    std::ostringstream json;
    json.precision(9);
    json << "[\n";
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const ScoreRow& r = rows[i];
        json << "  {\"row\": " << jsonString(r.row) << ", \"method\": " << jsonString(r.method)
             << ", \"precision\": " << jsonString(r.precision) << ", \"metric\": " << jsonString(r.metric)
             << ", \"value\": " << r.value << ", \"target\": " << r.target
             << ", \"detail\": " << jsonString(r.detail) << "}" << (i + 1 < rows.size() ? "," : "") << "\n";
    }
    json << "]\n";
    return json.str();
}

bool robustRowsAtTarget(const std::vector<ScoreRow>& rows) {
    for (const ScoreRow& r : rows)
        if (r.method == "robust" && !r.atTarget()) return false;
    return true;
}

}  // namespace lightpath
