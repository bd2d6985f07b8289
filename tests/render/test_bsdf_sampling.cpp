// chi-square tests of the path tracer's importance sampling against its evaluated densities, the
// way Nori's chi2test does it (tests/support/direction_chi_square.h), with a significance level
// corrected for the number of tests (Sidak).
#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <vector>

#include "materials/bsdf.h"
#include "materials/modified_phong_material.h"
#include "materials/phong_material.h"
#include "sampling/warp.h"
#include "../support/direction_chi_square.h"
#include "../support/uniform_real.h"

namespace lightpath {
namespace {

constexpr int kCosBins = 16, kPhiBins = 32, kSamples = 200000;
constexpr int kTests = 8;
const double kSignificance = 1.0 - std::pow(1.0 - 0.01, 1.0 / kTests);

struct Case {
    const char* name;
    PhongMaterial material;
    float cosOut;
};

// A material of type M with a diffuse and a highlight lobe (Phong's or the modified Phong's).
template <typename M = PhongMaterial>
M makeMaterial(Rgb kd, Rgb ks, float n) {
    M m;
    m.kd = kd;
    m.ks = ks;
    m.n = n;
    return m;
}

// p-value that directions drawn by `sampling` follow the density `density` claims.
double chiSquarePValue(const Bsdf& sampling, const Bsdf& density, float cosOut) {
    const float sinOut = std::sqrt(1.0f - cosOut * cosOut);
    const Vec3 wo{sinOut, 0, cosOut};
    test::DirectionHistogram histogram;
    histogram.cosBins = kCosBins;
    histogram.phiBins = kPhiBins;
    histogram.samples = kSamples;
    test::UniformReal<float> uniform(0.0f, 1.0f);
    return test::directionChiSquarePValue(
        histogram,
        [&](std::mt19937_64& rng) -> std::optional<Vec3> {
            const auto s = sampling.sample(wo, uniform(rng), {uniform(rng), uniform(rng)});
            return s ? std::optional<Vec3>(s->wi) : std::nullopt;
        },
        [&](const Vec3& wi) { return double(density.pdf(PhongMaterial::kDiffuse, wo, wi)) + density.pdf(PhongMaterial::kHighlight, wo, wi); });
}

TEST_CASE("chi-square: Lambert and Blinn highlight sampling follow their densities") {
    const Case cases[kTests] = {
        {"diffuse, normal incidence", makeMaterial(Rgb{0.8f}, Rgb{0}, 1), 1.0f},
        {"diffuse, grazing", makeMaterial(Rgb{0.5f}, Rgb{0}, 1), 0.1f},
        {"highlight n=1", makeMaterial(Rgb{0}, Rgb{0.9f}, 1), 0.7f},
        {"highlight n=10", makeMaterial(Rgb{0}, Rgb{0.9f}, 10), 0.5f},
        {"highlight n=100, grazing", makeMaterial(Rgb{0}, Rgb{0.9f}, 100), 0.2f},
        {"highlight n=40", makeMaterial(Rgb{0}, Rgb{0.5f}, 40), 0.9f},
        {"diffuse + highlight n=20", makeMaterial(Rgb{0.4f}, Rgb{0.3f}, 20), 0.6f},
        {"coloured diffuse + highlight n=5", makeMaterial({0.7f, 0.2f, 0.1f}, {0.1f, 0.1f, 0.6f}, 5), 0.3f},
    };
    for (const Case& c : cases) {
        CAPTURE(c.name);
        const Bsdf bsdf(c.material, {0, 0, 1}, true);
        CHECK(chiSquarePValue(bsdf, bsdf, c.cosOut) > kSignificance);
    }
}

TEST_CASE("chi-square: modified Phong's lobe about the mirror direction follows its density") {
    const struct {
        const char* name;
        ModifiedPhongMaterial material;
        float cosOut;
    } cases[] = {
        {"n=1", makeMaterial<ModifiedPhongMaterial>(Rgb{0}, Rgb{0.9f}, 1), 0.7f},
        {"n=30, grazing: part of the lobe falls below the surface", makeMaterial<ModifiedPhongMaterial>(Rgb{0}, Rgb{0.9f}, 30), 0.15f},
        {"diffuse + n=10", makeMaterial<ModifiedPhongMaterial>(Rgb{0.5f}, Rgb{0.4f}, 10), 0.5f},
    };
    for (const auto& c : cases) {
        CAPTURE(c.name);
        const Bsdf bsdf(c.material, {0, 0, 1}, true);
        CHECK(chiSquarePValue(bsdf, bsdf, c.cosOut) > kSignificance);
    }
}

// The directional albedo  integral of f cos over the hemisphere, by uniform hemisphere sampling,
// which does not use the material's own sampling.
Rgb directionalAlbedo(const Material& material, float cosOut) {
    const Vec3 wo{std::sqrt(1.0f - cosOut * cosOut), 0, cosOut};
    const SurfaceSide side{{0, 0, 1}, true, TransportMode::Radiance};
    std::mt19937_64 rng(7);
    test::UniformReal<float> uniform(0.0f, 1.0f);
    constexpr int kDirections = 400000;
    Rgb sum{0.0f};
    for (int i = 0; i < kDirections; ++i) {
        const float z = uniform(rng), phi = 2.0f * kPi * uniform(rng), r = std::sqrt(1.0f - z * z);
        const Vec3 wi{r * std::cos(phi), r * std::sin(phi), z};
        for (int lobe = 0; lobe < int(material.lobes().size()); ++lobe)
            if (!material.lobes()[lobe].delta()) sum += material.eval(lobe, side, wo, wi);
    }
    return sum * (2.0f * kPi / kDirections);
}

TEST_CASE("modified Phong reflects exactly kd + ks at normal incidence and never more (Lafortune and Willems 1994)") {
    const ModifiedPhongMaterial material = makeMaterial<ModifiedPhongMaterial>({0.5f, 0.2f, 0.0f}, {0.5f, 0.3f, 0.8f}, 20);
    const Rgb normal = directionalAlbedo(material, 1.0f);
    for (int c = 0; c < 3; ++c) CHECK(normal[c] == doctest::Approx(material.kd.constant()[c] + material.ks.constant()[c]).epsilon(0.01));
    for (float cosOut : {0.8f, 0.4f, 0.1f}) {
        CAPTURE(cosOut);
        const Rgb oblique = directionalAlbedo(material, cosOut);
        for (int c = 0; c < 3; ++c) CHECK(oblique[c] <= material.kd.constant()[c] + material.ks.constant()[c] + 0.01f);
    }
    // The control: the classic highlight ks (H.N)^n / pi is not normalised, so the same ks
    // reflects far from ks (about 8 ks / (n + 1) at normal incidence, Bsdf's lobe-choice estimate).
    PhongMaterial classic;
    classic.ks = Rgb{0.5f};
    classic.n = 20.0f;
    CHECK(directionalAlbedo(classic, 1.0f)[0] < 0.5f * 0.5f);
}

TEST_CASE("chi-square machinery rejects a wrong density") {
    // Sampling the n = 10 lobe while the density claims n = 12 must fail the same test.
    const PhongMaterial sampled = makeMaterial(Rgb{0}, Rgb{0.9f}, 10);
    const PhongMaterial claimed = makeMaterial(Rgb{0}, Rgb{0.9f}, 12);
    const Bsdf sampling(sampled, {0, 0, 1}, true), density(claimed, {0, 0, 1}, true);
    CHECK(chiSquarePValue(sampling, density, 0.8f) < kSignificance);
}

TEST_CASE("dielectric: reflection frequency is Fresnel's and refraction obeys Snell's law") {
    PhongMaterial glass;
    glass.kt = Rgb{1.0f};
    glass.ior = 1.5f;
    glass.fresnel = true;
    for (const bool entering : {true, false}) {
        for (const float cosOut : {1.0f, 0.8f, 0.4f, 0.1f}) {
            CAPTURE(entering);
            CAPTURE(cosOut);
            const Bsdf bsdf(glass, {0, 0, 1}, entering);
            const double eta = entering ? 1.0 / 1.5 : 1.5;  // n_i / n_t
            const double sinOut = std::sqrt(1.0 - double(cosOut) * cosOut);
            // Fresnel for unpolarised light, written out in double (Hecht, Optics, 4.4).
            double expectedReflectance = 1.0;
            const double sinT = eta * sinOut;
            if (sinT < 1.0) {
                const double cosT = std::sqrt(1.0 - sinT * sinT), ci = cosOut;
                const double rs = (eta * ci - cosT) / (eta * ci + cosT), rp = (ci - eta * cosT) / (ci + eta * cosT);
                expectedReflectance = 0.5 * (rs * rs + rp * rp);
            }
            const Vec3 wo{float(sinOut), 0, cosOut};
            std::mt19937_64 rng(5);
            test::UniformReal<float> uniform(0.0f, 1.0f);
            constexpr int kTrials = 40000;
            int reflected = 0;
            for (int i = 0; i < kTrials; ++i) {
                const auto s = bsdf.sample(wo, uniform(rng), {uniform(rng), uniform(rng)});
                REQUIRE(s);
                if (!bsdf.lobe(s->lobe).transmits()) {
                    ++reflected;
                    continue;
                }
                // Snell: n_i sin(theta_i) = n_t sin(theta_t), on the other side of the surface.
                const double sinTransmitted = std::sqrt(double(s->wi.x) * s->wi.x + double(s->wi.y) * s->wi.y);
                CHECK(s->wi.z < 0.0f);
                CHECK(sinTransmitted == doctest::Approx(eta * sinOut).epsilon(1e-4));
            }
            const double mean = expectedReflectance * kTrials;
            const double sigma = std::sqrt(kTrials * expectedReflectance * (1.0 - expectedReflectance));
            CHECK(std::fabs(reflected - mean) <= 5.0 * sigma + 1e-9);
        }
    }
}

// Sampling and evaluation must describe one BSDF: every sample's weight is eval / pdf of the
// direction it returned (eval is f |cos theta_i|), and E[weight] = integral of eval over the
// sphere (by uniform sampling, independent of the material's own sampling). With wo below the
// shading normal (smooth meshes at grazing angles: the geometric side and the shading normal
// disagree) eval is 0, so sampling must return nothing or weight 0 too, or BSDF sampling and
// next-event estimation add different light.
template <typename M>
void checkSamplingMatchesEval(const M& material, const char* name) {
    const SurfaceSide side{{0, 0, 1}, true, TransportMode::Radiance};
    for (const float cosOut : {0.9f, 0.3f, -0.05f, -0.4f}) {
        INFO(name << ", cos theta_o " << cosOut);
        const Vec3 wo{std::sqrt(1.0f - cosOut * cosOut), 0, cosOut};
        std::mt19937_64 rng(99);
        test::UniformReal<float> uniform(0.0f, 1.0f);
        constexpr int kDraws = 200000;
        Rgb sampled{0.0f}, integrated{0.0f};
        int mismatches = 0;
        for (int lobe = 0; lobe < int(material.lobes().size()); ++lobe) {
            if (material.lobes()[lobe].delta()) continue;
            for (int i = 0; i < kDraws; ++i) {
                const auto s = material.sample(lobe, side, wo, {uniform(rng), uniform(rng)});
                if (!s) continue;
                const Rgb expected = s->pdf > 0.0f ? material.eval(lobe, side, wo, s->wi) / s->pdf : Rgb{0.0f};
                for (int c = 0; c < 3; ++c)
                    if (std::abs(s->weight[c] - expected[c]) > 1e-3f * (1.0f + expected[c])) ++mismatches;
                sampled += s->weight;
            }
            for (int i = 0; i < kDraws; ++i) {
                const float z = 2.0f * uniform(rng) - 1.0f, phi = 2.0f * kPi * uniform(rng);
                const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
                integrated += material.eval(lobe, side, wo, {r * std::cos(phi), r * std::sin(phi), z});
            }
        }
        CHECK(mismatches == 0);
        sampled /= float(kDraws);
        integrated *= 4.0f * kPi / kDraws;
        for (int c = 0; c < 3; ++c) CHECK(sampled[c] == doctest::Approx(integrated[c]).epsilon(0.02).scale(0.01));
    }
}

TEST_CASE("sampling agrees with eval / pdf, also for wo below the shading normal") {
    checkSamplingMatchesEval(makeMaterial({0.8f, 0.5f, 0.2f}, Rgb{0}, 1), "Lambert");
    checkSamplingMatchesEval(makeMaterial(Rgb{0}, Rgb{0.2f}, 10), "Blinn highlight");
    checkSamplingMatchesEval(makeMaterial<ModifiedPhongMaterial>({0.5f, 0.3f, 0.1f}, Rgb{0.4f}, 10), "modified Phong");
}

// Bsdf keeps the lobe choice of the first wo asked and of the last other one (bdpt alternates a
// hit's wo with its reverse densities' wo): a kept answer must be the one for the wo asked. With
// Fresnel and a red mirror beside blue glass, the delta branches' share, and so the diffuse and
// highlight lobes' probabilities, change with wo.
TEST_CASE("Bsdf::pdf answers as a fresh Bsdf does, whatever wo was asked before") {
    PhongMaterial material = makeMaterial(Rgb{0.5f}, Rgb{0.3f}, 20);
    material.kr = Rgb{0.5f, 0.0f, 0.0f};
    material.kt = Rgb{0.0f, 0.0f, 0.5f};
    material.fresnel = true;
    const Bsdf kept(material, {0, 0, 1}, true);
    std::mt19937_64 rng(7);
    test::UniformReal<float> cosine(0.05f, 1.0f), azimuth(0.0f, 6.2831853f);
    auto direction = [&] {
        const float c = cosine(rng), s = std::sqrt(1.0f - c * c), phi = azimuth(rng);
        return Vec3{s * std::cos(phi), s * std::sin(phi), c};
    };
    const Vec3 own = direction();
    int changed = 0;  // the control: pairs of wo whose lobe choice differs, or the test shows nothing
    for (int i = 0; i < 200; ++i) {
        // The hit's own wo, then two others, then the own again: every slot is hit and replaced.
        const Vec3 wos[] = {own, direction(), direction(), own, direction()};
        const Vec3 wi = direction();
        for (const Vec3& wo : wos) {
            for (int lobe : {int(PhongMaterial::kDiffuse), int(PhongMaterial::kHighlight)}) {
                const Bsdf fresh(material, {0, 0, 1}, true);
                CAPTURE(i);
                CAPTURE(lobe);
                CHECK(kept.pdf(lobe, wo, wi) == fresh.pdf(lobe, wo, wi));
            }
        }
        // The diffuse density is the lobe's choice times cos(wi) / pi: it differs with wo by the choice.
        const Bsdf fresh(material, {0, 0, 1}, true);
        const float atOwn = fresh.pdf(PhongMaterial::kDiffuse, own, wi);
        changed += std::fabs(atOwn - fresh.pdf(PhongMaterial::kDiffuse, wos[1], wi)) > 1e-3f * atOwn;
    }
    CHECK(changed > 100);
    CHECK_FALSE(material.lobeAlbedosIgnoreWo({{0, 0, 1}, true, TransportMode::Radiance}));
}

// Materials whose lobe albedos are constants let Bsdf keep one lobe choice for every wo
// (Material::lobeAlbedosIgnoreWo): their kept answers too are a fresh Bsdf's.
TEST_CASE("Bsdf::pdf of a material with constant lobe albedos: one lobe choice serves every wo") {
    const PhongMaterial phong = makeMaterial(Rgb{0.5f, 0.2f, 0.1f}, Rgb{0.3f}, 20);
    const ModifiedPhongMaterial modified = makeMaterial<ModifiedPhongMaterial>({0.5f, 0.3f, 0.1f}, Rgb{0.4f}, 10);
    std::mt19937_64 rng(11);
    test::UniformReal<float> cosine(-1.0f, 1.0f), azimuth(0.0f, 6.2831853f);
    auto direction = [&] {
        const float c = cosine(rng), s = std::sqrt(1.0f - c * c), phi = azimuth(rng);
        return Vec3{s * std::cos(phi), s * std::sin(phi), c};
    };
    for (const Material* material : {static_cast<const Material*>(&phong), static_cast<const Material*>(&modified)}) {
        CHECK(material->lobeAlbedosIgnoreWo({{0, 0, 1}, true, TransportMode::Radiance}));
        const Bsdf kept(*material, {0, 0, 1}, true);
        for (int i = 0; i < 200; ++i) {
            const Vec3 wo = direction(), wi = direction();
            for (int lobe = 0; lobe < int(kept.lobes().size()); ++lobe) {
                if (kept.lobe(lobe).delta()) continue;
                const Bsdf fresh(*material, {0, 0, 1}, true);
                CAPTURE(i);
                CAPTURE(lobe);
                CHECK(kept.pdf(lobe, wo, wi) == fresh.pdf(lobe, wo, wi));
            }
        }
    }
}

// makeShadingPoint hands the Bsdf the scene analysis's has(l) per lobe: with the material's own
// answers it must sample and weigh exactly as a Bsdf that asks the material; the control, a list
// that claims the highlight absent, must change both (or the list is not read).
TEST_CASE("a Bsdf given its lobes' presence answers as one that asks the material") {
    PhongMaterial material = makeMaterial(Rgb{0.5f}, Rgb{0.3f}, 20);
    material.kr = Rgb{0.2f};
    std::array<bool, kMaxLobes> present{}, wrong{};
    for (int l = 0; l < int(material.lobes().size()); ++l) present[l] = wrong[l] = material.has(l);
    wrong[PhongMaterial::kHighlight] = false;
    const Bsdf asking(material, {0, 0, 1}, true), told(material, {0, 0, 1}, true, TransportMode::Radiance, {}, &present),
        misled(material, {0, 0, 1}, true, TransportMode::Radiance, {}, &wrong);
    CHECK(told.hasSmoothLobe() == asking.hasSmoothLobe());
    std::mt19937_64 rng(11);
    test::UniformReal<float> uniform(0.0f, 1.0f);
    int differs = 0;
    for (int i = 0; i < 500; ++i) {
        const Vec3 wo = glm::normalize(Vec3{uniform(rng) - 0.5f, uniform(rng) - 0.5f, 0.1f + uniform(rng)});
        const float uLobe = uniform(rng);
        const Vec2 u{uniform(rng), uniform(rng)};
        const auto a = asking.sample(wo, uLobe, u), t = told.sample(wo, uLobe, u);
        CAPTURE(i);
        REQUIRE(a.has_value() == t.has_value());
        if (a) {
            CHECK(a->lobe == t->lobe);
            CHECK(a->wi == t->wi);
            CHECK(a->weight == t->weight);
            CHECK(a->pdf == t->pdf);
            CHECK(asking.pdf(PhongMaterial::kDiffuse, wo, a->wi) == told.pdf(PhongMaterial::kDiffuse, wo, a->wi));
            differs += asking.pdf(PhongMaterial::kDiffuse, wo, a->wi) != misled.pdf(PhongMaterial::kDiffuse, wo, a->wi);
        }
    }
    CHECK(differs > 400);
}
}  // namespace
}  // namespace lightpath
