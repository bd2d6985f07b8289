#include "materials/dielectric_material.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "materials/ggx.h"
#include "materials/material_type.h"
#include "materials/optics.h"
#include "sampling/warp.h"

namespace lightpath {

namespace {

// Visible normals per axis of the stratified grid that integrates the albedo tables.
constexpr int kDielectricAlbedoStrata = 32;

// Walter et al. 2007, eq. 16: the microfacet normal that refracts o into i, eta = n_i / n_o, turned
// to the side of o (z > 0); nullopt where no facet does (both on one side of it, or a back face).
std::optional<Vec3> refractionHalfVector(const Vec3& o, const Vec3& i, float eta) {
    Vec3 m = eta * i + o;
    const float length = glm::length(m);
    if (!(length > 0.0f)) return std::nullopt;
    m /= length;
    if (m.z < 0.0f) m = -m;
    if (!(glm::dot(m, o) > 0.0f) || !(glm::dot(m, i) < 0.0f)) return std::nullopt;
    return m;
}

// The density of refracting o into i through a sampled visible normal m: D_o(m) times the Jacobian
// |dm/di| = |i.m| / (i.m + o.m / eta)^2 (Walter et al. 2007, eq. 17).
float refractionPdf(const Vec3& o, const Vec3& i, const Vec3& m, float eta, float alpha) {
    const float denominator = glm::dot(i, m) + glm::dot(o, m) / eta;
    if (!(denominator * denominator > 0.0f)) return 0.0f;
    const float visible = ggx::masking(o, alpha) * ggx::distribution(m, alpha) * glm::dot(o, m) / o.z;
    return visible * std::fabs(glm::dot(i, m)) / (denominator * denominator);
}

}  // namespace

struct DielectricMaterial::View {
    Frame frame;
    float eta;     // n_beyond / n_wo
    bool outside;  // wo is on the material's outside
    // Radiance crossing from beyond into wo's side is scaled by (n_wo / n_beyond)^2; importance is not.
    float compression(TransportMode mode) const { return mode == TransportMode::Radiance ? 1.0f / (eta * eta) : 1.0f; }
    // Fresnel reflectance at a facet of cosine c with o (optics.h's eta is n_incident / n_transmitted).
    float fresnel(float c) const { return fresnelDielectric(std::clamp(c, 0.0f, 1.0f), 1.0f / eta); }
};

DielectricMaterial::View DielectricMaterial::viewFrom(const SurfaceSide& side, const Vec3& wo) const {
    const bool flipped = glm::dot(wo, side.normal) < 0.0f;
    const bool outside = side.entering != flipped;
    return {Frame(flipped ? -side.normal : side.normal), outside ? ior_ : 1.0f / ior_, outside};
}

DielectricMaterial::DielectricMaterial(float ior, ColorParameter tint, float roughness)
    : ior_(ior), tint_(std::move(tint)), roughness_(roughness) {
    if (smooth()) return;  // the deltas' albedos are F and 1 - F exactly
    // E = integral over visible normals m of the sampling weight (F or 1 - F) G2 / G1 (Heitz 2018),
    // by the midpoint rule on a stratified grid of sampleVisibleNormal's inputs.
    const float a = alpha();
    for (int inside = 0; inside < 2; ++inside) {
        const float eta = inside ? 1.0f / ior_ : ior_;  // n_beyond / n_wo
        for (int node = 0; node < kAlbedoNodes; ++node) {
            const float c = std::max(float(node) / float(kAlbedoNodes - 1), 1e-3f);
            const Vec3 o{std::sqrt(1.0f - c * c), 0.0f, c};
            const float g1 = ggx::masking(o, a);
            double reflected = 0.0, transmitted = 0.0;
            for (int i = 0; i < kDielectricAlbedoStrata; ++i) {
                for (int j = 0; j < kDielectricAlbedoStrata; ++j) {
                    const Vec2 u{(i + 0.5f) / kDielectricAlbedoStrata, (j + 0.5f) / kDielectricAlbedoStrata};
                    const Vec3 m = ggx::sampleVisibleNormal(o, a, u);
                    const float f = fresnelDielectric(std::clamp(glm::dot(o, m), 0.0f, 1.0f), 1.0f / eta);
                    const Vec3 in = reflectAbout(o, m);
                    if (in.z > 0.0f) reflected += f * ggx::maskingShadowing(o, in, a) / g1;
                    const std::optional<Vec3> through = refractThrough(o, m, 1.0f / eta);
                    if (through && through->z < 0.0f) transmitted += (1.0f - f) * ggx::maskingShadowing(o, *through, a) / g1;
                }
            }
            constexpr double kCells = kDielectricAlbedoStrata * kDielectricAlbedoStrata;
            reflectionAlbedo_[inside][node] = float(reflected / kCells);
            transmissionAlbedo_[inside][node] = float(transmitted / kCells);
        }
    }
}

float DielectricMaterial::alpha() const { return std::max(ggx::kMinAlpha, roughness_ * roughness_); }

bool DielectricMaterial::has(int lobe) const {
    switch (lobe) {
        case kGlossyReflection: return !smooth();
        case kGlossyTransmission: return !smooth() && !tint_.black();
        case kMirror: return smooth();
        case kRefraction: return smooth() && !tint_.black();
    }
    return false;
}

Rgb DielectricMaterial::eval(int lobe, const SurfaceSide& side, const Vec3& wo, const Vec3& wi) const {
    if (!has(lobe) || lobes()[lobe].delta()) return Rgb{0.0f};
    const View view = viewFrom(side, wo);
    const Vec3 o = view.frame.toLocal(wo), i = view.frame.toLocal(wi);
    if (!(o.z > 0.0f)) return Rgb{0.0f};
    const float a = alpha();
    if (lobe == kGlossyReflection) {
        if (!(i.z > 0.0f)) return Rgb{0.0f};
        const Vec3 m = glm::normalize(o + i);
        return Rgb{view.fresnel(glm::dot(o, m)) * ggx::distribution(m, a) * ggx::maskingShadowing(o, i, a) / (4.0f * o.z)};
    }
    if (!(i.z < 0.0f)) return Rgb{0.0f};
    const std::optional<Vec3> m = refractionHalfVector(o, i, view.eta);
    if (!m) return Rgb{0.0f};
    const float denominator = glm::dot(i, *m) + glm::dot(o, *m) / view.eta;
    const float value = (1.0f - view.fresnel(glm::dot(o, *m))) * ggx::distribution(*m, a) * ggx::maskingShadowing(o, i, a) *
                        std::fabs(glm::dot(i, *m)) * glm::dot(o, *m) / (o.z * denominator * denominator);
    return tint_.at(side) * (value * view.compression(side.mode));
}

float DielectricMaterial::pdf(int lobe, const SurfaceSide& side, const Vec3& wo, const Vec3& wi) const {
    if (!has(lobe) || lobes()[lobe].delta()) return 0.0f;
    const View view = viewFrom(side, wo);
    const Vec3 o = view.frame.toLocal(wo), i = view.frame.toLocal(wi);
    if (!(o.z > 0.0f)) return 0.0f;
    if (lobe == kGlossyReflection) return ggx::reflectionPdf(o, i, alpha());
    if (!(i.z < 0.0f)) return 0.0f;
    const std::optional<Vec3> m = refractionHalfVector(o, i, view.eta);
    return m ? refractionPdf(o, i, *m, view.eta, alpha()) : 0.0f;
}

std::optional<LobeSample> DielectricMaterial::sample(int lobe, const SurfaceSide& side, const Vec3& wo, Vec2 u) const {
    if (!has(lobe) || lobes()[lobe].delta()) return std::nullopt;
    const View view = viewFrom(side, wo);
    const Vec3 o = view.frame.toLocal(wo);
    if (!(o.z > 0.0f)) return std::nullopt;  // eval() is 0 there
    const float a = alpha();
    const Vec3 m = ggx::sampleVisibleNormal(o, a, u);
    Vec3 i;
    if (lobe == kGlossyReflection) {
        i = reflectAbout(o, m);
        if (i.z <= 0.0f) return std::nullopt;
    } else {
        const std::optional<Vec3> through = refractThrough(o, m, 1.0f / view.eta);
        if (!through || through->z >= 0.0f) return std::nullopt;  // total internal reflection at m: the mirror lobe's
        i = *through;
    }
    LobeSample s;
    s.wi = glm::normalize(view.frame.toWorld(i));
    // The weight is eval / pdf, in which all but the sampling weight (F or 1 - F) G2 / G1 cancels
    // (Heitz 2018, eq. 19); computed as that quotient, from the same floats as eval() and pdf():
    // near the critical angle F has a square-root edge, where the sampled m's rounding would show.
    s.pdf = pdf(lobe, side, wo, s.wi);
    if (!(s.pdf > 0.0f)) return std::nullopt;
    s.weight = eval(lobe, side, wo, s.wi) / s.pdf;
    return s;
}

float DielectricMaterial::reflectionChoice(const View& view, const SurfaceSide& side, float c) const {
    const float f = view.fresnel(c);
    const float transmitted = has(kGlossyTransmission) ? (1.0f - f) * tint_.maxAt(side) : 0.0f;
    return f + transmitted > 0.0f ? f / (f + transmitted) : 1.0f;
}

std::optional<ChosenLobeSample> DielectricMaterial::sampleChosenLobe(const SurfaceSide& side, const Vec3& wo, float uLobe,
                                                                     Vec2 u) const {
    const View view = viewFrom(side, wo);
    const Vec3 o = view.frame.toLocal(wo);
    if (!(o.z > 0.0f)) return std::nullopt;
    const Vec3 m = ggx::sampleVisibleNormal(o, alpha(), u);
    Vec3 i;
    int lobe;
    if (uLobe < reflectionChoice(view, side, glm::dot(o, m))) {
        i = reflectAbout(o, m);
        lobe = kGlossyReflection;
        if (i.z <= 0.0f) return std::nullopt;
    } else {
        const std::optional<Vec3> through = refractThrough(o, m, 1.0f / view.eta);
        lobe = kGlossyTransmission;
        if (!through || through->z >= 0.0f) return std::nullopt;
        i = *through;
    }
    ChosenLobeSample s{lobe, {}};
    s.sample.wi = glm::normalize(view.frame.toWorld(i));
    // As in sample(): the quotient of eval and the density, from the same floats.
    s.sample.pdf = chosenLobePdf(lobe, side, wo, s.sample.wi);
    if (!(s.sample.pdf > 0.0f)) return std::nullopt;
    s.sample.weight = eval(lobe, side, wo, s.sample.wi) / s.sample.pdf;
    return s;
}

float DielectricMaterial::chosenLobePdf(int lobe, const SurfaceSide& side, const Vec3& wo, const Vec3& wi) const {
    const float within = pdf(lobe, side, wo, wi);
    if (!(within > 0.0f)) return 0.0f;
    const View view = viewFrom(side, wo);
    const Vec3 o = view.frame.toLocal(wo), i = view.frame.toLocal(wi);
    const std::optional<Vec3> m = lobe == kGlossyReflection ? std::optional<Vec3>(glm::normalize(o + i))
                                                            : refractionHalfVector(o, i, view.eta);
    if (!m) return 0.0f;
    const float reflecting = reflectionChoice(view, side, glm::dot(o, *m));
    return within * (lobe == kGlossyReflection ? reflecting : 1.0f - reflecting);
}

float DielectricMaterial::albedo(int lobe, const SurfaceSide& side, const Vec3& wo) const {
    if (!has(lobe) || lobes()[lobe].delta()) return 0.0f;  // the deltas' shares are their branches'
    const View view = viewFrom(side, wo);
    const float cosOut = std::clamp(std::fabs(glm::dot(wo, side.normal)), 0.0f, 1.0f);
    const auto& table = lobe == kGlossyReflection ? reflectionAlbedo_[view.outside ? 0 : 1]
                                                  : transmissionAlbedo_[view.outside ? 0 : 1];
    const float x = cosOut * float(kAlbedoNodes - 1);
    const int node = std::min(int(x), kAlbedoNodes - 2);
    const float e = glm::mix(table[node], table[node + 1], x - float(node));
    return lobe == kGlossyReflection ? e : e * tint_.maxAt(side) * view.compression(side.mode);
}

int DielectricMaterial::specularBranches(const SurfaceSide& side, const Vec3& wo, SpecularBranches& branches) const {
    if (!smooth()) return 0;
    const float cosOut = glm::dot(wo, side.normal);
    if (cosOut <= 0.0f) return 0;
    // The smooth glass's branches (PhongMaterial::specularBranches with kr = 0, kt = tint and
    // fresnel), except that the reflection is not tinted: the tint is a transmittance.
    const float eta = side.entering ? 1.0f / ior_ : ior_;  // n_wo / n_beyond
    const Vec3 mirror = reflectAbout(wo, side.normal);
    const std::optional<Vec3> refracted = refractThrough(wo, side.normal, eta);
    if (!refracted) {  // total internal reflection
        branches[0] = {mirror, Rgb{1.0f}, kMirror, 1.0f};
        return 1;
    }
    const float reflectance = fresnelDielectric(cosOut, eta);
    int count = 0;
    if (reflectance > 0.0f) branches[count++] = {mirror, Rgb{reflectance}, kMirror, reflectance};
    if (!tint_.black()) {
        const Rgb transmitted = tint_.at(side) * (1.0f - reflectance);
        const float compression = side.mode == TransportMode::Radiance ? eta * eta : 1.0f;
        branches[count++] = {*refracted, transmitted * compression, kRefraction, maxComponent(transmitted)};
    }
    return count;
}

int DielectricMaterial::factors(int lobe, const SurfaceSide& side, const Vec3& wo, const Vec3& wi,
                                NamedFactors& factors) const {
    if (!has(lobe) || lobes()[lobe].delta()) return 0;
    const Rgb value = eval(lobe, side, wo, wi);
    if (isBlack(value)) return 0;
    const View view = viewFrom(side, wo);
    const Vec3 o = view.frame.toLocal(wo), i = view.frame.toLocal(wi);
    const Vec3 m = lobe == kGlossyReflection ? glm::normalize(o + i) : refractionHalfVector(o, i, view.eta).value_or(Vec3{0, 0, 1});
    const float f = view.fresnel(glm::dot(o, m));
    const Rgb first = lobe == kGlossyReflection ? Rgb{f} : tint_.at(side) * (1.0f - f);
    Rgb rest{0.0f};
    for (int c = 0; c < 3; ++c) rest[c] = first[c] > 0.0f ? kPi * value[c] / first[c] : 0.0f;
    if (lobe == kGlossyReflection)
        factors = {{{"F", first}, {"pi D G / (4 N.V)", rest}}};
    else
        factors = {{{"tint (1 - F)", first}, {"pi D G |dm/dwi| (V.m) / N.V", rest}}};
    return 2;
}

}  // namespace lightpath

