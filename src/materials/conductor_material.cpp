#include "materials/conductor_material.h"

#include <algorithm>
#include <cmath>

#include "materials/ggx.h"
#include "materials/material_type.h"
#include "materials/optics.h"
#include "sampling/warp.h"

namespace lightpath {

namespace {

// Visible normals per axis of the stratified grid that integrates the albedo table.
constexpr int kConductorAlbedoStrata = 32;

}  // namespace

ConductorMaterial::ConductorMaterial(Rgb eta, Rgb k, float roughness) : eta_(eta), k_(k), roughness_(roughness) {
    if (smooth()) return;  // the mirror's albedo is F(cos theta_o) exactly
    // E = integral over visible normals m of F(wo.m) G2 / G1 (the sampling weight, Heitz 2018),
    // by the midpoint rule on a stratified grid of sampleVisibleNormal's inputs.
    const float a = alpha();
    for (int node = 0; node < kAlbedoNodes; ++node) {
        const float c = std::max(float(node) / float(kAlbedoNodes - 1), 1e-3f);
        const Vec3 o{std::sqrt(1.0f - c * c), 0.0f, c};
        const float g1 = ggx::masking(o, a);
        Rgb sum{0.0f};
        for (int i = 0; i < kConductorAlbedoStrata; ++i) {
            for (int j = 0; j < kConductorAlbedoStrata; ++j) {
                const Vec2 u{(i + 0.5f) / kConductorAlbedoStrata, (j + 0.5f) / kConductorAlbedoStrata};
                const Vec3 m = ggx::sampleVisibleNormal(o, a, u);
                const Vec3 in = reflectAbout(o, m);
                if (in.z > 0.0f) sum += fresnel(glm::dot(o, m)) * (ggx::maskingShadowing(o, in, a) / g1);
            }
        }
        albedoTable_[node] = sum / float(kConductorAlbedoStrata * kConductorAlbedoStrata);
    }
}

float ConductorMaterial::alpha() const { return std::max(ggx::kMinAlpha, roughness_ * roughness_); }

Rgb ConductorMaterial::fresnel(float cosine) const {
    return {fresnelConductor(cosine, eta_.r, k_.r), fresnelConductor(cosine, eta_.g, k_.g),
            fresnelConductor(cosine, eta_.b, k_.b)};
}

bool ConductorMaterial::has(int lobe) const {
    if (lobe == kGlossy) return !smooth();
    if (lobe == kMirror) return smooth();
    return false;
}

Rgb ConductorMaterial::eval(int lobe, const SurfaceSide& side, const Vec3& wo, const Vec3& wi) const {
    if (lobe != kGlossy || !has(lobe) || !side.bothAbove(wo, wi)) return Rgb{0.0f};
    const Frame frame(side.normal);
    const Vec3 o = frame.toLocal(wo), i = frame.toLocal(wi);
    const Vec3 m = glm::normalize(o + i);
    const float a = alpha();
    // f cos theta_i = F D G2 / (4 cos theta_o)
    return fresnel(glm::dot(o, m)) * (ggx::distribution(m, a) * ggx::maskingShadowing(o, i, a) / (4.0f * o.z));
}

float ConductorMaterial::pdf(int lobe, const SurfaceSide& side, const Vec3& wo, const Vec3& wi) const {
    if (lobe != kGlossy || !has(lobe) || !side.bothAbove(wo, wi)) return 0.0f;
    const Frame frame(side.normal);
    return ggx::reflectionPdf(frame.toLocal(wo), frame.toLocal(wi), alpha());
}

std::optional<LobeSample> ConductorMaterial::sample(int lobe, const SurfaceSide& side, const Vec3& wo, Vec2 u) const {
    if (lobe != kGlossy || !has(lobe)) return std::nullopt;
    const Frame frame(side.normal);
    const Vec3 o = frame.toLocal(wo);
    if (!(o.z > 0.0f)) return std::nullopt;  // eval() is 0 there
    const float a = alpha();
    const Vec3 m = ggx::sampleVisibleNormal(o, a, u);
    const Vec3 i = reflectAbout(o, m);
    if (i.z <= 0.0f) return std::nullopt;
    LobeSample s;
    s.wi = glm::normalize(frame.toWorld(i));
    s.pdf = ggx::reflectionPdf(o, i, a);
    if (!(s.pdf > 0.0f)) return std::nullopt;
    // F D G2 / (4 cos_o) over G1(wo) D / (4 cos_o): F G2 / G1 (Heitz 2018, eq. 19).
    s.weight = fresnel(glm::dot(o, m)) * (ggx::maskingShadowing(o, i, a) / ggx::masking(o, a));
    return s;
}

float ConductorMaterial::albedo(int lobe, const SurfaceSide& side, const Vec3& wo) const {
    if (!has(lobe)) return 0.0f;
    const float cosOut = std::clamp(glm::dot(wo, side.normal), 0.0f, 1.0f);
    if (lobe == kMirror) return maxComponent(fresnel(cosOut));
    const float x = cosOut * float(kAlbedoNodes - 1);
    const int node = std::min(int(x), kAlbedoNodes - 2);
    return maxComponent(glm::mix(albedoTable_[node], albedoTable_[node + 1], x - float(node)));
}

int ConductorMaterial::specularBranches(const SurfaceSide& side, const Vec3& wo, SpecularBranches& branches) const {
    if (!has(kMirror)) return 0;
    const float cosOut = glm::dot(wo, side.normal);
    if (cosOut <= 0.0f) return 0;
    const Rgb weight = fresnel(cosOut);
    branches[0] = {reflectAbout(wo, side.normal), weight, kMirror, maxComponent(weight)};
    return 1;
}

int ConductorMaterial::factors(int lobe, const SurfaceSide& side, const Vec3& wo, const Vec3& wi,
                               NamedFactors& factors) const {
    if (lobe != kGlossy) return 0;
    const Rgb value = eval(lobe, side, wo, wi);
    const Rgb f = fresnel(std::max(0.0f, glm::dot(wo, glm::normalize(wo + wi))));
    // pi eval = F times pi D G2 / (4 N.V)
    Rgb rest{0.0f};
    for (int c = 0; c < 3; ++c) rest[c] = f[c] > 0.0f ? kPi * value[c] / f[c] : 0.0f;
    factors = {{{"F(eta, k)", f}, {"pi D G / (4 N.V)", rest}}};
    return 2;
}

}  // namespace lightpath

