// The microfacet material's clear coat (KHR_materials_clearcoat; materials/microfacet_material.h)
// against references that do not come from it: Schlick's Fresnel by hand for a smooth coat, GGX's
// albedo of F0 0.04 by a quadrature written in the test support for a rough one, the uncoated
// material for a coat of weight 0, and a closed form per pixel for Whitted, the path tracer and bdpt.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "film/aov_presets.h"
#include "film/aov_set.h"
#include "materials/bsdf.h"
#include "materials/microfacet_material.h"
#include "render/renderer.h"
#include "scene/camera.h"
#include "scene/scene_loader.h"
#include "../support/ggx_albedo_reference.h"
#include "../support/material_harness.h"
#include "../support/uniform_real.h"

namespace lightpath {
namespace clearcoat_test {

const SurfaceSide kUp{{0, 0, 1}, true, TransportMode::Radiance};

MicrofacetMaterial coated(Rgb baseColor, float metallic, float roughness, float coat, float coatRoughness) {
    return MicrofacetMaterial(baseColor, metallic, roughness, Rgb{MicrofacetMaterial::kDielectricF0},
                              {coat, coatRoughness});
}

TEST_CASE("clear coat: over a polished metal, two mirror branches, w F_c and F_b (1 - w F_c)^2 (Schlick by hand)") {
    const float w = 0.8f;
    const MicrofacetMaterial material = coated({0.9f, 0.6f, 0.3f}, 1.0f, 0.0f, w, 0.0f);
    const Bsdf bsdf(material, {0, 0, 1}, true);
    CHECK(!bsdf.hasSmoothLobe());
    CHECK(bsdf.lobe(MicrofacetMaterial::kCoatMirror).delta());
    // Schlick 1994: F0 + (1 - F0)(1 - cos)^5, by hand at cosines 1, 1/2 and 1/4.
    const struct {
        double cosOut, grazing;  // (1 - cos)^5
    } cases[] = {{1.0, 0.0}, {0.5, 1.0 / 32.0}, {0.25, 243.0 / 1024.0}};
    for (const auto& c : cases) {
        CAPTURE(c.cosOut);
        SpecularBranches branches;
        REQUIRE(bsdf.specularBranches(test::outgoing(c.cosOut), branches) == 2);
        const double coat = 0.04 + 0.96 * c.grazing, below = (1.0 - w * coat) * (1.0 - w * coat);
        CHECK(branches[0].lobe == MicrofacetMaterial::kMirror);
        CHECK(branches[0].weight.r == doctest::Approx((0.9 + 0.1 * c.grazing) * below).epsilon(1e-5).scale(0));
        CHECK(branches[0].weight.b == doctest::Approx((0.3 + 0.7 * c.grazing) * below).epsilon(1e-5).scale(0));
        CHECK(branches[1].lobe == MicrofacetMaterial::kCoatMirror);
        CHECK(branches[1].weight.g == doctest::Approx(w * coat).epsilon(1e-5).scale(0));
        for (int b = 0; b < 2; ++b) {  // both the mirror of wo
            CHECK(branches[b].wi.z == doctest::Approx(c.cosOut));
            CHECK(branches[b].wi.x == doctest::Approx(-test::outgoing(c.cosOut).x));
        }
    }
}

TEST_CASE("clear coat: a rough coat reflects w times GGX's albedo of F0 0.04 and dims what is below by (1 - w E_c) both ways") {
    const float w = 0.7f;
    for (const float coatRoughness : {0.2f, 0.5f, 0.9f}) {
        const double alpha = double(coatRoughness) * coatRoughness;
        const MicrofacetMaterial material = coated({0.8f, 0.5f, 0.2f}, 0.0f, 0.6f, w, coatRoughness);
        const MicrofacetMaterial plain({0.8f, 0.5f, 0.2f}, 0.0f, 0.6f);
        for (const float cosOut : {0.999f, 0.7f, 0.4f, 0.15f}) {
            CAPTURE(coatRoughness);
            CAPTURE(cosOut);
            const Vec3 wo = test::outgoing(cosOut);
            const double reference = w * test::ggxAlbedoReference(cosOut, alpha, MicrofacetMaterial::kDielectricF0);
            // The coat's lobe by its one-sample estimate: the mean sample weight is its albedo.
            std::mt19937_64 rng(23);
            test::UniformReal<float> uniform(0.0f, 1.0f);
            constexpr int kDraws = 100000;
            double albedo = 0.0;
            for (int i = 0; i < kDraws; ++i)
                if (const auto s = material.sample(MicrofacetMaterial::kCoatGlossy, kUp, wo, {uniform(rng), uniform(rng)}))
                    albedo += s->weight.g;
            CHECK(albedo / kDraws == doctest::Approx(reference).epsilon(0.01).scale(0));
            CHECK(material.albedo(MicrofacetMaterial::kCoatGlossy, kUp, wo) == doctest::Approx(reference).epsilon(0.01).scale(0));
            // Below the coat, both of the base's lobes: the uncoated value times what it lets through.
            for (const float cosIn : {0.9f, 0.5f, 0.2f}) {
                CAPTURE(cosIn);
                const Vec3 wi = test::outgoing(cosIn, 2.5);
                const double through =
                    (1.0 - w * test::ggxAlbedoReference(cosOut, alpha, MicrofacetMaterial::kDielectricF0)) *
                    (1.0 - w * test::ggxAlbedoReference(cosIn, alpha, MicrofacetMaterial::kDielectricF0));
                for (const int lobe : {int(MicrofacetMaterial::kDiffuse), int(MicrofacetMaterial::kGlossy)}) {
                    CAPTURE(lobe);
                    const double ratio = material.eval(lobe, kUp, wo, wi).r / plain.eval(lobe, kUp, wo, wi).r;
                    CHECK(ratio == doctest::Approx(through).epsilon(0.005).scale(0));
                }
            }
        }
    }
}

TEST_CASE("clear coat: weight 0 is the uncoated material, bit for bit; any weight keeps f(wo, wi) = f(wi, wo)") {
    const MicrofacetMaterial none = coated({0.8f, 0.5f, 0.2f}, 0.3f, 0.4f, 0.0f, 0.3f);
    const MicrofacetMaterial plain({0.8f, 0.5f, 0.2f}, 0.3f, 0.4f);
    const MicrofacetMaterial material = coated({0.8f, 0.5f, 0.2f}, 0.3f, 0.4f, 1.0f, 0.3f);
    CHECK(!none.coated());
    CHECK(!none.has(MicrofacetMaterial::kCoatGlossy));
    CHECK(material.has(MicrofacetMaterial::kCoatGlossy));
    CHECK(!material.has(MicrofacetMaterial::kCoatMirror));
    std::mt19937_64 rng(5);
    test::UniformReal<float> uniform(0.05f, 0.95f);
    for (int i = 0; i < 200; ++i) {
        const Vec3 wo = test::outgoing(uniform(rng), 6.0 * uniform(rng)), wi = test::outgoing(uniform(rng), 6.0 * uniform(rng));
        for (int lobe = 0; lobe < int(MicrofacetMaterial::kLobes.size()); ++lobe) {
            CAPTURE(lobe);
            CHECK(none.eval(lobe, kUp, wo, wi) == plain.eval(lobe, kUp, wo, wi));
            CHECK(none.albedo(lobe, kUp, wo) == plain.albedo(lobe, kUp, wo));
            const Rgb forward = material.eval(lobe, kUp, wo, wi) / wi.z, backward = material.eval(lobe, kUp, wi, wo) / wo.z;
            CHECK(forward.g == doctest::Approx(backward.g).epsilon(1e-4).scale(1e-6));
        }
    }
    CHECK(none.diffuseReflectance() == plain.diffuseReflectance());
}

// A polished coat of weight 0.8 over a black polished base (F0 0: Schlick's (1 - cos)^5 alone) on
// a floor under a white sky: each point reflects the sky by the coat's and the base's mirror
// branches, w F_c(c) + F_b(c) (1 - w F_c(c))^2, c the cosine of the view ray with the floor's
// normal. Per pixel, the test averages that closed form over a 16 x 16 grid of its own rays.
TEST_CASE("clear coat: a polished coat over black under a white sky shows w F_c + F_b (1 - w F_c)^2, pixel by pixel") {
    const std::string text = R"(
[world]
background = 1
[camera]
eye = [0, 1.5, 4]
look_at = [0, 0, 0]
fov = 40
resolution = [24, 16]
[materials.lacquer]
type = "microfacet"
base_color = 0
metallic = 0
roughness = 0
dielectric_f0 = 0
clearcoat = 0.8
clearcoat_roughness = 0
[[planes]]
point = [0, 0, 0]
normal = [0, 1, 0]
material = "lacquer"
)";
    const Scene scene = loadSceneFromText(text, LIGHTPATH_SOURCE_DIR "/tests/render/data/lacquer.toml");
    const Camera camera(scene.camera);
    const auto schlick = [](double f0, double c) { return f0 + (1.0 - f0) * std::pow(1.0 - c, 5.0); };
    const auto reflected = [&](double c) {
        const double coat = 0.8 * schlick(0.04, c);
        return coat + schlick(0.0, c) * (1.0 - coat) * (1.0 - coat);
    };
    constexpr int kGrid = 16;
    for (const std::string integrator : {"whitted", "path", "bdpt"}) {
        CAPTURE(integrator);
        RenderOptions options;
        options.integrator = integrator;
        options.samplesPerPixel = integrator == "whitted" ? 64 : 1024;
        const Film film = Renderer(scene, AovSet(classesSet()), options).render().film;
        int compared = 0;
        double worst = 0.0, sum = 0.0, expectedSum = 0.0;
        for (int y = 0; y < film.height(); ++y)
            for (int x = 0; x < film.width(); ++x) {
                double expected = 0.0;
                int floor = 0;
                for (int j = 0; j < kGrid; ++j)
                    for (int i = 0; i < kGrid; ++i) {
                        const Ray ray = camera.generateRay(x + (i + 0.5f) / kGrid, y + (j + 0.5f) / kGrid);
                        const Vec3 d = glm::normalize(ray.direction);
                        floor += d.y < 0.0f;
                        expected += d.y < 0.0f ? reflected(-double(d.y)) : 1.0;
                    }
                if (floor != 0 && floor != kGrid * kGrid) continue;  // the horizon's pixels: an edge
                expected /= kGrid * kGrid;
                if (floor == 0) continue;  // the sky alone
                const double value = film.at(0, x, y).g;
                worst = std::max(worst, std::abs(value - expected));
                sum += value;
                expectedSum += expected;
                ++compared;
            }
        CAPTURE(worst);
        REQUIRE(compared > 150);
        // Whitted traces both branches: only the pixel's own sample positions differ from the grid.
        if (integrator == "whitted") CHECK(worst < 2e-3);
        // The path tracer and bdpt pick one branch by its weight: noise per pixel, the mean exact.
        CHECK(sum / expectedSum == doctest::Approx(1.0).epsilon(0.005).scale(0));
    }
}

}  // namespace clearcoat_test
}  // namespace lightpath
