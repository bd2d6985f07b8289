// Every integrator of the registry (integrators(), src/integrators/registry.h) through every
// integrator check (integrator_checks.h).
#include <doctest/doctest.h>

#include "cases.h"
#include "integrator_checks.h"

namespace lightpath::conformance {
namespace {

template <typename Check>
void forEveryIntegrator(Check&& check) {
    REQUIRE(!integrators().empty());
    for (const IntegratorInfo& integrator : integrators()) {
        const CheckResult result = check(integrator);
        INFO(std::string(integrator.name) << ":\n" << result.failures);
        CHECK(result.passed);
    }
}

TEST_CASE("integrators: the classes AOVs sum to the beauty and rest is zero") {
    const Scene scene = integratorScene();
    forEveryIntegrator([&](const IntegratorInfo& i) { return checkAovsSumToBeauty(i, scene); });
}

TEST_CASE("integrators: images are bit-identical for 1 and 3 threads") {
    const Scene scene = integratorScene();
    forEveryIntegrator([&](const IntegratorInfo& i) { return checkThreadDeterminism(i, scene); });
}

TEST_CASE("integrators: an AOV requested alone is bit-identical to the same AOV in the full render") {
    const Scene scene = integratorScene();
    forEveryIntegrator([&](const IntegratorInfo& i) { return checkSkipIdentity(i, scene); });
}

// Welch's test at kAgreementAlpha on image means of independent renders; the control renders the
// integrator's scene 5% brighter than its allowance and must be rejected at the same level.
TEST_CASE("integrators: the light on the paths shared with the path tracer is the path tracer's and 5% more is not" * doctest::test_suite("statistical")) {
    const Scene scene = agreementScene();
    for (const IntegratorInfo& integrator : integrators()) {
        const Scene control = brighter(agreementScene(), float(1.05 + agreementAllowance(integrator)));
        if (std::string_view(integrator.name) == "path") continue;  // the reference itself
        const std::string name = integrator.name;
        CAPTURE(name);
        const Agreements agreements = agreementsWithPath(integrator, scene, control);
        const Agreement &same = agreements.same, &off = agreements.control;
        CAPTURE(same.mean);
        CAPTURE(same.pathMean);
        CAPTURE(same.pValue);
        CHECK(same.pValue > kAgreementAlpha);
        CAPTURE(off.mean);
        CAPTURE(off.pValue);
        CHECK(off.pValue < kAgreementAlpha);
    }
}

TEST_CASE("integrators: an empty scene, a light alone and a camera inside a sphere render finite and right") {
    forEveryIntegrator([](const IntegratorInfo& i) { return checkDegenerateScenes(i); });
}

}  // namespace
}  // namespace lightpath::conformance
