#include "material_checks.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <string>

#include "direction_chi_square.h"
#include "lpe/automaton.h"
#include "lpe/path_string.h"
#include "materials/bsdf.h"
#include "monte_carlo.h"
#include "sanitizer.h"
#include "statistics.h"
#include "uniform_real.h"

namespace lightpath::conformance {
namespace {

constexpr Vec3 kNormal{0.0f, 0.0f, 1.0f};
constexpr int kChiSquareSamples = 100000;
// Each sample's weight is checked exactly (no statistic): the sanitizer stage runs a fifth of them
// (support/sanitizer.h).
constexpr int kWeightSamples = test::sanitizedCount(20000);
constexpr int kMonteCarloSamples = 200000;
// The reference of the Bsdf's one-sample estimate: eval over a defensive mixture (below).
constexpr int kMixtureSamples = 50000;
constexpr std::size_t kMixtureCentres = 8;

SurfaceSide sideOf(bool entering, TransportMode mode = TransportMode::Radiance) { return {kNormal, entering, mode}; }

Vec3 fromCos(float cosTheta, float phi = 0.0f) {
    const float sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
    return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta};
}

bool finite(const Rgb& v) { return std::isfinite(v.r) && std::isfinite(v.g) && std::isfinite(v.b); }
bool finiteNonNegative(const Rgb& v) { return finite(v) && v.r >= 0.0f && v.g >= 0.0f && v.b >= 0.0f; }
bool close(float a, float b, float relative) { return std::fabs(a - b) <= relative * (std::fabs(b) + 1e-4f); }
bool close(const Rgb& a, const Rgb& b, float relative) {
    return close(a.r, b.r, relative) && close(a.g, b.g, relative) && close(a.b, b.b, relative);
}
double sum(const Rgb& v) { return double(v.r) + v.g + v.b; }

std::string nameOf(const Material& material, int lobe) { return std::string(material.lobes()[lobe].name) + " lobe"; }

// Every smooth lobe the material declares, present or not.
template <typename Visit>
void forEachSmoothLobe(const Material& material, Visit&& visit) {
    const Lobes lobes = material.lobes();
    for (int l = 0; l < int(lobes.size()); ++l)
        if (!lobes[l].delta()) visit(l);
}

using test::Moments;
using test::momentsOf;

// The sum of the delta branches' weights from wo: what the Bsdf's delta lobes carry in all.
Rgb branchTotal(const Material& material, const SurfaceSide& side, const Vec3& wo) {
    SpecularBranches branches;
    const int count = material.specularBranches(side, wo, branches);
    Rgb total{0.0f};
    for (int b = 0; b < count; ++b) total += branches[b].weight;
    return total;
}

// Directions from a defensive mixture (Hesterberg 1995): half uniform over the sphere, half von
// Mises-Fisher lobes of several widths about `centres`. eval / density() estimates the integral
// of eval without bias whatever the centres are, and where they sit in a sharp lobe (a GGX
// roughness of 0.1 reflects into 1e-4 of the sphere, which uniform directions all but miss) the
// estimate's variance stays finite. Only eval() and this density enter it: the Bsdf's sample()
// merely places the centres.
class DefensiveMixture {
public:
    explicit DefensiveMixture(std::vector<glm::dvec3> centres) : centres_(std::move(centres)) {}

    Vec3 sample(std::mt19937_64& rng) const {
        std::uniform_real_distribution<double> u(0.0, 1.0);
        if (centres_.empty() || u(rng) < 0.5) return test::uniformSphereDirection(rng);
        const glm::dvec3& mean = centres_[std::size_t(u(rng) * double(centres_.size())) % centres_.size()];
        const double kappa = kKappas[std::size_t(u(rng) * double(kKappas.size())) % kKappas.size()];
        // Wenzel Jakob, "Numerically stable sampling of the von Mises Fisher distribution" (2012).
        const double xi = u(rng), phi = 2.0 * M_PI * u(rng);
        const double w = 1.0 + std::log(xi + (1.0 - xi) * std::exp(-2.0 * kappa)) / kappa;
        const double r = std::sqrt(std::max(0.0, 1.0 - w * w));
        const glm::dvec3 t = std::fabs(mean.x) > 0.5 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
        const glm::dvec3 a = glm::normalize(glm::cross(t, mean)), b = glm::cross(mean, a);
        return Vec3(glm::normalize(r * std::cos(phi) * a + r * std::sin(phi) * b + w * mean));
    }

