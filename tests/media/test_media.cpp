// The medium interface against closed forms: the Henyey-Greenstein phase function's sampling
// (chi-square, as Nori's warptest), its normalisation and mean cosine, Beer-Lambert
// transmittance, and the free-flight sampling's estimators (pbrt-v4 14.2) unbiased.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "media/henyey_greenstein.h"
#include "media/homogeneous_medium.h"
#include "media/medium_type.h"
#include "sampling/warp.h"
#include "schema/schema_error.h"
#include "../support/direction_chi_square.h"
#include "../support/statistics.h"
#include "../support/uniform_real.h"

namespace lightpath {
namespace {

// Per test, as the conformance kit's kMaterialAlpha.
constexpr double kAlpha = 1e-4;

// p-value that `sampling`'s directions follow `density`'s eval from wo.
double phaseChiSquarePValue(const HenyeyGreensteinPhase& sampling, const HenyeyGreensteinPhase& density, const Vec3& wo) {
    test::DirectionHistogram histogram;
    // A strongly peaked lobe (g = 0.9) varies 100-fold over 1/8 in cos theta: narrow bins, fine integration.
    histogram.cosBins = 64;
    histogram.subdivisions = 48;
    test::UniformReal<float> uniform(0.0f, 1.0f);
    return test::directionChiSquarePValue(
        histogram,
        [&](std::mt19937_64& rng) -> std::optional<Vec3> {
            const Vec2 u{uniform(rng), uniform(rng)};
            return sampling.sample(wo, u).wi;
        },
        [&](const Vec3& wi) { return double(density.pdf(wo, wi)); });
}

const Vec3 kOutgoing[] = {{0, 0, 1}, glm::normalize(Vec3{0.6f, -0.3f, -0.5f})};

TEST_CASE("chi-square: Henyey-Greenstein sampling follows its density for g in {-0.7, 0, 0.3, 0.9}") {
    for (const float g : {-0.7f, 0.0f, 0.3f, 0.9f}) {
        for (const Vec3& wo : kOutgoing) {
            CAPTURE(g);
            CAPTURE(wo.z);
            const HenyeyGreensteinPhase phase(g);
            CHECK(phaseChiSquarePValue(phase, phase, wo) > kAlpha);
        }
    }
}

TEST_CASE("chi-square control: sampling g = 0.3 against the density of g = 0.36 is rejected") {
    CHECK(phaseChiSquarePValue(HenyeyGreensteinPhase(0.3f), HenyeyGreensteinPhase(0.36f), kOutgoing[0]) < kAlpha);
}

TEST_CASE("Henyey-Greenstein integrates to 1 over the sphere, with mean cosine -g to wo") {
    // Midpoint rule in (cos theta, phi) about an oblique wo, in double: the test's own quadrature.
    const Vec3 wo = kOutgoing[1];
    const Frame frame(glm::normalize(Vec3{0.2f, 0.9f, 0.1f}));
    constexpr int kCos = 4000, kPhi = 64;
    for (const float g : {-0.9f, -0.7f, 0.0f, 0.3f, 0.9f}) {
        CAPTURE(g);
        const HenyeyGreensteinPhase phase(g);
        double integral = 0.0, meanCosine = 0.0;
        for (int i = 0; i < kCos; ++i) {
            const double z = -1.0 + 2.0 * (i + 0.5) / kCos, r = std::sqrt(1.0 - z * z);
            for (int j = 0; j < kPhi; ++j) {
                const double phi = 2.0 * M_PI * (j + 0.5) / kPhi;
                const Vec3 wi = frame.toWorld(Vec3{float(r * std::cos(phi)), float(r * std::sin(phi)), float(z)});
                const double dw = (2.0 / kCos) * (2.0 * M_PI / kPhi);
                integral += phase.eval(wo, wi) * dw;
                meanCosine += phase.eval(wo, wi) * glm::dot(wo, wi) * dw;
            }
        }
        CHECK(integral == doctest::Approx(1.0).epsilon(2e-3));
        // wo points back along the path: forward scattering (g > 0) leaves towards -wo.
        CHECK(meanCosine == doctest::Approx(-g).epsilon(2e-3).scale(1.0));
    }
}

TEST_CASE("isotropic Henyey-Greenstein is 1 / (4 pi), its samples' pdf is its value") {
    const HenyeyGreensteinPhase isotropic(0.0f);
    CHECK(isotropic.eval({0, 0, 1}, {1, 0, 0}) == doctest::Approx(1.0 / (4.0 * M_PI)));
    const HenyeyGreensteinPhase forward(0.6f);
    const Vec3 wo = kOutgoing[1];
    for (const Vec2 u : {Vec2{0.1f, 0.2f}, Vec2{0.5f, 0.9f}, Vec2{0.97f, 0.4f}}) {
        const PhaseSample s = forward.sample(wo, u);
        CHECK(glm::length(s.wi) == doctest::Approx(1.0f));
        CHECK(s.pdf == doctest::Approx(forward.eval(wo, s.wi)).epsilon(1e-4));
    }
}

HomogeneousMedium medium(Rgb sigmaA, Rgb sigmaS, float g = 0.0f) {
    HomogeneousMedium m;
    m.sigmaA = sigmaA;
    m.sigmaS = sigmaS;
    m.g = g;
    return m;
}

TEST_CASE("homogeneous transmittance is exp(-sigma_t d) per channel (Beer-Lambert)") {
    const HomogeneousMedium m = medium({0.1f, 0.2f, 0.0f}, {0.3f, 0.0f, 0.5f});
    const Ray ray{{1, 2, 3}, {0, 0, 1}};
    // sigma_t = (0.4, 0.2, 0.5), d = 2.
    const Rgb t = m.transmittance(ray, 1.0f, 3.0f);
    CHECK(t.r == doctest::Approx(std::exp(-0.8)));
    CHECK(t.g == doctest::Approx(std::exp(-0.4)));
    CHECK(t.b == doctest::Approx(std::exp(-1.0)));
    CHECK(m.transmittance(ray, 2.0f, 2.0f) == Rgb{1.0f});
    // A channel that neither absorbs nor scatters transmits everything, even to infinity.
    const Rgb far = medium({0.0f, 0.1f, 0.0f}, {0.0f, 0.0f, 0.2f}).transmittance(ray, 0.0f, INFINITY);
    CHECK(far == Rgb{1.0f, 0.0f, 0.0f});
}

// A grey sigma_t takes one exp for its three channels (beerLambert): the same bits as exp per
// channel; and a free flight through it reads no channel choice (choosesChannel), which the path
// tracer then does not draw. The control: a coloured sigma_t's flight does depend on the choice.
TEST_CASE("a grey medium's transmittance is exp(-sigma_t d) in every channel and its flights ignore the channel") {
    const HomogeneousMedium grey = medium(Rgb{0.01f}, Rgb{0.06f}), coloured = medium(Rgb{0.1f}, {1.0f, 0.9f, 0.8f});
    const Ray ray{{1, 2, 3}, {0, 0, 1}};
    for (const float d : {0.5f, 2.0f, 37.0f}) {
        const float sigma = 0.01f + 0.06f;
        CHECK(grey.transmittance(ray, 0.0f, d) == Rgb{std::exp(-sigma * d)});
    }
    CHECK(!grey.choosesChannel());
    CHECK(coloured.choosesChannel());
    CHECK(!medium(Rgb{0.1f, 0.2f, 0.3f}, Rgb{0.0f}).choosesChannel());  // scatters nothing: draws no distance
    int colouredDiffers = 0;
    for (const float uDistance : {0.05f, 0.3f, 0.6f, 0.9f}) {
        for (const float tMax : {1.0f, 10.0f, INFINITY}) {
            const MediumSample first = grey.sampleDistance(ray, tMax, 0.0f, uDistance);
            for (const float uChannel : {0.4f, 0.9f}) {
                const MediumSample other = grey.sampleDistance(ray, tMax, uChannel, uDistance);
                CHECK(other.scattered == first.scattered);
                CHECK(other.t == first.t);
                CHECK(other.weight == first.weight);
                colouredDiffers += coloured.sampleDistance(ray, tMax, uChannel, uDistance).t !=
                                   coloured.sampleDistance(ray, tMax, 0.0f, uDistance).t;
            }
        }
    }
    CHECK(colouredDiffers > 0);
}

struct FlightCase {
    const char* name;
    HomogeneousMedium medium;
    float distance;
};

// The estimators one free flight over [0, d) gives, per channel, against their closed forms:
//   passing:    E[weight; passed]        = T(d) = exp(-sigma_t d)
//   scattering: E[weight; scattered]     = ∫0^d sigma_s T(t) dt   = sigma_s / sigma_t (1 - T(d))
//               E[weight · t; scattered] = ∫0^d sigma_s T(t) t dt = sigma_s / sigma_t² (1 - T(d)(1 + sigma_t d))
// Each by Student's t-test; the control, sigma_t 3% larger in the closed form, must be rejected.
TEST_CASE("free-flight sampling's estimators of transmittance and in-scattering are unbiased, grey and coloured") {
    const FlightCase cases[] = {
        {"grey fog", medium(Rgb{0.2f}, Rgb{0.5f}), 1.5f},
        {"coloured smoke", medium({0.05f, 0.3f, 0.0f}, {0.2f, 0.1f, 1.2f}), 2.0f},
        {"a channel of vacuum", medium(Rgb{0.0f}, {0.0f, 0.3f, 0.9f}), 3.0f},
        {"absorbing only: the weight is T itself", medium({0.1f, 0.5f, 0.0f}, Rgb{0.0f}), 2.0f},
    };
    constexpr int kSamples = 200000;
    for (const FlightCase& c : cases) {
        const std::string name = c.name;
        CAPTURE(name);
        std::mt19937_64 rng(2024);
        test::UniformReal<float> uniform(0.0f, 1.0f);
        std::vector<double> passed[3], scattered[3], scatteredT[3];
        const Ray ray{{0, 0, 0}, {1, 0, 0}};
        for (int i = 0; i < kSamples; ++i) {
            const MediumSample s = c.medium.sampleDistance(ray, c.distance, uniform(rng), uniform(rng));
            CHECK_UNARY(s.scattered ? s.t >= 0.0f && s.t < c.distance : s.t == c.distance);
            for (int k = 0; k < 3; ++k) {
                passed[k].push_back(s.scattered ? 0.0 : s.weight[k]);
                scattered[k].push_back(s.scattered ? s.weight[k] : 0.0);
                scatteredT[k].push_back(s.scattered ? s.weight[k] * s.t : 0.0);
            }
        }
        for (int k = 0; k < 3; ++k) {
            CAPTURE(k);
            const double sa = c.medium.sigmaA[k], ss = c.medium.sigmaS[k], d = c.distance;
            const auto closedForms = [&](double st) {
                const double T = std::exp(-st * d);
                const double scatter = st > 0.0 ? ss / st * (1.0 - T) : 0.0;
                const double scatterT = st > 0.0 ? ss / (st * st) * (1.0 - T * (1.0 + st * d)) : 0.0;
                return std::array<double, 3>{T, scatter, scatterT};
            };
            const auto expected = closedForms(sa + ss);
            const auto pValue = [](const std::vector<double>& samples, double mean) {
                // All samples equal (a channel of vacuum passes with weight exactly 1): compare exactly.
                if (std::all_of(samples.begin(), samples.end(), [&](double x) { return x == samples[0]; }))
                    return std::abs(samples[0] - mean) < 1e-6 ? 1.0 : 0.0;
                return test::studentTTest(samples, mean);
            };
            CHECK(pValue(passed[k], expected[0]) > kAlpha);
            CHECK(pValue(scattered[k], expected[1]) > kAlpha);
            CHECK(pValue(scatteredT[k], expected[2]) > kAlpha);
            if (sa + ss > 0.0) {
                const auto control = closedForms(1.03 * (sa + ss));
                CHECK(pValue(passed[k], control[0]) < kAlpha);
            }
        }
    }
}

TEST_CASE("the homogeneous medium is registered with its schema, g = ±1 and negative sigmas are refused") {
    CHECK(MediumRegistry::instance().names() == std::vector<std::string>{"homogeneous"});
    const MediumType& type = *MediumRegistry::instance().find("homogeneous");
    CHECK(type.schema.events == "<V.>");
    ParameterValues values(type.schema);
    values.set("sigma_a", Rgb{0.1f, 0.2f, 0.3f});
    values.set("sigma_s", Rgb{0.5f});
    values.set("g", 0.25);
    const MediumSlot made = type.make(values);
    const auto& homogeneous = dynamic_cast<const HomogeneousMedium&>(*made);
    CHECK(homogeneous.sigmaT() == Rgb{0.6f, 0.7f, 0.8f});
    CHECK(homogeneous.g == 0.25f);
    CHECK_THROWS_AS(values.set("g", 1.0), SchemaError);
    CHECK_THROWS_AS(values.set("g", -1.0), SchemaError);
    CHECK_THROWS_AS(values.set("sigma_s", Rgb{0.1f, -0.1f, 0.0f}), SchemaError);
}

}  // namespace
}  // namespace lightpath