namespace lightpath {
namespace {

constexpr Range kDielectricRoughnessRange{0.0, 1.0, false, false};

MaterialSlot makeDielectric(const ParameterValues& values) {
    DielectricMaterial material(values.number("ior"), colorParameter(values, "tint"), values.number("roughness"));
    readSurfaceRows(values, material);
    return material;
}

}  // namespace
}  // namespace lightpath

LIGHTPATH_REGISTER_MATERIAL(lightpath::MaterialType{
    {"material", "dielectric",
     "rough glass (Walter et al. 2007): exact Fresnel on GGX microfacets, reflected and refracted",
     {{"ior", lightpath::ParameterType::Number, "", "1.5", lightpath::kPositive,
       "index of refraction of the inside relative to the outside (glass 1.5, water 1.33)"},
      {"roughness", lightpath::ParameterType::Number, "", "0.5", lightpath::kDielectricRoughnessRange,
       "GGX alpha = roughness²; 0 is smooth glass (`<RS>`, `<TS>`), above 0 glossy lobes (`<RG>`, `<TG>`)"},
      {"tint", lightpath::ParameterType::Colour, "", "1", lightpath::kNonNegative,
       "transmittance colour: multiplies the refracted light, not the reflected"},
      lightpath::kEmissionParameter, lightpath::kTwoSidedEmissionParameter, lightpath::kAlphaParameter},
     "<[RT][GS]>|O"},
    5, lightpath::makeDielectric,
    // Reflection: F, D and G2 are symmetric in wo and wi. Transmission: reciprocal only with the
    // eta^2 rule, f(wo, wi) / n_o^2 = f(wi, wo) / n_i^2. Conserves energy in the importance form.
    // A textured tint promises nothing (an image may hold values above 1).
    {{true, false}, [](const lightpath::ParameterValues& values) {
         if (values.texture("tint") != nullptr) return false;
         const lightpath::Rgb tint = values.colour("tint");
         return tint.r <= 1.0f && tint.g <= 1.0f && tint.b <= 1.0f;
     }}})
