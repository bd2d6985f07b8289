// Set analysis: overlaps and gaps decided on the automaton, each example checked independently
// with std::regex on its compact string and its length against a value worked out by hand.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdint>
#include <regex>
#include <string>
#include <vector>

#include "lpe/analysis.h"
#include "lpe/path_string.h"
#include "test_paths.h"

using lpe_test::allStrings;

namespace {

// An LPE of compact letters (E D G S L, sets, operators) as ECMAScript over compact strings, in
// which a background event prints B and an emitting object O: the bare L of an LPE also matches
// them, the L of a set (OSL's) does not.
std::regex reference(const std::string& expression) {
    std::string text;
    bool inSet = false;
    for (const char c : expression) {
        if (c == '[') inSet = true;
        if (c == ']') inSet = false;
        text += c == 'L' && !inSet ? "[LBO]" : std::string(1, c);
    }
    return std::regex(text, std::regex::ECMAScript);
}

// The renderer's `classes` and the lecture's taxonomy (src/film/aov_presets.cpp), written out:
// this suite links the engine only.
const std::vector<lpe::NamedExpression> kClasses = {
    {"raycast", "E(D|G)L"}, {"raytrace", "ES+(D|G)L"}, {"mirror", "ES+L"}, {"emission", "EL"},
    {"indirect", "ES*(D|G)(D|G|S)+L"},
};
const std::vector<lpe::NamedExpression> kTaxonomy = {
    {"raycasting", "E(D|G)L"}, {"raytracing", "E(S*)(D|G)L"}, {"radiosity", "ED*L"}, {"pathtracing", "E(D|G|S)*L"},
};

bool regexAccepts(const std::string& expression, const lpe::Path& path) {
    return std::regex_match(lpe::toCompactString(path), reference(expression));
}


}  // namespace

TEST_CASE("the default AOV set partitions E(D|G|S)*L") {
    const auto& classes = kClasses;
    REQUIRE(classes.size() == 5);
    CHECK(classes[0].name == "raycast");
    CHECK(classes[4].name == "indirect");
    const lpe::SetReport report = lpe::analyse(classes, "E(D|G|S)*L");
    CHECK(report.overlaps.empty());
    CHECK_FALSE(report.gap.has_value());
    CHECK(report.partition());

    // Independently: every string of the universe up to length 7 is accepted by exactly one.
    const std::regex universe("E[DGS]*L");
    for (const std::string& path : allStrings("EDGSL", 7)) {
        if (!std::regex_match(path, universe)) continue;
        int accepting = 0;
        for (const auto& e : classes) accepting += std::regex_match(path, reference(e.expression));
        CAPTURE(path);
        CHECK(accepting == 1);
    }
}

TEST_CASE("the default AOV set leaves a real gap in E.*L") {
    const lpe::SetReport report = lpe::analyse(kClasses, "E.*L");
    CHECK(report.overlaps.empty());
    REQUIRE(report.gap.has_value());
    CHECK_FALSE(report.partition());
    const lpe::Path& gap = *report.gap;
    CAPTURE(lpe::toTupleString(gap));
    CHECK(regexAccepts("E.*L", gap));
    for (const auto& e : kClasses) CHECK_FALSE(regexAccepts(e.expression, gap));
    // EL is emission and E(D|G|S)L are raycast or mirror: the gap needs an event that does not
    // scatter D, G or S, so the shortest has three events (ESL-shaped, e.g. E s L).
    CHECK(gap.size() == 3);
}

TEST_CASE("an overlapping pair is reported with a shortest example both accept") {
    const lpe::SetReport report = lpe::analyse({{"everything", "E.*L"}, {"diffuse", "ED+L"}});
    REQUIRE(report.overlaps.size() == 1);
    const lpe::Overlap& overlap = report.overlaps.front();
    CHECK(overlap.first == 0);
    CHECK(overlap.second == 1);
    CHECK(regexAccepts("E.*L", overlap.example));
    CHECK(regexAccepts("ED+L", overlap.example));
    CHECK(overlap.example.size() == 3);  // EDL: ED+L has nothing shorter
    CHECK(lpe::toCompactString(overlap.example) == "EDL");
    CHECK_FALSE(report.gap.has_value());  // E.*L covers its own universe
    CHECK_FALSE(report.partition());
}