    // The mixture's density at `direction`, taken as exactly unit length (in double): a float's
    // length error of 1e-7 would move a lobe of kappa 1e7 by a factor e.
    double density(const Vec3& direction) const {
        const glm::dvec3 d = glm::normalize(glm::dvec3(direction));
        double lobes = 0.0;
        for (const glm::dvec3& mean : centres_) {
            const double below = glm::dot(mean, d) - 1.0;
            for (const double kappa : kKappas)
                if (kappa * below > -60.0)  // a lobe's value below 1e-26 of its peak: nothing to add
                    lobes += kappa / (2.0 * M_PI * -std::expm1(-2.0 * kappa)) * std::exp(kappa * below);
        }
        const double uniform = 1.0 / (4.0 * M_PI);
        return centres_.empty() ? uniform : 0.5 * uniform + 0.5 * lobes / double(centres_.size() * kKappas.size());
    }

private:
    static constexpr std::array<double, 5> kKappas{30.0, 1e3, 3e4, 1e6, 3e7};
    std::vector<glm::dvec3> centres_;
};

}  // namespace

std::vector<Vec3> outgoingDirections() { return {fromCos(0.95f), fromCos(0.6f, 1.0f), fromCos(0.15f, 4.0f)}; }

CheckResult checkSamplingMatchesPdf(const Material& material, int lobe, const Vec3& wo, bool entering) {
    CheckResult result;
    const SurfaceSide side = sideOf(entering);
    test::DirectionHistogram histogram;
    histogram.samples = kChiSquareSamples;
    // A GGX lobe of alpha 0.05 at grazing incidence is a few sub-cells wide at 12 per axis, where
    // the midpoint rule misses it by more than the test resolves; 24 integrates it.
    histogram.subdivisions = 24;
    test::UniformReal<float> uniform(0.0f, 1.0f);
    const double p = test::directionChiSquarePValue(
        histogram,
        [&](std::mt19937_64& rng) -> std::optional<Vec3> {
            const Vec2 u{uniform(rng), uniform(rng)};
            const auto s = material.sample(lobe, side, wo, u);
            return s ? std::optional<Vec3>(s->wi) : std::nullopt;
        },
        [&](const Vec3& wi) { return double(material.pdf(lobe, side, wo, wi)); });
    if (!(p > kMaterialAlpha))
        result.fail(nameOf(material, lobe), " from wo.z = ", wo.z, ": chi-square p-value ", p, " <= ", kMaterialAlpha,
                    ": sample() does not draw directions with the density pdf() claims");
    return result;
}

