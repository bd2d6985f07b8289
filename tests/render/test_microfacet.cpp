// The GGX microfacet material (materials/microfacet_material.h) against references that do not
// come from it: the single-scattering GGX albedo by a quadrature written here (white furnace),
// the glTF blend's energy and its F0 and base by hand,
// Helmholtz reciprocity, chi-square of its visible-normal sampling against its density (the
// helper of test_bsdf_sampling.cpp), and the path tracer against bdpt on a box holding it.
#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <vector>

#include "film/aov_presets.h"
#include "film/aov_set.h"
#include "materials/bsdf.h"
#include "materials/microfacet_material.h"
#include "render/renderer.h"
#include "scene/scene_loader.h"
#include "../support/direction_chi_square.h"
#include "../support/ggx_albedo_reference.h"
#include "../support/material_harness.h"
#include "../support/monte_carlo.h"
#include "../support/paired_agreement.h"
#include "../support/statistics.h"
#include "../support/uniform_real.h"

namespace lightpath {
namespace {

// glTF's metallic = 1: a conductor whose F0 is the base colour.
MicrofacetMaterial conductor(Rgb f0, float roughness) { return MicrofacetMaterial(f0, 1.0f, roughness); }

constexpr float kRoughnessSweep[] = {0.2f, 0.35f, 0.5f, 0.7f, 0.85f, 1.0f};
constexpr float kCosSweep[] = {0.999f, 0.7f, 0.4f, 0.15f};

TEST_CASE("microfacet: white furnace, a conductor with F = 1 reflects the single-scattering GGX albedo, never more than 1") {
    const SurfaceSide side{{0, 0, 1}, true, TransportMode::Radiance};
    for (const float roughness : kRoughnessSweep) {
        const MicrofacetMaterial material = conductor(Rgb{1.0f}, roughness);  // Schlick's F = 1
        const double alpha = double(roughness) * roughness;
        for (const float cosOut : kCosSweep) {
            CAPTURE(roughness);
            CAPTURE(cosOut);
            const Vec3 wo = test::outgoing(cosOut);
            std::mt19937_64 rng(17);
            test::UniformReal<float> uniform(0.0f, 1.0f);
            constexpr int kDraws = 100000;
            double byWeight = 0.0, byEval = 0.0;
            for (int i = 0; i < kDraws; ++i) {
                const auto s = material.sample(MicrofacetMaterial::kGlossy, side, wo, {uniform(rng), uniform(rng)});
                if (!s) continue;
                byWeight += s->weight.r;
                // The same estimate from eval and pdf: sampling and evaluation describe one BSDF.
                byEval += material.eval(MicrofacetMaterial::kGlossy, side, wo, s->wi).r /
                          material.pdf(MicrofacetMaterial::kGlossy, side, wo, s->wi);
            }
            byWeight /= kDraws;
            byEval /= kDraws;
            const double reference = test::ggxAlbedoReference(cosOut, alpha);
            CAPTURE(reference);
            CHECK(reference <= 1.0);
            CHECK(byWeight <= 1.0);
            CHECK(byWeight == doctest::Approx(reference).epsilon(0.01));
            CHECK(byEval == doctest::Approx(reference).epsilon(0.01));
        }
    }
}

TEST_CASE("microfacet: eval is reciprocal, f(wo, wi) = f(wi, wo)") {
    const SurfaceSide side{{0, 0, 1}, true, TransportMode::Radiance};
    std::mt19937_64 rng(3);
    test::UniformReal<double> uniform(0.0, 1.0);
    for (const float roughness : kRoughnessSweep) {
        const MicrofacetMaterial material({0.95f, 0.64f, 0.54f}, 0.3f, roughness);
        for (int i = 0; i < 200; ++i) {
            const Vec3 wo = test::outgoing(0.05 + 0.95 * uniform(rng), 2.0 * kPi * uniform(rng));
            const Vec3 wi = test::outgoing(0.05 + 0.95 * uniform(rng), 2.0 * kPi * uniform(rng));
            for (const int lobe : {MicrofacetMaterial::kDiffuse, MicrofacetMaterial::kGlossy}) {
                CAPTURE(lobe);
                // eval is f |cos theta_i|
                const Rgb forward = material.eval(lobe, side, wo, wi) / wi.z;
                const Rgb backward = material.eval(lobe, side, wi, wo) / wo.z;
                for (int c = 0; c < 3; ++c) CHECK(forward[c] == doctest::Approx(backward[c]).epsilon(1e-4));
            }
        }
    }
}

// The blend's directional albedo from wo: its glossy lobe by the lobe's sampling weights, its
// base by uniform hemisphere sampling of eval (not the material's own sampling), and the mirror
// branch at roughness 0.
Rgb blendAlbedo(const MicrofacetMaterial& material, float cosOut) {
    const SurfaceSide side{{0, 0, 1}, true, TransportMode::Radiance};
    const Vec3 wo = test::outgoing(cosOut);
    std::mt19937_64 rng(23);
    test::UniformReal<float> uniform(0.0f, 1.0f);
    constexpr int kDraws = 100000;
    Rgb glossy{0.0f}, base{0.0f};
    for (int i = 0; i < kDraws; ++i) {
        if (const auto s = material.sample(MicrofacetMaterial::kGlossy, side, wo, {uniform(rng), uniform(rng)}))
            glossy += s->weight;
        const float z = uniform(rng), phi = 2.0f * kPi * uniform(rng), r = std::sqrt(1.0f - z * z);
        base += material.eval(MicrofacetMaterial::kDiffuse, side, wo, {r * std::cos(phi), r * std::sin(phi), z});
    }
    Rgb total = glossy / float(kDraws) + base * (2.0f * kPi / kDraws);
    SpecularBranches branches;
    if (material.specularBranches(side, wo, branches) == 1) total += branches[0].weight;
    return total;
}

TEST_CASE("microfacet: white furnace, glTF's metallic-roughness blend of a white base reflects at most 1 at every roughness" * doctest::test_suite("statistical")) {
    for (const float metallic : {0.0f, 0.5f}) {
        for (const float roughness : {0.0f, 0.2f, 0.35f, 0.5f, 0.7f, 0.85f, 1.0f}) {
            const MicrofacetMaterial material(Rgb{1.0f}, metallic, roughness);
            for (const float cosOut : {0.999f, 0.7f, 0.4f, 0.15f, 0.03f}) {
                CAPTURE(metallic);
                CAPTURE(roughness);
                CAPTURE(cosOut);
                const Rgb albedo = blendAlbedo(material, cosOut);
                CAPTURE(albedo.r);
                CHECK(albedo.r <= 1.0f + 0.005f);  // 0.005: a few standard errors of the estimate
                // and the base is not lost: a white dielectric reflects most of what arrives
                if (metallic == 0.0f && cosOut > 0.3f) CHECK(albedo.r > 0.8f);
            }
        }
    }
}

TEST_CASE("microfacet: F0 = mix(0.04, base_color, metallic) and the base is (1 - metallic) base_color (glTF 2.0, appendix B)") {
    const SurfaceSide side{{0, 0, 1}, true, TransportMode::Radiance};
    SpecularBranches branches;
    // At normal incidence Schlick's F is F0: 0.5 * 0.04 + 0.5 * base, by hand.
    const MicrofacetMaterial half({0.6f, 0.2f, 1.0f}, 0.5f, 0.0f);
    REQUIRE(half.specularBranches(side, {0, 0, 1}, branches) == 1);
    CHECK(branches[0].weight.r == doctest::Approx(0.32));
    CHECK(branches[0].weight.g == doctest::Approx(0.12));
    CHECK(branches[0].weight.b == doctest::Approx(0.52));
    const MicrofacetMaterial dielectric(Rgb{0.6f}, 0.0f, 0.0f);
    REQUIRE(dielectric.specularBranches(side, {0, 0, 1}, branches) == 1);
    CHECK(branches[0].weight.r == doctest::Approx(0.04));
    // A smooth base under a mirror layer: (1 - F(1))(1 - F(cos theta_i)) of 0.6/pi, with Schlick's F
    // written out for cos theta_i = 0.5: 0.04 + 0.96/32.
    const float cosIn = 0.5f;
    const Vec3 wi = test::outgoing(cosIn);
    const double expected = 0.6 / 3.14159265358979 * (1.0 - 0.04) * (1.0 - (0.04 + 0.96 / 32.0)) * cosIn;
    CHECK(dielectric.eval(MicrofacetMaterial::kDiffuse, side, {0, 0, 1}, wi).r == doctest::Approx(expected).epsilon(1e-4));
    const MicrofacetMaterial metal(Rgb{0.6f}, 1.0f, 0.5f);
    CHECK(!metal.has(MicrofacetMaterial::kDiffuse));
}

// dielectric_f0 replaces the 0.04: F0 = mix(dielectric_f0, base_color, metallic). A dielectric of
// F0 X over a black base is the conductor of F0 X (no base either way), lobe by lobe.
TEST_CASE("microfacet: dielectric_f0 is the dielectric's F0; over a black base it is the conductor of that F0") {
    const SurfaceSide side{{0, 0, 1}, true, TransportMode::Radiance};
    SpecularBranches branches;
    const Rgb f0{0.02f, 0.3f, 0.9f};
    const MicrofacetMaterial smooth(ColorParameter(Rgb{0.6f}), 0.5f, 0.0f, f0);
    REQUIRE(smooth.specularBranches(side, {0, 0, 1}, branches) == 1);
    CHECK(branches[0].weight.r == doctest::Approx(0.5 * 0.02 + 0.5 * 0.6));  // at normal incidence F = F0
    CHECK(branches[0].weight.b == doctest::Approx(0.5 * 0.9 + 0.5 * 0.6));
    for (const float roughness : {0.2f, 0.6f}) {
        CAPTURE(roughness);
        const MicrofacetMaterial dielectric(ColorParameter(Rgb{0.0f}), 0.0f, roughness, f0);
        const MicrofacetMaterial metal = conductor(f0, roughness);
        std::mt19937_64 rng(7);
        for (int k = 0; k < 200; ++k) {
            Vec3 wo = test::uniformSphereDirection(rng), wi = test::uniformSphereDirection(rng);
            wo.z = std::fabs(wo.z), wi.z = std::fabs(wi.z);  // both above the surface
            for (int c = 0; c < 3; ++c)
                CHECK(dielectric.eval(MicrofacetMaterial::kGlossy, side, wo, wi)[c] ==
                      doctest::Approx(metal.eval(MicrofacetMaterial::kGlossy, side, wo, wi)[c]).epsilon(1e-5));
            CHECK(dielectric.eval(MicrofacetMaterial::kDiffuse, side, wo, wi) == Rgb{0.0f});
        }
    }
}

constexpr int kChiSquareTests = 8;
const double kSignificance = 1.0 - std::pow(1.0 - 0.01, 1.0 / kChiSquareTests);

// p-value that the material's sampled directions follow the density its pdf claims (through
// the Bsdf, lobe choice included), as test_bsdf_sampling.cpp tests the Phong materials.
double chiSquarePValue(const MicrofacetMaterial& material, float cosOut) {
    const Bsdf bsdf(material, {0, 0, 1}, true);
    const Vec3 wo = test::outgoing(cosOut, 4.0);  // an azimuth off the frame's axes
    test::DirectionHistogram histogram;
    histogram.subdivisions = 24;  // 12 misses narrow grazing lobes: the midpoint rule, not the sampling
    test::UniformReal<float> uniform(0.0f, 1.0f);
    return test::directionChiSquarePValue(
        histogram,
        [&](std::mt19937_64& rng) -> std::optional<Vec3> {
            const auto s = bsdf.sample(wo, uniform(rng), {uniform(rng), uniform(rng)});
            return s ? std::optional<Vec3>(s->wi) : std::nullopt;
        },
        [&](const Vec3& wi) {
            double density = 0.0;
            for (int lobe = 0; lobe < int(bsdf.lobes().size()); ++lobe)
                if (!bsdf.lobe(lobe).delta()) density += bsdf.pdf(lobe, wo, wi);
            return density;
        });
}

TEST_CASE("microfacet: chi-square, visible-normal and the base's cosine sampling follow their densities") {
    const struct {
        float metallic, roughness, cosOut;
    } cases[kChiSquareTests] = {{1, 0.5f, 0.9f}, {1, 0.5f, 0.3f}, {1, 0.7f, 0.6f}, {1, 0.7f, 0.1f},
                                {1, 1.0f, 0.999f}, {1, 1.0f, 0.2f}, {0, 0.5f, 0.7f}, {0.5f, 0.22f, 0.15f}};
    for (const auto& c : cases) {
        CAPTURE(c.metallic);
        CAPTURE(c.roughness);
        CAPTURE(c.cosOut);
        CHECK(chiSquarePValue(MicrofacetMaterial({0.9f, 0.6f, 0.3f}, c.metallic, c.roughness), c.cosOut) > kSignificance);
    }
}

TEST_CASE("microfacet: at roughness 0 the conductor is one mirror branch of Schlick's Fresnel, a delta <RS>") {
    const MicrofacetMaterial material = conductor({0.9f, 0.6f, 0.3f}, 0.0f);
    const Bsdf bsdf(material, {0, 0, 1}, true);
    CHECK(!bsdf.hasSmoothLobe());
    CHECK(bsdf.lobe(MicrofacetMaterial::kMirror).delta());
    SpecularBranches branches;
    const float cosOut = 0.5f;
    REQUIRE(bsdf.specularBranches(test::outgoing(cosOut), branches) == 1);
    CHECK(branches[0].wi.z == doctest::Approx(cosOut));
    CHECK(branches[0].wi.x == doctest::Approx(-test::outgoing(cosOut).x));
    // Schlick 1994: F0 + (1 - F0)(1 - cos)^5, by hand for cos = 0.5: (0.5)^5 = 1/32.
    CHECK(branches[0].weight.r == doctest::Approx(0.9 + 0.1 / 32.0));
    CHECK(branches[0].weight.b == doctest::Approx(0.3 + 0.7 / 32.0));
}

TEST_CASE("microfacet: the path tracer and bdpt agree on a box with a rough and a polished ball (t-test)" *
          doctest::test_suite("statistical")) {
    Scene scene = loadScene(LIGHTPATH_SOURCE_DIR "/tests/render/data/cornell-microfacet.toml");
    scene.camera.width = scene.camera.height = 32;
    // The same seed: common random numbers make the paired differences small (test_bdpt.cpp).
    const Film bdpt = test::renderClassesFilm(scene, "bdpt", 256, 11), path = test::renderClassesFilm(scene, "path", 256, 11);
    test::checkPairedAgreement(bdpt, path, 0.001);
}

}  // namespace
}  // namespace lightpath