TEST_CASE("the lecture taxonomy overlaps pairwise, with hand-checked shortest examples") {
    const auto& taxonomy = kTaxonomy;
    REQUIRE(taxonomy.size() == 4);
    const lpe::SetReport report = lpe::analyse(taxonomy);
    // Every pair overlaps: ray casting's EDL is also ray tracing, radiosity and path tracing;
    // radiosity and path tracing share EL, which is shorter.
    REQUIRE(report.overlaps.size() == 6);
    for (const lpe::Overlap& o : report.overlaps) {
        const std::string& a = taxonomy[o.first].expression;
        const std::string& b = taxonomy[o.second].expression;
        CAPTURE(a);
        CAPTURE(b);
        CHECK(regexAccepts(a, o.example));
        CHECK(regexAccepts(b, o.example));
        CHECK(regexAccepts("E.*L", o.example));
        const bool radiosityAndPathTracing = taxonomy[o.first].name == "radiosity" && taxonomy[o.second].name == "pathtracing";
        CHECK(o.example.size() == (radiosityAndPathTracing ? 2u : 3u));
    }
    REQUIRE(report.gap.has_value());
    CHECK(report.gap->size() == 3);
    CHECK(regexAccepts("E.*L", *report.gap));
    for (const auto& e : taxonomy) CHECK_FALSE(regexAccepts(e.expression, *report.gap));
}

TEST_CASE("gap examples are real and shortest") {
    // ED*L misses every glossy path of E(D|G)*L; the shortest is EGL.
    const lpe::SetReport report = lpe::analyse({{"radiosity", "ED*L"}}, "E(D|G)*L");
    REQUIRE(report.gap.has_value());
    CHECK(lpe::toCompactString(*report.gap) == "EGL");
    CHECK(regexAccepts("E(D|G)*L", *report.gap));
    CHECK_FALSE(regexAccepts("ED*L", *report.gap));

    // Two disjoint expressions leaving long paths out: the gap has five events (EDDDL).
    const lpe::SetReport longer = lpe::analyse({{"short", "ED{0,2}L"}, {"long", "ED{4,}L"}}, "ED*L");
    CHECK(longer.overlaps.empty());
    REQUIRE(longer.gap.has_value());
    CHECK(lpe::toCompactString(*longer.gap) == "EDDDL");
}

TEST_CASE("analysis agrees with brute force over all short compact paths") {
    const std::vector<std::vector<lpe::NamedExpression>> sets = {
        {{"a", "E(D|G)L"}, {"b", "ES+L"}, {"c", "E.D.L"}},
        {{"a", "E[^S]*L"}, {"b", "E.*S.*L"}},
        {{"a", "ED?L"}, {"b", "E(GS)+L"}, {"c", "E(D|S){2}L"}},
        {{"a", "E(S|G)*DL"}, {"b", "E.{2}L"}},
    };
    const std::vector<std::string> paths = allStrings("EDGSsLB", 5);
    for (const auto& set : sets) {
        const std::string universe = "E.*L";
        const lpe::SetReport report = lpe::analyse(set, universe);
        const std::regex universeReference = reference(universe);
        std::vector<std::regex> references;
        for (const auto& e : set) references.push_back(reference(e.expression));
        // Brute force: the shortest gap and the shortest overlap of each pair among these paths.
        std::size_t gap = SIZE_MAX;
        std::vector<std::vector<std::size_t>> overlap(set.size(), std::vector<std::size_t>(set.size(), SIZE_MAX));
        for (const std::string& path : paths) {
            if (!std::regex_match(path, universeReference)) continue;
            std::vector<bool> accepted;
            bool any = false;
            for (const std::regex& r : references) {
                accepted.push_back(std::regex_match(path, r));
                any = any || accepted.back();
            }
            if (!any) gap = std::min(gap, path.size());
            for (std::size_t i = 0; i < set.size(); ++i) {
                for (std::size_t j = i + 1; j < set.size(); ++j) {
                    if (accepted[i] && accepted[j]) overlap[i][j] = std::min(overlap[i][j], path.size());
                }
            }
        }
        // Beyond the enumerated length brute force sees nothing, so longer examples count as none.
        const auto seen = [&](std::size_t length) { return length <= 5 ? length : SIZE_MAX; };
        CAPTURE(set.front().expression);
        CHECK(seen(report.gap ? report.gap->size() : SIZE_MAX) == gap);
        for (std::size_t i = 0; i < set.size(); ++i) {
            for (std::size_t j = i + 1; j < set.size(); ++j) {
                std::size_t found = SIZE_MAX;
                for (const lpe::Overlap& o : report.overlaps) {
                    if (o.first == i && o.second == j) found = o.example.size();
                }
                CAPTURE(i);
                CAPTURE(j);
                CHECK(seen(found) == overlap[i][j]);
            }
        }
    }
}