namespace lightpath {
namespace {

// Measured metals lie well inside these (silver's k is about 4, aluminium's about 8).
constexpr Range kEtaRange{0.0, 10.0, true, false};
constexpr Range kExtinctionRange{0.0, 20.0, false, false};

MaterialSlot makeConductor(const ParameterValues& values) {
    ConductorMaterial material(values.colour("eta"), values.colour("k"), values.number("roughness"));
    readSurfaceRows(values, material);
    return material;
}

}  // namespace
}  // namespace lightpath

// The defaults are gold's index at about 650, 550 and 450 nm (Johnson and Christy 1972).
LIGHTPATH_REGISTER_MATERIAL(lightpath::MaterialType{
    {"material", "conductor", "a metal by its complex index of refraction: exact Fresnel on GGX microfacets",
     {{"eta", lightpath::ParameterType::Colour, "", "[0.183, 0.421, 1.373]", lightpath::kEtaRange,
       "real part of the metal's index of refraction relative to the outside, per channel"},
      {"k", lightpath::ParameterType::Colour, "", "[3.424, 2.346, 1.770]", lightpath::kExtinctionRange,
       "imaginary part (extinction coefficient) of the index, per channel"},
      lightpath::kGgxRoughnessParameter,
      lightpath::kEmissionParameter, lightpath::kTwoSidedEmissionParameter, lightpath::kAlphaParameter},
     "<R[GS]>|O"},
    4, lightpath::makeConductor,
    // F, D and G2 are symmetric in wo and wi: reciprocal; F <= 1 and G2 <= G1: at most 1.
    {{true, true}, [](const lightpath::ParameterValues&) { return true; }}})
