// The rough dielectric (materials/dielectric_material.h) against references that do not come from
// it: Walter et al. 2007's BSDF written out here in double with its own Fresnel (eq. 22) and
// integrated over the sphere (white furnace), reciprocity with the eta^2 rule, chi-square of its
// sampling against its density with a control that must fail, the smooth glass's branches at
// roughness 0, and the path tracer against bdpt on a rough glass ball over a diffuse floor.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "materials/bsdf.h"
#include "materials/dielectric_material.h"
#include "materials/phong_material.h"
#include "scene/scene_loader.h"
#include "../support/direction_chi_square.h"
#include "../support/material_harness.h"
#include "../support/paired_agreement.h"
#include "../support/pinhole_reference.h"
#include "../support/uniform_real.h"

namespace lightpath {
namespace dielectric_test {

constexpr double kPiD = 3.14159265358979323846;

struct V3 {
    double x, y, z;
};
V3 operator+(V3 a, V3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
V3 operator*(double s, V3 a) { return {s * a.x, s * a.y, s * a.z}; }
double dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V3 normalized(V3 a) { return (1.0 / std::sqrt(dot(a, a))) * a; }
V3 toV3(const Vec3& v) { return {v.x, v.y, v.z}; }

// Walter et al. 2007, eq. 22: unpolarised Fresnel reflectance for c = |i.m|, from index ni into nt.
double walterFresnel(double c, double ni, double nt) {
    const double g2 = nt * nt / (ni * ni) - 1.0 + c * c;
    if (g2 < 0.0) return 1.0;  // total internal reflection
    const double g = std::sqrt(g2);
    const double a = (g - c) / (g + c), b = (c * (g + c) - 1.0) / (c * (g - c) + 1.0);
    return 0.5 * a * a * (1.0 + b * b);
}

// GGX D (eq. 33) and Smith's height-correlated G2 from Lambda (Heitz 2014, eq. 99), in double.
double ggxD(V3 m, double alpha) {
    if (m.z <= 0.0) return 0.0;
    const double a2 = alpha * alpha, c2 = m.z * m.z, t = 1.0 + (a2 - 1.0) * c2;
    return a2 / (kPiD * t * t);
}
double ggxLambda(V3 w, double alpha) {
    const double c2 = w.z * w.z;
    return 0.5 * (std::sqrt(1.0 + alpha * alpha * (1.0 - c2) / c2) - 1.0);
}
double smithG2(V3 o, V3 i, double alpha) { return 1.0 / (1.0 + ggxLambda(o, alpha) + ggxLambda(i, alpha)); }

// Walter's f_s(i, o) |cos theta_i| for radiance, in his notation: o the outgoing (camera) direction
// on the side of index no (o.z > 0), i the incident one, ni the index on the other side.
// Reflection eq. 20, transmission eq. 21 with the half vectors of eqs. 13 and 16.
double walterBsdfCos(V3 o, V3 i, double alpha, double no, double ni) {
    if (i.z > 0.0) {
        const V3 h = normalized(o + i);
        return walterFresnel(dot(o, h), no, ni) * smithG2(o, i, alpha) * ggxD(h, alpha) / (4.0 * o.z);
    }
    V3 h = normalized(-1.0 * (no * o + ni * i));
    if (h.z < 0.0) h = -1.0 * h;
    const double ih = dot(i, h), oh = dot(o, h);
    if (oh <= 0.0 || ih >= 0.0) return 0.0;
    const double denominator = ni * ih + no * oh;
    return std::fabs(ih) * oh / o.z * no * no * (1.0 - walterFresnel(oh, no, ni)) * smithG2(o, i, alpha) *
           ggxD(h, alpha) / (denominator * denominator);
}

struct Albedos {
    double reflected = 0.0, transmitted = 0.0;  // transmitted: in the importance form (no eta^2)
};

// The reference albedos: walterBsdfCos integrated over the sphere of i by the midpoint rule in
// spherical coordinates about the lobe's own axis (the mirror direction above, the refracted one or
// the horizon below), theta = pi s^2 so the steps are finest at the peak.
Albedos referenceAlbedos(V3 o, double alpha, double no, double ni) {
    const double eta = no / ni, cosT2 = 1.0 - eta * eta * (1.0 - o.z * o.z);
    const V3 mirror{-o.x, -o.y, o.z};
    const V3 refracted = cosT2 > 0.0 ? normalized(V3{-eta * o.x, -eta * o.y, -std::sqrt(cosT2)})
                                     : normalized(V3{-o.x, -o.y, -1e-3});
    const int steps = 1500, turns = 240;
    Albedos result;
    for (const bool above : {true, false}) {
        const V3 axis = above ? mirror : refracted;
        // A frame about the axis.
        const V3 u = normalized(std::fabs(axis.z) < 0.9 ? V3{-axis.y, axis.x, 0.0} : V3{0.0, -axis.z, axis.y});
        const V3 v{axis.y * u.z - axis.z * u.y, axis.z * u.x - axis.x * u.z, axis.x * u.y - axis.y * u.x};
        double sum = 0.0;
        for (int t = 0; t < steps; ++t) {
            const double s = (t + 0.5) / steps, theta = kPiD * s * s, dTheta = 2.0 * kPiD * s / steps;
            const double st = std::sin(theta), ct = std::cos(theta);
            for (int p = 0; p < turns; ++p) {
                const double phi = 2.0 * kPiD * (p + 0.5) / turns;
                const V3 i = ct * axis + (st * std::cos(phi)) * u + (st * std::sin(phi)) * v;
                if ((i.z > 0.0) != above || i.z == 0.0) continue;
                sum += walterBsdfCos(o, i, alpha, no, ni) * st * dTheta * (2.0 * kPiD / turns);
            }
        }
        (above ? result.reflected : result.transmitted) = above ? sum : sum * (ni * ni) / (no * no);
    }
    return result;
}

// The code's albedos from wo, by its own sampling: the integral of its weights over the unit square
// of inputs by the midpoint rule, with u.x = 1 - (1 - s)^2 so that the steps are finest at u.x = 1,
// the rim of the visible-normal disk where the rare steep facets are (beyond the critical angle,
// only they transmit).
Albedos sampledAlbedos(const DielectricMaterial& material, const SurfaceSide& side, const Vec3& wo) {
    constexpr int kGrid = 256;
    Albedos result;
    for (int a = 0; a < kGrid; ++a) {
        const double s = (a + 0.5) / kGrid, jacobian = 2.0 * (1.0 - s);
        for (int b = 0; b < kGrid; ++b) {
            const Vec2 u{float(1.0 - (1.0 - s) * (1.0 - s)), (b + 0.5f) / kGrid};
            if (const auto r = material.sample(DielectricMaterial::kGlossyReflection, side, wo, u))
                result.reflected += r->weight.g * jacobian;
            if (const auto t = material.sample(DielectricMaterial::kGlossyTransmission, side, wo, u))
                result.transmitted += t->weight.g * jacobian;
        }
    }
    result.reflected /= kGrid * kGrid;
    result.transmitted /= kGrid * kGrid;
    return result;
}

TEST_CASE("dielectric: white furnace, reflectance plus transmittance is Walter's BSDF integrated over the sphere, never above 1" *
          doctest::test_suite("statistical")) {
    constexpr float kIor = 1.5f;
    for (const bool entering : {true, false}) {
        const double no = entering ? 1.0 : kIor, ni = entering ? kIor : 1.0;
        const SurfaceSide side{{0, 0, 1}, entering, TransportMode::Importance};
        // From inside, 0.5 lies beyond the critical angle (cos 0.745): only tilted facets transmit.
        for (const double cosOut : entering ? std::vector<double>{0.9, 0.6, 0.25} : std::vector<double>{0.95, 0.8, 0.5}) {
            for (const float roughness : {0.1f, 0.3f, 0.6f, 1.0f}) {
                CAPTURE(entering);
                CAPTURE(cosOut);
                CAPTURE(roughness);
                const DielectricMaterial material(kIor, Rgb{1.0f}, roughness);
                const Vec3 wo = test::outgoing(cosOut, 0.7);
                const Albedos reference = referenceAlbedos(toV3(wo), double(roughness) * roughness, no, ni);
                const Albedos measured = sampledAlbedos(material, side, wo);
                CAPTURE(reference.reflected);
                CAPTURE(reference.transmitted);
                CAPTURE(measured.transmitted);
                CHECK(reference.reflected + reference.transmitted <= 1.0 + 1e-3);
                CHECK(measured.reflected + measured.transmitted <= 1.0);
                CHECK(measured.reflected == doctest::Approx(reference.reflected).epsilon(0.01).scale(0.0));
                // 1%, or 2e-4 absolute where (beyond the critical angle) hardly anything crosses.
                CHECK(std::fabs(measured.transmitted - reference.transmitted) <= std::max(0.01 * reference.transmitted, 2e-4));
                // Radiance is compressed by (n_o / n_i)^2 as it crosses; importance is not.
                const SurfaceSide radiance{{0, 0, 1}, entering, TransportMode::Radiance};
                const auto s = material.sample(DielectricMaterial::kGlossyTransmission, radiance, wo, {0.3f, 0.6f});
                const auto t = material.sample(DielectricMaterial::kGlossyTransmission, side, wo, {0.3f, 0.6f});
                if (s && t) CHECK(s->weight.g == doctest::Approx(t->weight.g * no * no / (ni * ni)).epsilon(1e-5));
            }
        }
    }
}

TEST_CASE("dielectric: eval is Walter's BSDF and reciprocal with the eta^2 rule, f(wo, wi) / n_o^2 = f(wi, wo) / n_i^2") {
    std::mt19937_64 rng(5);
    test::UniformReal<double> uniform(0.0, 1.0);
    const Rgb tint{0.9f, 0.7f, 0.4f};
    for (const float roughness : {0.1f, 0.4f, 1.0f}) {
        const DielectricMaterial material(1.5f, tint, roughness);
        for (const bool entering : {true, false}) {
            const double no = entering ? 1.0 : 1.5, ni = entering ? 1.5 : 1.0;
            const SurfaceSide side{{0, 0, 1}, entering, TransportMode::Radiance};
            // The same interface seen from wi's side, and the caller's side kept (bdpt's reverse densities).
            const SurfaceSide fromBelow{{0, 0, -1}, !entering, TransportMode::Radiance};
            for (int n = 0; n < 400; ++n) {
                const bool through = n % 2 == 1;
                const int lobe = through ? DielectricMaterial::kGlossyTransmission : DielectricMaterial::kGlossyReflection;
                const Vec3 wo = test::outgoing(0.05 + 0.95 * uniform(rng), 2.0 * kPi * uniform(rng));
                Vec3 wi = test::outgoing(0.05 + 0.95 * uniform(rng), 2.0 * kPi * uniform(rng));
                if (through) wi.z = -wi.z;
                const SurfaceSide& wiSide = through ? fromBelow : side;
                const double forward = material.eval(lobe, side, wo, wi).g / std::fabs(wi.z);
                const double backward = material.eval(lobe, wiSide, wi, wo).g / std::fabs(wo.z);
                const double backwardSameSide = material.eval(lobe, side, wi, wo).g / std::fabs(wo.z);
                const double walter = walterBsdfCos(toV3(wo), toV3(wi), double(roughness) * roughness, no, ni) /
                                      std::fabs(wi.z) * (through ? tint.g : 1.0);
                CAPTURE(through);
                CAPTURE(wo.z);
                CAPTURE(wi.z);
                CHECK(forward == doctest::Approx(walter).epsilon(2e-3));
                const double nWi = through ? ni : no;
                // Relative, but for values below 1e-3 (the lobes reach 1-100): those are held to 2e-6.
                // They arise at grazing facets (o.m near 0.003) and at the critical angle from inside
                // (o.m near 0.745, where 1 - F vanishes): ill-conditioned there, the two evaluations
                // round apart by up to 2% of values of 1e-7 to 7e-5 (the forward one within 0.2% of Walter's).
                CHECK(forward / (no * no) == doctest::Approx(backward / (nWi * nWi)).epsilon(2e-3).scale(1e-3));
                CHECK(backwardSameSide == doctest::Approx(backward).epsilon(1e-5));
            }
        }
    }
}

double chiSquareP(const Bsdf& sampled, const Bsdf& density, const Vec3& wo) {
    test::DirectionHistogram histogram;
    histogram.subdivisions = 24;
    test::UniformReal<float> uniform(0.0f, 1.0f);
    return test::directionChiSquarePValue(
        histogram,
        [&](std::mt19937_64& rng) -> std::optional<Vec3> {
            const auto s = sampled.sample(wo, uniform(rng), {uniform(rng), uniform(rng)});
            return s ? std::optional<Vec3>(s->wi) : std::nullopt;
        },
        [&](const Vec3& wi) {
            return double(density.pdf(DielectricMaterial::kGlossyReflection, wo, wi) +
                          density.pdf(DielectricMaterial::kGlossyTransmission, wo, wi));
        });
}

TEST_CASE("dielectric: chi-square, reflection and transmission sampling follow their density, outside and inside") {
    constexpr int kTests = 6;
    const double significance = 1.0 - std::pow(1.0 - 0.01, 1.0 / kTests);
    const struct {
        float roughness, cosOut;
        bool entering;
    } cases[kTests] = {{0.3f, 0.9f, true}, {0.6f, 0.3f, true}, {1.0f, 0.6f, true},
                       {0.3f, 0.9f, false}, {0.5f, 0.6f, false}, {0.8f, 0.3f, false}};
    for (const auto& c : cases) {
        CAPTURE(c.roughness);
        CAPTURE(c.cosOut);
        CAPTURE(c.entering);
        const DielectricMaterial material(1.5f, Rgb{1.0f}, c.roughness);
        const Bsdf bsdf(material, {0, 0, 1}, c.entering);
        CHECK(chiSquareP(bsdf, bsdf, test::outgoing(c.cosOut, 4.0)) > significance);
    }
    // The control: the density of a slightly different index (1.6) must be told apart.
    const DielectricMaterial glass(1.5f, Rgb{1.0f}, 0.3f), denser(1.6f, Rgb{1.0f}, 0.3f);
    CHECK(chiSquareP(Bsdf(glass, {0, 0, 1}, true), Bsdf(denser, {0, 0, 1}, true), test::outgoing(0.9, 4.0)) < significance);
}

// Walter et al. 2007's choice (section 5.3): reflect with probability F at the sampled visible
// normal, so with a white tint every sample's weight is Heitz 2018's G2(o, i) / G1(o), in [0, 1],
// whatever F does over the facets (in the importance form, which has no (n_o/n_i)^2). A choice made
// before the facet, in proportion to the lobes' albedos, weighs F(m) / P(reflect): above 1 at grazing.
TEST_CASE("dielectric: reflection or transmission is chosen by F at the sampled facet, each weight G2 / G1") {
    std::mt19937_64 rng(17);
    test::UniformReal<float> uniform(0.0f, 1.0f);
    for (const float roughness : {0.3f, 0.7f})
        for (const double cosOut : {0.15, 0.8})
            for (const bool entering : {true, false}) {
                CAPTURE(roughness);
                CAPTURE(cosOut);
                CAPTURE(entering);
                const DielectricMaterial material(1.5f, Rgb{1.0f}, roughness);
                const Bsdf bsdf(material, {0, 0, 1}, entering, TransportMode::Importance);
                const Vec3 wo = test::outgoing(cosOut, 1.0);
                const double alpha = double(roughness) * double(roughness);
                int worst = 0, reflected = 0, sampled = 0;
                for (int n = 0; n < 4096; ++n) {
                    const auto s = bsdf.sample(wo, uniform(rng), {uniform(rng), uniform(rng)});
                    if (!s) continue;
                    ++sampled;
                    reflected += s->lobe == DielectricMaterial::kGlossyReflection;
                    const V3 o = toV3(wo), i = toV3(s->wi);
                    const double expected = smithG2(o, V3{i.x, i.y, std::fabs(i.z)}, alpha) * (1.0 + ggxLambda(o, alpha));
                    worst += std::fabs(double(s->weight.g) - expected) > 2e-3 * std::max(1.0, expected);
                }
                CHECK(worst == 0);
                CHECK(sampled > 3000);
                CHECK(reflected > 0);
                CHECK(reflected < sampled);
            }
}

TEST_CASE("dielectric: at roughness 0 it is the smooth Fresnel glass, the same directions and weights, deltas <RS> and <TS>") {
    const DielectricMaterial smooth(1.5f, Rgb{1.0f}, 0.0f), tinted(1.5f, Rgb{0.9f, 0.5f, 0.2f}, 0.0f);
    PhongMaterial glass;
    glass.kt = Rgb{1.0f};
    glass.ior = 1.5f;
    glass.fresnel = true;
    PhongMaterial tintedGlass = glass;
    tintedGlass.kt = Rgb{0.9f, 0.5f, 0.2f};
    CHECK(!Bsdf(smooth, {0, 0, 1}, true).hasSmoothLobe());
    CHECK(smooth.lobes()[DielectricMaterial::kMirror].event == PhongMaterial::kLobes[PhongMaterial::kMirror].event);
    CHECK(smooth.lobes()[DielectricMaterial::kRefraction].event == PhongMaterial::kLobes[PhongMaterial::kRefraction].event);
    for (const TransportMode mode : {TransportMode::Radiance, TransportMode::Importance}) {
        for (const bool entering : {true, false}) {
            const SurfaceSide side{{0, 0, 1}, entering, mode};
            for (const double cosOut : {1.0, 0.9, 0.5, 0.3, 0.1}) {  // inside, 0.5 and below are total reflection
                CAPTURE(entering);
                CAPTURE(cosOut);
                const Vec3 wo = test::outgoing(cosOut, 1.3);
                SpecularBranches ours, theirs, tintedOurs, tintedTheirs;
                const int count = smooth.specularBranches(side, wo, ours);
                REQUIRE(count == glass.specularBranches(side, wo, theirs));
                for (int b = 0; b < count; ++b) {
                    CHECK(ours[b].wi == theirs[b].wi);
                    CHECK(ours[b].weight == theirs[b].weight);
                    CHECK(ours[b].albedo == theirs[b].albedo);
                    CHECK(smooth.lobes()[ours[b].lobe].event == PhongMaterial::kLobes[theirs[b].lobe].event);
                }
                // A tint colours the refracted ray only, as kt does; the mirror ray keeps F.
                REQUIRE(tinted.specularBranches(side, wo, tintedOurs) == count);
                tintedGlass.specularBranches(side, wo, tintedTheirs);
                if (count == 2) {
                    CHECK(tintedOurs[0].weight == ours[0].weight);
                    CHECK(tintedOurs[1].weight == tintedTheirs[1].weight);
                }
            }
        }
    }
    // And the rough lobes approach it: at roughness 0.02 they reflect F and transmit 1 - F.
    const DielectricMaterial nearlySmooth(1.5f, Rgb{1.0f}, 0.02f);
    const SurfaceSide side{{0, 0, 1}, true, TransportMode::Importance};
    const Vec3 wo = test::outgoing(0.7);
    SpecularBranches branches;
    REQUIRE(smooth.specularBranches(side, wo, branches) == 2);
    const Albedos rough = sampledAlbedos(nearlySmooth, side, wo);
    CHECK(rough.reflected == doctest::Approx(branches[0].weight.g).epsilon(0.01));
    CHECK(rough.transmitted == doctest::Approx(branches[1].weight.g).epsilon(0.01));
    const auto refracted = nearlySmooth.sample(DielectricMaterial::kGlossyTransmission, side, wo, {0.5f, 0.5f});
    REQUIRE(refracted);
    CHECK(glm::length(refracted->wi - branches[1].wi) < 0.02f);
}

// A rough glass ball filled with an absorbing medium, against a uniform sky: what passes straight
// through (E <TG> <TG> L) is dimmed by Beer-Lambert's exp(-sigma_a chord), the chord 2 R cos(theta_t)
// of the ray refracted by Snell's law at its impact parameter b (sin theta_t = b / (R ior)); a
// roughness of 0.05 bends rays by well under a degree. Its control: without the switch into the
// interior, nothing is dimmed.
// The scene's beauty and `set` under the path tracer.
Film renderPath(const Scene& scene, const std::vector<lpe::NamedExpression>& set, int spp) {
    const AovSet aovs(set);
    RenderOptions options;
    options.integrator = "path";
    options.samplesPerPixel = spp;
    options.seed = 5;
    return Renderer(scene, aovs, options).render().film;
}

TEST_CASE("dielectric: rough glass switches media, light through an absorbing interior is dimmed by exp(-sigma_a chord)") {
    constexpr double kRadius = 0.5, kIor = 1.5;
    const Rgb sigmaA{0.2f, 0.6f, 1.2f};
    const auto ballScene = [&](bool absorbing) {
        std::string text = R"(
            [camera]
            eye = [0, 0, 6]
            look_at = [0, 0, 0]
            fov = 4
            resolution = [8, 8]
            [world]
            background = 1
            [media.ink]
            sigma_a = [0.2, 0.6, 1.2]
            [materials.frosted]
            type = "dielectric"
            ior = 1.5
            roughness = 0.05
            [[spheres]]
            center = [0, 0, 0]
            radius = 0.5
            material = "frosted"
        )";
        if (absorbing) text += "interior = \"ink\"\n";
        return loadSceneFromText(text, "ink-ball.toml");
    };
    const std::vector<lpe::NamedExpression> through{{"through", "E<TG><TG>L"}};
    const Scene clear = ballScene(false), inked = ballScene(true);
    const Film clearFilm = renderPath(clear, through, 128), inkedFilm = renderPath(inked, through, 128);

    const CameraDescription& camera = clear.camera;
    for (int c = 0; c < 3; ++c) {
        CAPTURE(c);
        double expected = 0.0, seen = 0.0, undimmed = 0.0;
        for (int j = 0; j < camera.height; ++j)
            for (int i = 0; i < camera.width; ++i) {
                const glm::dvec3 d = test::pixelDirection(camera, i, j);
                const glm::dvec3 eye(camera.eye);
                const double b = glm::length(glm::cross(-eye, d));  // the ray's distance from the centre
                const double sinT = b / (kRadius * kIor);
                const double chord = 2.0 * kRadius * std::sqrt(1.0 - sinT * sinT);
                expected += clearFilm.at(1, i, j)[c] * std::exp(-double(sigmaA[c]) * chord);
                seen += inkedFilm.at(1, i, j)[c];
                undimmed += clearFilm.at(1, i, j)[c];
            }
        REQUIRE(undimmed > 0.0);
        CHECK(seen / expected == doctest::Approx(1.0).epsilon(0.005));
        CHECK(seen / undimmed < 0.9);  // the control: the interior is dense enough to tell
    }
}

TEST_CASE("dielectric: the path tracer and bdpt agree on a rough glass ball over a diffuse floor (t-test)" *
          doctest::test_suite("statistical")) {
    Scene scene = loadScene(LIGHTPATH_SOURCE_DIR "/tests/render/data/cornell-rough-glass.toml");
    scene.camera.width = scene.camera.height = 24;
    const Film bdpt = test::renderClassesFilm(scene, "bdpt", 512, 11), path = test::renderClassesFilm(scene, "path", 512, 11);
    test::checkPairedAgreement(bdpt, path, 0.001);
}

}  // namespace dielectric_test
}  // namespace lightpath