CheckResult checkSampleWeights(const Material& material, const Vec3& wo) {
    CheckResult result;
    std::mt19937_64 rng(99);
    test::UniformReal<float> uniform(0.0f, 1.0f);
    for (const bool entering : {true, false}) {
        const SurfaceSide side = sideOf(entering);
        for (const Vec3& from : {wo, Vec3{wo.x, wo.y, -wo.z}}) {  // also from below the shading normal
            forEachSmoothLobe(material, [&](int lobe) {
                if (!material.has(lobe)) return;
                for (int i = 0; i < kWeightSamples; ++i) {
                    const auto s = material.sample(lobe, side, from, {uniform(rng), uniform(rng)});
                    if (!s) continue;
                    const float pdf = material.pdf(lobe, side, from, s->wi);
                    const Rgb expected = pdf > 0.0f ? material.eval(lobe, side, from, s->wi) / pdf : Rgb{0.0f};
                    if (!close(s->pdf, pdf, 1e-3f) && pdf > 0.0f)
                        result.fail(nameOf(material, lobe), " from wo.z = ", from.z, ": sample's pdf ", s->pdf, " but pdf() says ", pdf);
                    if (!close(s->weight, expected, 1e-3f))
                        result.fail(nameOf(material, lobe), " from wo.z = ", from.z, " to wi.z = ", s->wi.z, ": weight ",
                                    s->weight.g, " but eval/pdf is ", expected.g);
                }
            });
            const Bsdf bsdf(material, kNormal, entering);
            for (int i = 0; i < kWeightSamples; ++i) {
                const auto s = bsdf.sample(from, uniform(rng), {uniform(rng), uniform(rng)});
                if (!s || bsdf.lobe(s->lobe).delta()) continue;
                const float pdf = bsdf.pdf(s->lobe, from, s->wi);
                const Rgb expected = pdf > 0.0f ? bsdf.eval(s->lobe, from, s->wi) / pdf : Rgb{0.0f};
                if (!close(s->pdf, pdf, 1e-3f) && pdf > 0.0f)
                    result.fail("Bsdf, ", nameOf(material, s->lobe), " from wo.z = ", from.z, ": sample's pdf ", s->pdf,
                                " but Bsdf::pdf says ", pdf);
                if (!close(s->weight, expected, 1e-3f))
                    result.fail("Bsdf, ", nameOf(material, s->lobe), " from wo.z = ", from.z, ": weight ", s->weight.g,
                                " but eval/pdf is ", expected.g);
            }
        }
    }
    return result;
}

CheckResult checkReciprocity(const Material& material, int lobe) {
    // A transmission lobe connects the two sides: wi is taken below the surface.
    const float sign = material.lobes()[lobe].transmits() ? -1.0f : 1.0f;
    CheckResult result;
    std::mt19937_64 rng(4);
    test::UniformReal<float> uniform(0.0f, 1.0f);
    for (const bool entering : {true, false}) {
        const SurfaceSide sides = sideOf(entering);
        for (int i = 0; i < 4000; ++i) {
            const Vec3 a = fromCos(0.05f + 0.95f * uniform(rng), 2.0f * kPi * uniform(rng));
            const Vec3 b = fromCos(sign * (0.05f + 0.95f * uniform(rng)), 2.0f * kPi * uniform(rng));
            // f(a, b) from a's side, f(b, a) from b's (the shading normal is on the side of wo).
            const SurfaceSide fromB{sign * kNormal, entering == (sign > 0.0f), TransportMode::Radiance};
            const Rgb forward = material.eval(lobe, sides, a, b) / std::fabs(b.z);
            const Rgb backward = material.eval(lobe, fromB, b, a) / std::fabs(a.z);
            if (!close(forward, backward, 1e-3f))
                result.fail(nameOf(material, lobe), ": f(wo, wi) = ", forward.g, " but f(wi, wo) = ", backward.g,
                            " (wo.z = ", a.z, ", wi.z = ", b.z, ")");
        }
    }
    return result;
}

