#include "materials/phong_material.h"

#include <algorithm>
#include <cmath>

#include "materials/lambert_lobe.h"
#include "materials/material_type.h"
#include "materials/optics.h"
#include "sampling/warp.h"
#include "util/hot_path.h"

namespace lightpath {
namespace {

// The halfway vector between wo and wi; nullopt when they are opposite.
std::optional<Vec3> halfwayOf(const Vec3& wo, const Vec3& wi) {
    const Vec3 sum = wo + wi;
    const float length = glm::length(sum);
    if (length == 0.0f) return std::nullopt;
    return sum / length;
}

// Blinn's form of Phong's highlight: the halfway vector's cosine with the normal, raised to n.
float blinnTerm(const Vec3& normal, const Vec3& wo, const Vec3& wi, float exponent) {
    const std::optional<Vec3> halfway = halfwayOf(wo, wi);
    return halfway ? std::pow(std::max(0.0f, glm::dot(normal, *halfway)), exponent) : 0.0f;
}

}  // namespace

bool PhongMaterial::has(int lobe) const {
    switch (lobe) {
        case kDiffuse: return !kd.black();
        case kHighlight: return !ks.black();
        case kMirror: return !kr.black() || !kt.black();  // kt: total internal reflection
        case kRefraction: return !kt.black();
    }
    return false;
}

LIGHTPATH_HOT_PATH
Rgb PhongMaterial::eval(int lobe, const SurfaceSide& side, const Vec3& wo, const Vec3& wi) const {
    if (!side.bothAbove(wo, wi)) return Rgb{0.0f};
    if (lobe == kDiffuse) return lambert::eval(kd.at(side), side, wi);
    if (lobe == kHighlight) return ks.at(side) * (blinnTerm(side.normal, wo, wi, n) / kPi);
    return Rgb{0.0f};  // a delta lobe has no value to evaluate
}

LIGHTPATH_HOT_PATH
float PhongMaterial::pdf(int lobe, const SurfaceSide& side, const Vec3& wo, const Vec3& wi) const {
    if (!side.bothAbove(wo, wi)) return 0.0f;
    if (lobe == kDiffuse) return lambert::pdf(side, wi);
    if (lobe == kHighlight) {
        const std::optional<Vec3> halfway = halfwayOf(wo, wi);
        if (!halfway) return 0.0f;
        const float cosHalf = glm::dot(*halfway, side.normal), woDotHalf = glm::dot(wo, *halfway);
        if (cosHalf <= 0.0f || woDotHalf <= 0.0f) return 0.0f;
        // The half vector's density, (n+1)/(2 pi) cos^n, times the Jacobian dH/dwi = 1/(4 wo.H).
        return phongLobePdf(cosHalf, n) / (4.0f * woDotHalf);
    }
    return 0.0f;
}

LIGHTPATH_HOT_PATH
std::optional<LobeSample> PhongMaterial::sample(int lobe, const SurfaceSide& side, const Vec3& wo, Vec2 u) const {
    if (lobe == kDiffuse) return lambert::sample(kd.at(side), side, wo, u);
    if (lobe == kHighlight) {
        if (!(glm::dot(wo, side.normal) > 0.0f)) return std::nullopt;  // eval() is 0 there
        LobeSample s;
        const Vec3 halfway = Frame(side.normal).toWorld(samplePhongLobe(u, n));
        const float woDotHalf = glm::dot(wo, halfway);
        if (woDotHalf <= 0.0f) return std::nullopt;
        s.wi = reflectAbout(wo, halfway);
        if (glm::dot(s.wi, side.normal) <= 0.0f) return std::nullopt;
        s.pdf = pdf(lobe, side, wo, s.wi);
        // (ks (H.N)^n / pi) / ((n+1)/(2 pi) (H.N)^n / (4 wo.H)): the lobe's power cancels.
        s.weight = ks.at(side) * (8.0f * woDotHalf / (n + 1.0f));
        return s;
    }
    return std::nullopt;
}

float PhongMaterial::albedo(int lobe, const SurfaceSide& side, const Vec3&) const {
    // A rough albedo of the highlight lobe, only to choose lobes in proportion to what they
    // reflect: ks (H.N)^n / pi integrates to 2 ks for n = 0 and to about 8 ks / (n + 1) for a sharp lobe.
    if (lobe == kDiffuse) return kd.maxAt(side);
    if (lobe == kHighlight) return ks.maxAt(side) * std::min(2.0f, 8.0f / (n + 1.0f));
    return 0.0f;
}

LIGHTPATH_HOT_PATH
int PhongMaterial::specularBranches(const SurfaceSide& side, const Vec3& wo, SpecularBranches& branches) const {
    if (kr.black() && kt.black()) return 0;
    const float cosOut = glm::dot(wo, side.normal);
    if (cosOut <= 0.0f) return 0;
    // n_incident / n_transmitted for light arriving from the side of the normal.
    const float eta = side.entering ? 1.0f / ior : ior;
    const Vec3 mirror = reflectAbout(wo, side.normal);
    const Rgb mirrorWeight = kr.at(side), refractionWeight = kt.at(side);
    const std::optional<Vec3> refracted = kt.black() ? std::nullopt : refractThrough(wo, side.normal, eta);
    if (!refracted) {
        // Total internal reflection: the transmitted share is reflected too.
        const Rgb weight = mirrorWeight + refractionWeight;
        branches[0] = {mirror, weight, kMirror, maxComponent(weight)};
        return isBlack(weight) ? 0 : 1;
    }
    Rgb reflected = mirrorWeight, transmitted = refractionWeight;
    float compression = 1.0f;
    if (fresnel) {
        const float reflectance = fresnelDielectric(cosOut, eta);
        reflected += refractionWeight * reflectance;
        transmitted *= 1.0f - reflectance;
        // Radiance is compressed by (n_i / n_t)^2 as it crosses (pbrt-v4 9.5.2); importance is not.
        if (side.mode == TransportMode::Radiance) compression = eta * eta;
    }
    int count = 0;
    if (!isBlack(reflected)) branches[count++] = {mirror, reflected, kMirror, maxComponent(reflected)};
    branches[count++] = {*refracted, transmitted * compression, kRefraction, maxComponent(transmitted)};
    return count;
}

int PhongMaterial::factors(int lobe, const SurfaceSide& side, const Vec3& wo, const Vec3& wi,
                           NamedFactors& factors) const {
    if (lobe == kDiffuse) {
        factors = lambert::factors(kd.at(side), side, wi);
        return 2;
    }
    if (lobe == kHighlight) {
        factors = {{{"ks", ks.at(side)}, {"(H.N)^n", Rgb{blinnTerm(side.normal, wo, wi, n)}}}};
        return 2;
    }
    return 0;
}

}  // namespace lightpath