namespace lightpath {
namespace {

// A texture of one colour everywhere (written here, not OpenImageIO's): a textured base_color must
// act as the untextured material whose base_color is that colour times the tint.
class UniformTexture final : public Texture {
public:
    explicit UniformTexture(Rgb colour) : colour_(colour) {}
    Rgb lookup(const TextureFootprint&, const TextureSampling&) const override { return colour_; }
    float lookupChannel(const TextureFootprint&, const TextureSampling&, int channel) const override {
        return channel < 3 ? colour_[channel] : 1.0f;
    }
    Rgb average() const override { return colour_; }
    int alphaChannel() const override { return -1; }

private:
    Rgb colour_;
};

}  // namespace

TEST_CASE("microfacet: a textured base_color shades as the constant it reads (texel times tint)") {
    const Rgb texel{0.7f, 0.3f, 0.1f}, tint{0.5f, 1.0f, 0.8f};
    const SurfaceSide side{{0, 0, 1}, true, TransportMode::Radiance};
    for (const float metallic : {0.0f, 0.4f, 1.0f}) {
        for (const float roughness : {0.0f, 0.3f, 0.8f}) {
            CAPTURE(metallic);
            CAPTURE(roughness);
            const MicrofacetMaterial textured(
                ColorParameter(std::make_shared<UniformTexture>(texel), tint, 1.0f, true), metallic, roughness);
            const MicrofacetMaterial constant(texel * tint, metallic, roughness);
            const Vec3 wo = test::outgoing(0.6, 0.3), wi = test::outgoing(0.45, 2.9);
            for (int lobe = 0; lobe < 3; ++lobe) {
                CAPTURE(lobe);
                REQUIRE(textured.has(lobe) == constant.has(lobe));
                const Rgb a = textured.eval(lobe, side, wo, wi), b = constant.eval(lobe, side, wo, wi);
                for (int c = 0; c < 3; ++c) CHECK(a[c] == doctest::Approx(b[c]).epsilon(1e-6));
                CHECK(textured.albedo(lobe, side, wo) == doctest::Approx(constant.albedo(lobe, side, wo)).epsilon(1e-6));
                const auto s = textured.sample(lobe, side, wo, {0.3f, 0.6f});
                const auto t = constant.sample(lobe, side, wo, {0.3f, 0.6f});
                REQUIRE(s.has_value() == t.has_value());
                if (s)
                    for (int c = 0; c < 3; ++c) CHECK(s->weight[c] == doctest::Approx(t->weight[c]).epsilon(1e-6));
            }
            SpecularBranches x, y;
            REQUIRE(textured.specularBranches(side, wo, x) == constant.specularBranches(side, wo, y));
            if (roughness == 0.0f)
                for (int c = 0; c < 3; ++c) CHECK(x[0].weight[c] == doctest::Approx(y[0].weight[c]).epsilon(1e-6));
            const Rgb ra = textured.diffuseReflectance(), rb = constant.diffuseReflectance();
            for (int c = 0; c < 3; ++c) CHECK(ra[c] == doctest::Approx(rb[c]).epsilon(1e-6));
        }
    }
}

}  // namespace lightpath
