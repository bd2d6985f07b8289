// Every material case (cases.cpp) through every material check (material_checks.h).
#include <doctest/doctest.h>

#include <vector>

#include "material_checks.h"

namespace lightpath::conformance {
namespace {

// The indices of the material's smooth lobes that scatter something.
std::vector<int> presentSmoothLobes(const Material& material) {
    std::vector<int> present;
    for (int l = 0; l < int(material.lobes().size()); ++l)
        if (!material.lobes()[l].delta() && material.has(l)) present.push_back(l);
    return present;
}

// Runs `check` over every case, each failure reported with the case's name.
template <typename Check>
void forEveryMaterial(Check&& check) {
    int cases = 0;
    forEachMaterialCase([&](const MaterialCase& c) {
        ++cases;
        const CheckResult result = check(c);
        INFO(c.name << ":\n" << result.failures);
        CHECK(result.passed);
    });
    CHECK(cases > 0);
}

// Statistical: a chi-square over every material, lobe and direction. The sanitizer stage runs the
// same sample() through the weight check below.
TEST_CASE("materials: sample() follows pdf() in every smooth lobe (chi-square)" * doctest::test_suite("statistical")) {
    forEveryMaterial([](const MaterialCase& c) {
        CheckResult result;
        for (const int lobe : presentSmoothLobes(*c.material))
            for (const Vec3& wo : outgoingDirections()) result.merge(checkSamplingMatchesPdf(*c.material, lobe, wo));
        return result;
    });
}

TEST_CASE("materials: every sample's weight is eval / pdf, per lobe and through the Bsdf") {
    forEveryMaterial([](const MaterialCase& c) {
        CheckResult result;
        for (const Vec3& wo : outgoingDirections()) result.merge(checkSampleWeights(*c.material, wo));
        return result;
    });
}

TEST_CASE("materials: the Bsdf's one-sample estimate is unbiased (delta branches included)" * doctest::test_suite("statistical")) {
    forEveryMaterial([](const MaterialCase& c) {
        CheckResult result;
        for (const Vec3& wo : outgoingDirections())
            for (const bool entering : {true, false}) result.merge(checkBsdfUnbiased(*c.material, wo, entering));
        return result;
    });
}

TEST_CASE("materials: reciprocal lobes are reciprocal where the type claims it") {
    forEveryMaterial([](const MaterialCase& c) {
        CheckResult result;
        for (const int lobe : presentSmoothLobes(*c.material))
            if (c.claims.reciprocal[lobe]) result.merge(checkReciprocity(*c.material, lobe));
        return result;
    });
}

TEST_CASE("materials: white furnace <= 1 where energy conservation is claimed and albedo() near each lobe's reflectance" * doctest::test_suite("statistical")) {
    forEveryMaterial([](const MaterialCase& c) {
        CheckResult result;
        if (c.claims.conservesEnergy) result.merge(checkEnergyConservation(*c.material));
        for (const int lobe : presentSmoothLobes(*c.material)) result.merge(checkLobeAlbedo(*c.material, lobe));
        return result;
    });
}

TEST_CASE("materials: finite, non-negative values everywhere, delta branches in the right directions") {
    forEveryMaterial([](const MaterialCase& c) {
        CheckResult result = checkFiniteNonNegative(*c.material);
        result.merge(checkSpecularBranches(*c.material));
        result.merge(checkDeclaredLobes(*c.material, c.claims.events));
        return result;
    });
}

}  // namespace
}  // namespace lightpath::conformance