CheckResult checkEnergyConservation(const Material& material) {
    CheckResult result;
    std::mt19937_64 rng(17);
    test::UniformReal<float> uniform(0.0f, 1.0f);
    for (const bool entering : {true, false}) {
        const Bsdf bsdf(material, kNormal, entering, TransportMode::Importance);
        for (float cosOut : {1.0f, 0.7f, 0.4f, 0.1f, 0.02f}) {
            const Vec3 wo = fromCos(cosOut);
            std::vector<double> channel[3];
            for (int i = 0; i < kMonteCarloSamples; ++i) {
                const auto s = bsdf.sample(wo, uniform(rng), {uniform(rng), uniform(rng)});
                const Rgb w = s ? s->weight : Rgb{0.0f};
                for (int c = 0; c < 3; ++c) channel[c].push_back(w[c]);
            }
            for (int c = 0; c < 3; ++c) {
                const Moments m = momentsOf(channel[c]);
                // 1% for the float rounding of the weights, and 4.75 standard errors (one-sided 1e-6).
                const double bound = 1.01 + 4.75 * std::sqrt(m.variance / m.count);
                if (!(m.mean <= bound))
                    result.fail("white furnace from wo.z = ", cosOut, (entering ? "" : " (inside)"), ": channel ", c,
                                " reflects ", m.mean, " of the incident light (more than 1)");
            }
        }
    }
    return result;
}

CheckResult checkLobeAlbedo(const Material& material, int lobe) {
    CheckResult result;
    const SurfaceSide side = sideOf(true);
    const Vec3 wo = kNormal;
    std::mt19937_64 rng(23);
    test::UniformReal<float> uniform(0.0f, 1.0f);
    // The lobe's reflectance by its own sampling (checkSampleWeights and the chi-square hold it to eval).
    Rgb reflectance{0.0f};
    for (int i = 0; i < kMonteCarloSamples; ++i)
        if (const auto s = material.sample(lobe, side, wo, {uniform(rng), uniform(rng)})) reflectance += s->weight;
    reflectance /= float(kMonteCarloSamples);
    const float claimed = material.albedo(lobe, side, wo), measured = maxComponent(reflectance);
    if (!(claimed >= measured / 1.5f && claimed <= 1.5f * measured))
        result.fail(nameOf(material, lobe), ": albedo() says ", claimed, " at normal incidence, the lobe reflects ", measured);
    return result;
}

CheckResult checkDeclaredLobes(const Material& material, const std::string& events) {
    CheckResult result;
    const Lobes lobes = material.lobes();
    // An interface (index-matched boundary) scatters nothing: no lobes, no events, and rays cross it.
    if (material.isInterface()) {
        if (!lobes.empty() || !events.empty()) result.fail("an interface declares lobes or events: ", events);
        return result;
    }
    if (lobes.empty() || lobes.size() > std::size_t(kMaxLobes))
        result.fail(lobes.size(), " lobes declared: a material has 1 to ", kMaxLobes);
    const lpe::Automaton automaton = lpe::Automaton::compile({{"events", events}});
    for (int l = 0; l < int(lobes.size()); ++l) {
        const lpe::Path path{lpe::Event{lobes[l].event.type, lobes[l].event.scatter, ""}};
        if (!automaton.matches(path, 0))
            result.fail(nameOf(material, l), ": its event ", lpe::toExpressionString(path),
                        " is not among the type's declared events ", events);
    }
    return result;
}

CheckResult checkBsdfUnbiased(const Material& material, const Vec3& wo, bool entering) {
    CheckResult result;
    const Bsdf bsdf(material, kNormal, entering);
    const SurfaceSide side = sideOf(entering);
    std::mt19937_64 rng(31);
    test::UniformReal<float> uniform(0.0f, 1.0f);
    std::vector<double> sampled, reference;
    for (int i = 0; i < kMonteCarloSamples; ++i) {
        const auto s = bsdf.sample(wo, uniform(rng), {uniform(rng), uniform(rng)});
        sampled.push_back(s ? sum(s->weight) : 0.0);
    }
    const double delta = sum(branchTotal(material, side, wo));
    std::vector<glm::dvec3> centres;
    std::mt19937_64 centreRng(37);
    for (int i = 0; i < 4096 && centres.size() < kMixtureCentres; ++i)
        if (const auto s = bsdf.sample(wo, uniform(centreRng), {uniform(centreRng), uniform(centreRng)}))
            centres.push_back(glm::normalize(glm::dvec3(s->wi)));
    const DefensiveMixture mixture(std::move(centres));
    for (int i = 0; i < kMixtureSamples; ++i) {
        const Vec3 wi = mixture.sample(rng);
        double value = 0.0;
        forEachSmoothLobe(material, [&](int lobe) { value += sum(material.eval(lobe, side, wo, wi)); });
        reference.push_back(value / mixture.density(wi) + delta);
    }
    const Moments a = momentsOf(sampled), b = momentsOf(reference);
    const double p = test::welchTTest(a.mean, a.variance, a.count, b.mean, b.variance, b.count);
    if (!(p > kMaterialAlpha))
        result.fail("from wo.z = ", wo.z, (entering ? "" : " (inside)"), ": the Bsdf's samples average ", a.mean,
                    " but its lobes reflect ", b.mean, " (Welch p = ", p, ")");
    return result;
}