namespace lightpath {
namespace {

MaterialSlot makePhong(const ParameterValues& values) {
    PhongMaterial material;
    material.ka = colorParameter(values, "ka");
    material.kd = colorParameter(values, "kd");
    material.ks = colorParameter(values, "ks");
    material.n = values.number("n");
    material.kr = colorParameter(values, "kr");
    material.kt = colorParameter(values, "kt");
    material.ior = values.number("ior");
    material.fresnel = values.boolean("fresnel");
    readSurfaceRows(values, material);
    return material;
}

}  // namespace
}  // namespace lightpath

// The defaults are PhongMaterial's (phong_material.h); the meanings scenes/README.md's table shows.
LIGHTPATH_REGISTER_MATERIAL(lightpath::MaterialType{
    {"material", "phong", "the lecture's illumination formula (Szymczak) with Whitted's mirror and glass",
     {{"ka", lightpath::ParameterType::Colour, "", "0", lightpath::kNonNegative, "ambient reflectance: `ka Ia`"},
      {"kd", lightpath::ParameterType::Colour, "", "0", lightpath::kNonNegative, "diffuse reflectance: `kd (N·L)`"},
      {"ks", lightpath::ParameterType::Colour, "", "0", lightpath::kNonNegative,
       "specular (highlight) reflectance: `ks (H·N)^n`"},
      {"n", lightpath::ParameterType::Number, "", "20", lightpath::kNonNegative,
       "specular exponent: larger is a tighter highlight"},
      {"kr", lightpath::ParameterType::Colour, "", "0", lightpath::kNonNegative, "mirror reflection weight (Whitted)"},
      {"kt", lightpath::ParameterType::Colour, "", "0", lightpath::kNonNegative,
       "transmission (refraction) weight (Whitted)"},
      {"ior", lightpath::ParameterType::Number, "", "1.5", lightpath::kPositive,
       "index of refraction of the inside (glass 1.5, water 1.33)"},
      {"fresnel", lightpath::ParameterType::Boolean, "", "false", {},
       "clear glass: the mirror and refracted rays split `kt` by Fresnel's equations"},
      lightpath::kEmissionParameter, lightpath::kTwoSidedEmissionParameter, lightpath::kAlphaParameter},
     "<R[DGS]>|<TS>|O"},
    0, lightpath::makePhong,
    // Lambert's lobe is reciprocal; Szymczak's highlight ks (H.N)^n / pi is f |cos theta_i|, so f
    // carries 1/cos theta_i and is not. Not energy-conserving by design (docs/design.md).
    {{true, false}, nullptr}})
