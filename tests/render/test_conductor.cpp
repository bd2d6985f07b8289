// The conductor material (materials/conductor_material.h) against references that do not come
// from it: its Fresnel reflectance against the real-valued closed form of Born and Wolf, its
// directional albedo against a quadrature written here (white furnace), Helmholtz reciprocity,
// chi-square of its sampling against its density, and the path tracer against bdpt on a box.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "film/aov_presets.h"
#include "film/aov_set.h"
#include "materials/bsdf.h"
#include "materials/conductor_material.h"
#include "materials/optics.h"
#include "render/renderer.h"
#include "scene/scene_loader.h"
#include "../support/direction_chi_square.h"
#include "../support/ggx_albedo_reference.h"
#include "../support/material_harness.h"
#include "../support/paired_agreement.h"
#include "../support/statistics.h"
#include "../support/uniform_real.h"

namespace lightpath {
namespace conductor_test {

// Unpolarised reflectance of a metal eta + i k from the outside (index 1), the real-valued closed
// form of Born and Wolf (Principles of Optics, 14.4.1), with a^2 + b^2 = sqrt((eta^2 - k^2 -
// sin^2)^2 + 4 eta^2 k^2) and a^2 = (a^2 + b^2 + eta^2 - k^2 - sin^2) / 2:
//   Rs = (a^2 + b^2 - 2 a cos + cos^2) / (a^2 + b^2 + 2 a cos + cos^2)
//   Rp = Rs (a^2 + b^2 - 2 a sin tan + sin^2 tan^2) / (a^2 + b^2 + 2 a sin tan + sin^2 tan^2)
double bornWolfReflectance(double cosI, double eta, double k) {
    const double sin2 = 1.0 - cosI * cosI, cos2 = cosI * cosI;
    const double t0 = eta * eta - k * k - sin2;
    const double a2b2 = std::sqrt(t0 * t0 + 4.0 * eta * eta * k * k);
    const double a = std::sqrt(0.5 * (a2b2 + t0));
    const double rs = (a2b2 - 2.0 * a * cosI + cos2) / (a2b2 + 2.0 * a * cosI + cos2);
    // sin tan = sin^2 / cos; multiplied through by cos^2 to stay finite at grazing angles.
    const double rp = rs * (cos2 * a2b2 - 2.0 * a * cosI * sin2 + sin2 * sin2) /
                      (cos2 * a2b2 + 2.0 * a * cosI * sin2 + sin2 * sin2);
    return 0.5 * (rs + rp);
}

// Gold, copper, aluminium and a weak absorber at three wavelengths' worth of eta and k.
constexpr struct {
    float eta, k;
} kMetals[] = {{0.183f, 3.424f}, {0.271f, 3.609f}, {1.316f, 2.292f}, {1.2f, 7.26f}, {2.0f, 0.3f}};

TEST_CASE("conductor: exact Fresnel of eta + i k against Born and Wolf's closed form, and dielectric Fresnel at k = 0") {
    for (const auto& metal : kMetals) {
        for (const double cosI : {1.0, 0.9, 0.7, 0.5, 0.3, 0.1, 0.02}) {
            CAPTURE(metal.eta);
            CAPTURE(metal.k);
            CAPTURE(cosI);
            const double reference = bornWolfReflectance(cosI, metal.eta, metal.k);
            CHECK(fresnelConductor(float(cosI), metal.eta, metal.k) == doctest::Approx(reference).epsilon(1e-4));
        }
        // Normal incidence by hand: ((eta - 1)^2 + k^2) / ((eta + 1)^2 + k^2).
        const double e = metal.eta, k = metal.k;
        CHECK(fresnelConductor(1.0f, metal.eta, metal.k) ==
              doctest::Approx(((e - 1) * (e - 1) + k * k) / ((e + 1) * (e + 1) + k * k)).epsilon(1e-5));
    }
    for (const float cosI : {1.0f, 0.6f, 0.2f})
        CHECK(fresnelConductor(cosI, 1.5f, 0.0f) == doctest::Approx(fresnelDielectric(cosI, 1.0f / 1.5f)).epsilon(1e-5));
}

// The single-scattering albedo of GGX with Born and Wolf's exact F (tests/support/ggx_albedo_reference.h).
double albedoReference(double cosOut, double alpha, double eta, double k) {
    return test::ggxAlbedoWithFresnel(cosOut, alpha, [&](double om) { return bornWolfReflectance(om, eta, k); }, 2000, 180);
}

TEST_CASE("conductor: white furnace, its albedo is the GGX single-scattering albedo with exact Fresnel, never above 1") {
    const SurfaceSide side{{0, 0, 1}, true, TransportMode::Radiance};
    // Red channel: a near-perfect reflector (silver-like), green: copper, blue: a weak absorber.
    const Rgb eta{0.155f, 0.677f, 2.0f}, k{4.828f, 2.625f, 0.3f};
    for (const float roughness : {0.2f, 0.5f, 0.8f, 1.0f}) {
        const ConductorMaterial material(eta, k, roughness);
        for (const float cosOut : {0.95f, 0.5f, 0.15f}) {
            CAPTURE(roughness);
            CAPTURE(cosOut);
            const Vec3 wo = test::outgoing(cosOut);
            std::mt19937_64 rng(29);
            test::UniformReal<float> uniform(0.0f, 1.0f);
            constexpr int kDraws = 50000;
            Rgb byWeight{0.0f};
            double byEval = 0.0;
            for (int i = 0; i < kDraws; ++i) {
                const auto s = material.sample(ConductorMaterial::kGlossy, side, wo, {uniform(rng), uniform(rng)});
                if (!s) continue;
                byWeight += s->weight;
                byEval += material.eval(ConductorMaterial::kGlossy, side, wo, s->wi).g /
                          material.pdf(ConductorMaterial::kGlossy, side, wo, s->wi);
            }
            byWeight /= float(kDraws);
            byEval /= kDraws;
            for (int c = 0; c < 3; ++c) {
                CAPTURE(c);
                const double reference = albedoReference(cosOut, double(roughness) * roughness, eta[c], k[c]);
                CAPTURE(reference);
                CHECK(reference <= 1.0);
                CHECK(byWeight[c] <= 1.0f);
                CHECK(byWeight[c] == doctest::Approx(reference).epsilon(0.01));
            }
            CHECK(byEval == doctest::Approx(byWeight.g).epsilon(1e-3));
        }
    }
}

TEST_CASE("conductor: eval is reciprocal, f(wo, wi) = f(wi, wo)") {
    const SurfaceSide side{{0, 0, 1}, true, TransportMode::Radiance};
    std::mt19937_64 rng(5);
    test::UniformReal<double> uniform(0.0, 1.0);
    for (const float roughness : {0.1f, 0.4f, 1.0f}) {
        const ConductorMaterial material({0.271f, 0.677f, 1.316f}, {3.609f, 2.625f, 2.292f}, roughness);
        for (int i = 0; i < 200; ++i) {
            const Vec3 wo = test::outgoing(0.05 + 0.95 * uniform(rng), 2.0 * kPi * uniform(rng));
            const Vec3 wi = test::outgoing(0.05 + 0.95 * uniform(rng), 2.0 * kPi * uniform(rng));
            const Rgb forward = material.eval(ConductorMaterial::kGlossy, side, wo, wi) / wi.z;
            const Rgb backward = material.eval(ConductorMaterial::kGlossy, side, wi, wo) / wo.z;
            for (int c = 0; c < 3; ++c) CHECK(forward[c] == doctest::Approx(backward[c]).epsilon(1e-4));
        }
    }
}

TEST_CASE("conductor: at roughness 0 it is one mirror branch of exact Fresnel, a delta <RS>") {
    const ConductorMaterial material({0.183f, 0.421f, 1.373f}, {3.424f, 2.346f, 1.770f}, 0.0f);
    const Bsdf bsdf(material, {0, 0, 1}, true);
    CHECK(!bsdf.hasSmoothLobe());
    SpecularBranches branches;
    REQUIRE(bsdf.specularBranches(test::outgoing(0.5), branches) == 1);
    CHECK(branches[0].wi.z == doctest::Approx(0.5));
    CHECK(branches[0].weight.r == doctest::Approx(bornWolfReflectance(0.5, 0.183, 3.424)).epsilon(1e-4));
    CHECK(branches[0].weight.b == doctest::Approx(bornWolfReflectance(0.5, 1.373, 1.770)).epsilon(1e-4));
}

TEST_CASE("conductor: chi-square, its visible-normal sampling follows its density") {
    constexpr int kTests = 5;
    const double significance = 1.0 - std::pow(1.0 - 0.01, 1.0 / kTests);
    const struct {
        float roughness, cosOut;
    } cases[kTests] = {{0.3f, 0.9f}, {0.5f, 0.3f}, {0.7f, 0.6f}, {1.0f, 0.2f}, {0.22f, 0.15f}};
    for (const auto& c : cases) {
        CAPTURE(c.roughness);
        CAPTURE(c.cosOut);
        const ConductorMaterial material({0.271f, 0.677f, 1.316f}, {3.609f, 2.625f, 2.292f}, c.roughness);
        const Bsdf bsdf(material, {0, 0, 1}, true);
        const Vec3 wo = test::outgoing(c.cosOut, 4.0);
        test::DirectionHistogram histogram;
        histogram.subdivisions = 24;
        test::UniformReal<float> uniform(0.0f, 1.0f);
        const double p = test::directionChiSquarePValue(
            histogram,
            [&](std::mt19937_64& rng) -> std::optional<Vec3> {
                const auto s = bsdf.sample(wo, uniform(rng), {uniform(rng), uniform(rng)});
                return s ? std::optional<Vec3>(s->wi) : std::nullopt;
            },
            [&](const Vec3& wi) { return double(bsdf.pdf(ConductorMaterial::kGlossy, wo, wi)); });
        CHECK(p > significance);
    }
}

TEST_CASE("conductor: the path tracer and bdpt agree on a box with a rough copper and a polished silver ball (t-test)" *
          doctest::test_suite("statistical")) {
    Scene scene = loadScene(LIGHTPATH_SOURCE_DIR "/tests/render/data/cornell-conductor.toml");
    scene.camera.width = scene.camera.height = 32;
    const Film bdpt = test::renderClassesFilm(scene, "bdpt", 256, 11), path = test::renderClassesFilm(scene, "path", 256, 11);
    test::checkPairedAgreement(bdpt, path, 0.001);
}

}  // namespace conductor_test
}  // namespace lightpath
