#include "materials/modified_phong_material.h"

#include <algorithm>
#include <cmath>

#include "materials/lambert_lobe.h"
#include "materials/material_type.h"
#include "materials/optics.h"
#include "sampling/warp.h"
#include "util/hot_path.h"

namespace lightpath {
namespace {

// cos(alpha), alpha the angle between wi and the mirror direction of wo.
float cosToMirror(const SurfaceSide& side, const Vec3& wo, const Vec3& wi) {
    return std::max(0.0f, glm::dot(wi, reflectAbout(wo, side.normal)));
}

}  // namespace

bool ModifiedPhongMaterial::has(int lobe) const {
    if (lobe == kDiffuse) return !kd.black();
    if (lobe == kHighlight) return !ks.black();
    return false;
}

LIGHTPATH_HOT_PATH
Rgb ModifiedPhongMaterial::eval(int lobe, const SurfaceSide& side, const Vec3& wo, const Vec3& wi) const {
    if (!side.bothAbove(wo, wi)) return Rgb{0.0f};
    if (lobe == kDiffuse) return lambert::eval(kd.at(side), side, wi);
    if (lobe == kHighlight)
        return ks.at(side) * ((n + 2.0f) / (2.0f * kPi) * std::pow(cosToMirror(side, wo, wi), n) * glm::dot(wi, side.normal));
    return Rgb{0.0f};
}

LIGHTPATH_HOT_PATH
float ModifiedPhongMaterial::pdf(int lobe, const SurfaceSide& side, const Vec3& wo, const Vec3& wi) const {
    if (!side.bothAbove(wo, wi)) return 0.0f;
    if (lobe == kDiffuse) return lambert::pdf(side, wi);
    // cos^n about the mirror direction, (n+1)/(2 pi) cos^n(alpha); directions below the surface
    // are lost, so the lobe's density over the hemisphere integrates to at most 1.
    if (lobe == kHighlight) return phongLobePdf(cosToMirror(side, wo, wi), n);
    return 0.0f;
}

LIGHTPATH_HOT_PATH
std::optional<LobeSample> ModifiedPhongMaterial::sample(int lobe, const SurfaceSide& side, const Vec3& wo,
                                                        Vec2 u) const {
    if (lobe == kDiffuse) return lambert::sample(kd.at(side), side, wo, u);
    if (lobe == kHighlight) {
        if (!(glm::dot(wo, side.normal) > 0.0f)) return std::nullopt;  // eval() is 0 there
        LobeSample s;
        s.wi = Frame(reflectAbout(wo, side.normal)).toWorld(samplePhongLobe(u, n));
        const float cosIn = glm::dot(s.wi, side.normal);
        if (cosIn <= 0.0f) return std::nullopt;
        s.pdf = phongLobePdf(cosToMirror(side, wo, s.wi), n);
        // ks (n+2)/(2 pi) cos^n cos_i over (n+1)/(2 pi) cos^n: the lobe cancels.
        s.weight = ks.at(side) * ((n + 2.0f) / (n + 1.0f) * cosIn);
        return s;
    }
    return std::nullopt;
}

float ModifiedPhongMaterial::albedo(int lobe, const SurfaceSide& side, const Vec3&) const {
    if (lobe == kDiffuse) return kd.maxAt(side);
    if (lobe == kHighlight) return ks.maxAt(side);  // exact at normal incidence, less elsewhere
    return 0.0f;
}

int ModifiedPhongMaterial::factors(int lobe, const SurfaceSide& side, const Vec3& wo, const Vec3& wi,
                                   NamedFactors& factors) const {
    if (lobe == kDiffuse) {
        factors = lambert::factors(kd.at(side), side, wi);
        return 2;
    }
    if (lobe == kHighlight) {
        const float cosIn = glm::dot(side.normal, wi);
        factors = {{{"ks", ks.at(side)}, {"(n+2)/2 cos^n(a) N.L", Rgb{(n + 2.0f) / 2.0f * std::pow(cosToMirror(side, wo, wi), n) * cosIn}}}};
        return 2;
    }
    return 0;
}

}  // namespace lightpath

namespace lightpath {
namespace {

MaterialSlot makeModifiedPhong(const ParameterValues& values) {
    ModifiedPhongMaterial material;
    material.kd = colorParameter(values, "kd");
    material.ks = colorParameter(values, "ks");
    material.n = values.number("n");
    readSurfaceRows(values, material);
    return material;
}

}  // namespace
}  // namespace lightpath

LIGHTPATH_REGISTER_MATERIAL(lightpath::MaterialType{
    {"material", "modified-phong", "Lafortune and Willems' energy-conserving Phong (1994)",
     {{"kd", lightpath::ParameterType::Colour, "", "0", lightpath::kNonNegative, "diffuse albedo, f = kd/π"},
      {"ks", lightpath::ParameterType::Colour, "", "0", lightpath::kNonNegative,
       "specular albedo at normal incidence: `ks (n+2)/(2π) cos^n α`"},
      {"n", lightpath::ParameterType::Number, "", "20", lightpath::kNonNegative,
       "specular exponent: larger is a tighter highlight"},
      lightpath::kEmissionParameter, lightpath::kTwoSidedEmissionParameter, lightpath::kAlphaParameter},
     "<R[DG]>|O"},
    1, lightpath::makeModifiedPhong,
    // Lafortune and Willems 1994: both lobes reciprocal, and kd + ks <= 1 reflects at most 1.
    {{true, true}, [](const lightpath::ParameterValues& v) {
         const lightpath::Rgb sum = v.colour("kd") + v.colour("ks");
         return sum.r <= 1.0f && sum.g <= 1.0f && sum.b <= 1.0f;
     }}})