CheckResult checkFiniteNonNegative(const Material& material) {
    CheckResult result;
    std::mt19937_64 rng(41);
    test::UniformReal<float> uniform(0.0f, 1.0f);
    for (const TransportMode mode : {TransportMode::Radiance, TransportMode::Importance}) {
        for (const bool entering : {true, false}) {
            const SurfaceSide side = sideOf(entering, mode);
            const Bsdf bsdf(material, kNormal, entering, mode);
            for (int i = 0; i < 5000; ++i) {
                // Every fifth pair exactly at the horizon, opposite, or equal: where formulas divide by 0.
                Vec3 wo = test::uniformSphereDirection(rng), wi = test::uniformSphereDirection(rng);
                if (i % 5 == 0) wo = fromCos(0.0f, 0.3f);
                if (i % 10 == 1) wi = -wo;
                if (i % 10 == 2) wi = wo;
                forEachSmoothLobe(material, [&](int lobe) {
                    const Rgb f = material.eval(lobe, side, wo, wi);
                    const float pdf = material.pdf(lobe, side, wo, wi), albedo = material.albedo(lobe, side, wo);
                    if (!finiteNonNegative(f)) result.fail(nameOf(material, lobe), ": eval is ", f.r, " ", f.g, " ", f.b);
                    if (!(std::isfinite(pdf) && pdf >= 0.0f)) result.fail(nameOf(material, lobe), ": pdf is ", pdf);
                    if (!(std::isfinite(albedo) && albedo >= 0.0f)) result.fail(nameOf(material, lobe), ": albedo is ", albedo);
                    const auto s = material.sample(lobe, side, wo, {uniform(rng), uniform(rng)});
                    if (s && !(finiteNonNegative(s->weight) && std::isfinite(s->pdf) && s->pdf >= 0.0f &&
                               std::fabs(glm::length(s->wi) - 1.0f) < 1e-3f))
                        result.fail(nameOf(material, lobe), ": a sample has weight ", s->weight.g, ", pdf ", s->pdf,
                                    ", |wi| ", glm::length(s->wi));
                });
                SpecularBranches branches;
                const int count = material.specularBranches(side, wo, branches);
                for (int b = 0; b < count; ++b)
                    if (!(finiteNonNegative(branches[b].weight) && std::isfinite(branches[b].albedo) && branches[b].albedo >= 0.0f))
                        result.fail("branch ", b, ": weight ", branches[b].weight.g, ", albedo ", branches[b].albedo);
                const auto s = bsdf.sample(wo, uniform(rng), {uniform(rng), uniform(rng)});
                if (s && !(finiteNonNegative(s->weight) && std::isfinite(s->pdf) && s->pdf >= 0.0f))
                    result.fail("Bsdf sample: weight ", s->weight.g, ", pdf ", s->pdf);
            }
        }
    }
    return result;
}

