// Every light case (cases.cpp) through every light check (light_checks.h).
#include <doctest/doctest.h>

#include "light_checks.h"

namespace lightpath::conformance {
namespace {

template <typename Check>
void forEveryLight(Check&& check) {
    int lights = 0;
    forEachLightCase([&](const LightCase& c) {
        const LightWorld world(c.scene);
        REQUIRE(!world.lights.all().empty());
        for (const auto& light : world.lights.all()) {
            ++lights;
            const CheckResult result = check(*light, world, c);
            INFO(c.name << ":\n" << result.failures);
            CHECK(result.passed);
        }
    });
    CHECK(lights > 0);
}

TEST_CASE("lights: pdf() integrates to 1 over the light and sample() draws with it" * doctest::test_suite("statistical")) {
    forEveryLight([](const Light& light, const LightWorld& world, const LightCase&) {
        CheckResult result;
        if (!light.isDelta())
            for (const Vec3& receiver : receiversOf(light)) result.merge(checkLightDensity(light, world, receiver));
        return result;
    });
}

TEST_CASE("lights: every sample's weight is radiance / pdf, its pdf is pdf(), and it is finite") {
    forEveryLight([](const Light& light, const LightWorld& world, const LightCase&) {
        CheckResult result;
        for (const Vec3& receiver : receiversOf(light)) result.merge(checkLightSamples(light, world, receiver));
        if (light.isDelta()) result.merge(checkDeltaLightIntensity(light));
        return result;
    });
}

TEST_CASE("lights: power() is the flux sampleEmission() estimates") {
    forEveryLight([](const Light& light, const LightWorld&, const LightCase&) { return checkLightPower(light); });
}

TEST_CASE("lights: light walks aimed at targets (emitAlong) estimate the same flux, with the mixture's density") {
    forEveryLight([](const Light& light, const LightWorld&, const LightCase&) { return checkAimedEmission(light); });
}

}  // namespace
}  // namespace lightpath::conformance