CheckResult checkSpecularBranches(const Material& material) {
    CheckResult result;
    std::mt19937_64 rng(53);
    test::UniformReal<float> uniform(0.0f, 1.0f);
    for (const bool entering : {true, false}) {
        const SurfaceSide side = sideOf(entering, TransportMode::Importance);
        for (int i = 0; i < 2000; ++i) {
            const Vec3 wo = fromCos(0.02f + 0.98f * uniform(rng), 2.0f * kPi * uniform(rng));
            SpecularBranches branches;
            const int count = material.specularBranches(side, wo, branches);
            if (count < 0 || count > 2) {
                result.fail(count, " branches");
                continue;
            }
            // Bsdf asks for branches only when a delta lobe is present: none may come without one.
            bool deltaPresent = false;
            for (int l = 0; l < int(material.lobes().size()); ++l)
                deltaPresent = deltaPresent || (material.lobes()[l].delta() && material.has(l));
            if (count > 0 && !deltaPresent) result.fail(count, " branches, but no delta lobe is present (has())");
            for (int b = 0; b < count; ++b) {
                const SpecularBranch& branch = branches[b];
                if (!close(branch.albedo, maxComponent(branch.weight), 1e-5f))
                    result.fail("branch ", b, ": albedo ", branch.albedo, " but its weight's largest channel is ",
                                maxComponent(branch.weight));
                if (branch.lobe < 0 || branch.lobe >= int(material.lobes().size())) {
                    result.fail("branch ", b, " names lobe ", branch.lobe, ", which the material does not declare");
                } else if (!material.lobes()[branch.lobe].delta()) {
                    result.fail("branch ", b, " names a smooth lobe");
                } else if (!material.lobes()[branch.lobe].transmits()) {
                    const Vec3 mirror = 2.0f * wo.z * kNormal - wo;
                    if (glm::length(branch.wi - mirror) > 1e-4f)
                        result.fail("mirror branch from wo.z = ", wo.z, " leaves at wi.z = ", branch.wi.z, ", not ", mirror.z);
                } else {
                    const float offPlane = glm::dot(branch.wi, glm::normalize(glm::cross(kNormal, wo)));
                    if (!(branch.wi.z < 0.0f) || std::fabs(offPlane) > 1e-4f)
                        result.fail("refracted branch from wo.z = ", wo.z, " at wi.z = ", branch.wi.z,
                                    " is not on the other side in the plane of incidence");
                    // Back through the surface from the other side: Snell's law read both ways gives wo again.
                    const SurfaceSide other{-kNormal, !entering, TransportMode::Importance};
                    SpecularBranches back;
                    const int backCount = material.specularBranches(other, branch.wi, back);
                    bool returned = false;
                    for (int k = 0; k < backCount; ++k)
                        returned = returned || (material.lobes()[back[k].lobe].transmits() && glm::length(back[k].wi - wo) < 2e-3f);
                    if (!returned)
                        result.fail("refraction is not reversible: refracting wi.z = ", branch.wi.z,
                                    " back does not return to wo.z = ", wo.z);
                }
            }
        }
    }
    return result;
}

CheckResult checkMaterial(const MaterialCase& c) {
    const Material& material = *c.material;
    CheckResult result;
    result.merge(checkFiniteNonNegative(material));
    result.merge(checkSpecularBranches(material));
    result.merge(checkDeclaredLobes(material, c.claims.events));
    forEachSmoothLobe(material, [&](int lobe) {
        if (!material.has(lobe)) return;
        for (const Vec3& wo : outgoingDirections()) result.merge(checkSamplingMatchesPdf(material, lobe, wo));
        result.merge(checkLobeAlbedo(material, lobe));
        if (c.claims.reciprocal[lobe]) result.merge(checkReciprocity(material, lobe));
    });
    for (const Vec3& wo : outgoingDirections()) {
        result.merge(checkSampleWeights(material, wo));
        for (const bool entering : {true, false}) result.merge(checkBsdfUnbiased(material, wo, entering));
    }
    if (c.claims.conservesEnergy) result.merge(checkEnergyConservation(material));
    return result;
}

}  // namespace lightpath::conformance
