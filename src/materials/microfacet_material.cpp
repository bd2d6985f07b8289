#include "materials/microfacet_material.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "materials/ggx.h"
#include "materials/lambert_lobe.h"
#include "materials/material_type.h"
#include "materials/optics.h"
#include "sampling/warp.h"

namespace lightpath {
namespace {

// Visible normals per axis of the stratified grid that integrates the specular albedo table.
constexpr int kAlbedoStrata = 64;

// The GGX reflection lobe's f cos theta_i = F D G2 / (4 cos theta_o), in the local frame.
Rgb ggxReflection(const Rgb& f0, float alpha, const Vec3& o, const Vec3& i) {
    const Vec3 m = glm::normalize(o + i);
    return MicrofacetMaterial::fresnel(f0, glm::dot(o, m)) *
           (ggx::distribution(m, alpha) * ggx::maskingShadowing(o, i, alpha) / (4.0f * o.z));
}

}  // namespace

MicrofacetMaterial::AlbedoTable MicrofacetMaterial::albedoTable(float roughness, int strata) {
    AlbedoTable table;
    const float a = std::max(ggx::kMinAlpha, roughness * roughness);
    for (int k = 0; k < kAlbedoNodes; ++k) {
        const float cosine = float(k) / float(kAlbedoNodes - 1);
        if (roughness == 0.0f) {  // the mirror reflects F(cos theta_o) exactly
            table.bias[k] = schlickWeight(cosine);
            table.scale[k] = 1.0f - table.bias[k];
            continue;
        }
        // E = integral over visible normals m of F(wo.m) G2 / G1 (the sampling weight, Heitz 2018),
        // by the midpoint rule on a stratified grid of sampleVisibleNormal's inputs.
        const float c = std::max(cosine, 1e-3f);
        const Vec3 o{std::sqrt(1.0f - c * c), 0.0f, c};
        const float g1 = ggx::masking(o, a);
        double scale = 0.0, bias = 0.0;
        for (int i = 0; i < strata; ++i) {
            for (int j = 0; j < strata; ++j) {
                const Vec2 u{(i + 0.5f) / strata, (j + 0.5f) / strata};
                const Vec3 m = ggx::sampleVisibleNormal(o, a, u);
                const Vec3 in = reflectAbout(o, m);
                if (in.z <= 0.0f) continue;
                const float weight = ggx::maskingShadowing(o, in, a) / g1;
                const float grazing = schlickWeight(glm::dot(o, m));
                scale += weight * (1.0f - grazing);
                bias += weight * grazing;
            }
        }
        table.scale[k] = float(scale / (strata * strata));
        table.bias[k] = float(bias / (strata * strata));
    }
    // 2 integral of E(mu) mu dmu by the trapezoid rule on the table's nodes.
    for (int k = 0; k < kAlbedoNodes; ++k) {
        const float mu = float(k) / float(kAlbedoNodes - 1);
        const float w = (k == 0 || k == kAlbedoNodes - 1) ? 0.5f : 1.0f;
        table.averageScale += table.scale[k] * (2.0f * mu * w / float(kAlbedoNodes - 1));
        table.averageBias += table.bias[k] * (2.0f * mu * w / float(kAlbedoNodes - 1));
    }
    return table;
}

std::vector<MicrofacetMaterial::AlbedoTable> MicrofacetMaterial::albedoTables(const ScalarParameter& roughness) {
    std::vector<AlbedoTable> tables;
    if (!roughness.textured()) {
        tables.push_back(albedoTable(roughness.constant(), kAlbedoStrata));
    } else {
        // Coarser strata: nine tables, and E varies smoothly with roughness.
        for (int n = 0; n < kRoughnessNodes; ++n)
            tables.push_back(albedoTable(float(n) / float(kRoughnessNodes - 1), kAlbedoStrata / 2));
    }
    return tables;
}

std::pair<int, float> MicrofacetMaterial::roughnessNode(float roughness) {
    const float x = std::clamp(roughness, 0.0f, 1.0f) * float(kRoughnessNodes - 1);
    const int node = std::min(int(x), kRoughnessNodes - 2);
    return {node, x - float(node)};
}

MicrofacetMaterial::MicrofacetMaterial(ColorParameter baseColor, ScalarParameter metallic, ScalarParameter roughness,
                                       const Rgb& dielectricF0)
    : MicrofacetMaterial(std::move(baseColor), std::move(metallic), std::move(roughness), dielectricF0, Clearcoat{}) {}

MicrofacetMaterial::MicrofacetMaterial(ColorParameter baseColor, ScalarParameter metallic, ScalarParameter roughness,
                                       const Rgb& dielectricF0, Clearcoat clearcoat)
    : baseColor_(std::move(baseColor)), metallic_(std::move(metallic)), roughness_(std::move(roughness)),
      dielectricF0_(glm::clamp(dielectricF0, Rgb{0.0f}, Rgb{1.0f})), coat_(std::move(clearcoat)),
      coated_(coat_.weight.textured() || coat_.weight.constant() > 0.0f) {
    tables_ = albedoTables(roughness_);
    if (coated_) coatTables_ = albedoTables(coat_.roughness);
    constant_ = shadingOf(baseColor_.constant(), metallic_.constant(), roughness_.constant(), coat_.weight.constant(),
                          coat_.roughness.constant());
    // The untextured base's average from E at each node (2 integral of E(mu) mu dmu, trapezoids).
    constant_.averageAlbedo = Rgb{0.0f};
    for (int k = 0; k < kAlbedoNodes; ++k) {
        const float mu = float(k) / float(kAlbedoNodes - 1);
        const float w = (k == 0 || k == kAlbedoNodes - 1) ? 0.5f : 1.0f;
        constant_.averageAlbedo += specularAlbedo(constant_.f0, mu, constant_) * (2.0f * mu * w / float(kAlbedoNodes - 1));
    }
    constant_.averageAlbedo = glm::min(Rgb{1.0f}, constant_.averageAlbedo);
}

Rgb MicrofacetMaterial::fresnel(const Rgb& f0, float cosine) {
    return f0 + (Rgb{1.0f} - f0) * schlickWeight(cosine);
}

MicrofacetMaterial::Shading MicrofacetMaterial::shadingAt(const SurfaceSide& side) const {
    if (!baseColor_.varies() && !metallic_.textured() && !roughness_.textured() && !coat_.weight.textured() &&
        !coat_.roughness.textured())
        return constant_;
    return shadingOf(baseColor_.at(side), metallic_.at(side), roughness_.at(side), coat_.weight.at(side),
                     coat_.roughness.at(side));
}

MicrofacetMaterial::Shading MicrofacetMaterial::shadingOf(const Rgb& baseColor, float metallic, float roughness,
                                                          float coat, float coatRoughness) const {
    Shading shading;
    metallic = std::clamp(metallic, 0.0f, 1.0f);
    roughness = std::clamp(roughness, 0.0f, 1.0f);
    shading.f0 = glm::mix(dielectricF0_, baseColor, metallic);
    shading.diffuse = (1.0f - metallic) * baseColor;
    shading.alpha = std::max(ggx::kMinAlpha, roughness * roughness);
    if (tables_.size() > 1) std::tie(shading.node, shading.blend) = roughnessNode(roughness);
    // E is linear in F0 (the table's scale and bias), so is its average.
    const auto [averageScale, averageBias] = averageTerms(tables_, shading.node, shading.blend);
    shading.averageAlbedo = glm::min(Rgb{1.0f}, shading.f0 * averageScale + Rgb{averageBias});
    if (coated_) {
        shading.coat = std::clamp(coat, 0.0f, 1.0f);
        coatRoughness = std::clamp(coatRoughness, 0.0f, 1.0f);
        shading.coatAlpha = std::max(ggx::kMinAlpha, coatRoughness * coatRoughness);
        if (coatTables_.size() > 1) std::tie(shading.coatNode, shading.coatBlend) = roughnessNode(coatRoughness);
        const auto [coatScale, coatBias] = averageTerms(coatTables_, shading.coatNode, shading.coatBlend);
        shading.coatAverage = shading.coat * std::min(1.0f, kDielectricF0 * coatScale + coatBias);
    }
    return shading;
}

std::pair<float, float> MicrofacetMaterial::averageTerms(const std::vector<AlbedoTable>& tables, int node,
                                                         float blend) {
    if (tables.size() == 1) return {tables[0].averageScale, tables[0].averageBias};
    const AlbedoTable &t0 = tables[std::size_t(node)], &t1 = tables[std::size_t(node) + 1];
    return {glm::mix(t0.averageScale, t1.averageScale, blend), glm::mix(t0.averageBias, t1.averageBias, blend)};
}

std::pair<float, float> MicrofacetMaterial::albedoTerms(const std::vector<AlbedoTable>& tables, int node, float blend,
                                                        float cosine) {
    const float x = std::clamp(cosine, 0.0f, 1.0f) * float(kAlbedoNodes - 1);
    const int k = std::min(int(x), kAlbedoNodes - 2);
    const float t = x - float(k);
    const AlbedoTable& table = tables[std::size_t(node)];
    float scale = glm::mix(table.scale[k], table.scale[k + 1], t);
    float bias = glm::mix(table.bias[k], table.bias[k + 1], t);
    if (tables.size() > 1) {
        const AlbedoTable& next = tables[std::size_t(node) + 1];
        scale = glm::mix(scale, glm::mix(next.scale[k], next.scale[k + 1], t), blend);
        bias = glm::mix(bias, glm::mix(next.bias[k], next.bias[k + 1], t), blend);
    }
    return {scale, bias};
}

Rgb MicrofacetMaterial::specularAlbedo(const Rgb& f0, float cosine) const { return specularAlbedo(f0, cosine, constant_); }

Rgb MicrofacetMaterial::specularAlbedo(const Rgb& f0, float cosine, const Shading& shading) const {
    const auto [scale, bias] = albedoTerms(tables_, shading.node, shading.blend, cosine);
    return glm::min(Rgb{1.0f}, f0 * scale + Rgb{bias});
}

float MicrofacetMaterial::coatAlbedo(float cosine) const {
    Shading unit = constant_;
    unit.coat = 1.0f;
    return coated_ ? coatAlbedo(cosine, unit) : 0.0f;
}

float MicrofacetMaterial::coatAlbedo(float cosine, const Shading& shading) const {
    if (shading.coat == 0.0f) return 0.0f;
    // A polished coat reflects F_c(cos) exactly, which the table only interpolates between nodes.
    if (coatSmooth()) return shading.coat * fresnel(Rgb{kDielectricF0}, std::clamp(cosine, 0.0f, 1.0f)).g;
    const auto [scale, bias] = albedoTerms(coatTables_, shading.coatNode, shading.coatBlend, cosine);
    return shading.coat * std::min(1.0f, kDielectricF0 * scale + bias);
}

float MicrofacetMaterial::coatTransmission(const Shading& shading, float cosOut, float cosIn) const {
    if (shading.coat == 0.0f) return 1.0f;
    return (1.0f - coatAlbedo(cosOut, shading)) * (1.0f - coatAlbedo(cosIn, shading));
}

Rgb MicrofacetMaterial::diffuseWeight(const Shading& shading, float cosOut, float cosIn) const {
    const Rgb weight = shading.diffuse * (Rgb{1.0f} - specularAlbedo(shading.f0, cosOut, shading)) *
                       (Rgb{1.0f} - specularAlbedo(shading.f0, cosIn, shading));
    return shading.coat == 0.0f ? weight : weight * coatTransmission(shading, cosOut, cosIn);
}

Rgb MicrofacetMaterial::diffuseReflectance() const {
    // Textures: read as their images' means times their factors.
    const bool textured = baseColor_.varies() || metallic_.textured() || roughness_.textured() ||
                          coat_.weight.textured() || coat_.roughness.textured();
    const Shading shading = textured ? shadingOf(baseColor_.mean(), metallic_.mean(), roughness_.mean(),
                                                 coat_.weight.mean(), coat_.roughness.mean())
                                     : constant_;
    return meanBaseAlbedo(shading);
}

Rgb MicrofacetMaterial::diffuseReflectanceAt(const SurfaceSide& side) const {
    const Shading shading = shadingAt(side);
    return meanBaseAlbedo(shading);
}

Rgb MicrofacetMaterial::meanBaseAlbedo(const Shading& shading) {
    // baseAlbedoToward averaged over cosine-weighted wo as well.
    const Rgb remaining = Rgb{1.0f} - shading.averageAlbedo;
    const float underCoat = 1.0f - shading.coatAverage;
    return shading.diffuse * remaining * remaining * (underCoat * underCoat);
}

Rgb MicrofacetMaterial::baseAlbedoToward(const Shading& shading, float cosOut) const {
    // c (1 - E(wo)) times the cosine-weighted mean of 1 - E(wi), and the same of the coat's.
    const Rgb base = shading.diffuse * (Rgb{1.0f} - specularAlbedo(shading.f0, cosOut, shading)) *
                     (Rgb{1.0f} - shading.averageAlbedo);
    if (shading.coat == 0.0f) return base;
    return base * ((1.0f - coatAlbedo(cosOut, shading)) * (1.0f - shading.coatAverage));
}

Rgb MicrofacetMaterial::diffuseReflectanceToward(const SurfaceSide& side, const Vec3& wo) const {
    return baseAlbedoToward(shadingAt(side), std::max(0.0f, glm::dot(wo, side.normal)));
}

Rgb MicrofacetMaterial::diffuseReflectanceBetween(const SurfaceSide& side, const Vec3& wo, const Vec3& wi) const {
    return diffuseWeight(shadingAt(side), std::max(0.0f, glm::dot(wo, side.normal)),
                         std::max(0.0f, glm::dot(wi, side.normal)));
}

bool MicrofacetMaterial::has(int lobe) const {
    switch (lobe) {
        case kDiffuse: return metallic_.textured() ? !baseColor_.black() : !isBlack(constant_.diffuse);
        case kGlossy: return !smooth();
        case kMirror: return smooth();
        case kCoatGlossy: return coated_ && !coatSmooth();
        case kCoatMirror: return coated_ && coatSmooth();
        default: return false;
    }
}

Rgb MicrofacetMaterial::eval(int lobe, const SurfaceSide& side, const Vec3& wo, const Vec3& wi) const {
    if (!has(lobe) || !side.bothAbove(wo, wi)) return Rgb{0.0f};
    const Frame frame(side.normal);
    const Vec3 o = frame.toLocal(wo), i = frame.toLocal(wi);
    const Shading shading = shadingAt(side);
    if (lobe == kDiffuse) return lambert::eval(diffuseWeight(shading, o.z, i.z), side, wi);
    if (lobe == kGlossy) {
        const Rgb value = ggxReflection(shading.f0, shading.alpha, o, i);
        return shading.coat == 0.0f ? value : value * coatTransmission(shading, o.z, i.z);
    }
    if (lobe == kCoatGlossy) return shading.coat * ggxReflection(Rgb{kDielectricF0}, shading.coatAlpha, o, i);
    return Rgb{0.0f};
}

float MicrofacetMaterial::pdf(int lobe, const SurfaceSide& side, const Vec3& wo, const Vec3& wi) const {
    if (!has(lobe) || !side.bothAbove(wo, wi)) return 0.0f;
    if (lobe == kDiffuse) return lambert::pdf(side, wi);
    const Frame frame(side.normal);
    if (lobe == kGlossy) {
        const float a = roughness_.textured() ? shadingAt(side).alpha : constant_.alpha;
        return ggx::reflectionPdf(frame.toLocal(wo), frame.toLocal(wi), a);
    }
    if (lobe == kCoatGlossy) {
        const float a = coat_.roughness.textured() ? shadingAt(side).coatAlpha : constant_.coatAlpha;
        return ggx::reflectionPdf(frame.toLocal(wo), frame.toLocal(wi), a);
    }
    return 0.0f;
}

std::optional<LobeSample> MicrofacetMaterial::sample(int lobe, const SurfaceSide& side, const Vec3& wo,
                                                     Vec2 u) const {
    if (!has(lobe)) return std::nullopt;
    if (lobe == kDiffuse) {
        std::optional<LobeSample> s = lambert::sample(Rgb{1.0f}, side, wo, u);
        if (s) s->weight = diffuseWeight(shadingAt(side), glm::dot(wo, side.normal), glm::dot(s->wi, side.normal));
        return s;
    }
    if (lobe != kGlossy && lobe != kCoatGlossy) return std::nullopt;
    const Frame frame(side.normal);
    const Vec3 o = frame.toLocal(wo);
    if (!(o.z > 0.0f)) return std::nullopt;  // eval() is 0 there
    const Shading shading = shadingAt(side);
    const bool coat = lobe == kCoatGlossy;
    const float a = coat ? shading.coatAlpha : shading.alpha;
    const Vec3 m = ggx::sampleVisibleNormal(o, a, u);
    const Vec3 i = reflectAbout(o, m);
    if (i.z <= 0.0f) return std::nullopt;
    LobeSample s;
    s.wi = glm::normalize(frame.toWorld(i));
    s.pdf = ggx::reflectionPdf(o, i, a);
    if (!(s.pdf > 0.0f)) return std::nullopt;
    // F D G2 / (4 cos_o) over G1(wo) D / (4 cos_o): F G2 / G1 (Heitz 2018, eq. 19).
    const float shadowing = ggx::maskingShadowing(o, i, a) / ggx::masking(o, a);
    if (coat) {
        s.weight = shading.coat * fresnel(Rgb{kDielectricF0}, glm::dot(o, m)) * shadowing;
    } else {
        s.weight = fresnel(shading.f0, glm::dot(o, m)) * shadowing;
        if (shading.coat != 0.0f) s.weight *= coatTransmission(shading, o.z, i.z);
    }
    return s;
}

float MicrofacetMaterial::albedo(int lobe, const SurfaceSide& side, const Vec3& wo) const {
    if (!has(lobe)) return 0.0f;
    const float cosOut = std::max(0.0f, glm::dot(wo, side.normal));
    const Shading shading = shadingAt(side);
    if (lobe == kCoatGlossy) return coatAlbedo(cosOut, shading);
    if (lobe == kDiffuse) return maxComponent(baseAlbedoToward(shading, cosOut));
    // The glossy lobe below the coat: through it from wo and back about the mirror direction.
    const float below = 1.0f - coatAlbedo(cosOut, shading);
    return maxComponent(specularAlbedo(shading.f0, cosOut, shading)) * (shading.coat == 0.0f ? 1.0f : below * below);
}

int MicrofacetMaterial::specularBranches(const SurfaceSide& side, const Vec3& wo, SpecularBranches& branches) const {
    if (!has(kMirror) && !has(kCoatMirror)) return 0;
    const float cosOut = glm::dot(wo, side.normal);
    if (cosOut <= 0.0f) return 0;
    const Shading shading = shadingAt(side);
    const Vec3 mirror = reflectAbout(wo, side.normal);
    int count = 0;
    if (has(kMirror)) {
        // Through the coat both ways along the mirror direction: (1 - w E_c(cos))^2.
        const Rgb weight = fresnel(shading.f0, cosOut) * coatTransmission(shading, cosOut, cosOut);
        branches[std::size_t(count++)] = {mirror, weight, kMirror, maxComponent(weight)};
    }
    if (has(kCoatMirror)) {
        const Rgb weight = shading.coat * fresnel(Rgb{kDielectricF0}, cosOut);
        branches[std::size_t(count++)] = {mirror, weight, kCoatMirror, maxComponent(weight)};
    }
    return count;
}

int MicrofacetMaterial::factors(int lobe, const SurfaceSide& side, const Vec3& wo, const Vec3& wi,
                                NamedFactors& factors) const {
    const Shading shading = shadingAt(side);
    if (lobe == kDiffuse) {
        factors = lambert::factors(
            diffuseWeight(shading, glm::dot(wo, side.normal), glm::dot(wi, side.normal)), side, wi);
        factors[0].name = shading.coat == 0.0f ? "(1-m) base (1-E(V)) (1-E(L))"
                                               : "(1-m) base (1-E(V)) (1-E(L)) (1-cE_c(V)) (1-cE_c(L))";
        return 2;
    }
    if (lobe != kGlossy && lobe != kCoatGlossy) return 0;
    const Rgb value = eval(lobe, side, wo, wi);
    const float cosHalf = std::max(0.0f, glm::dot(wo, glm::normalize(wo + wi)));
    // pi eval = F (times what the coat lets through, or the coat's weight) times pi D G2 / (4 N.V)
    Rgb f{0.0f};
    const char* name = "F";
    if (lobe == kCoatGlossy) {
        f = shading.coat * fresnel(Rgb{kDielectricF0}, cosHalf);
        name = "c F_c";
    } else {
        f = fresnel(shading.f0, cosHalf);
        if (shading.coat != 0.0f) {
            f *= coatTransmission(shading, glm::dot(wo, side.normal), glm::dot(wi, side.normal));
            name = "F (1-cE_c(V)) (1-cE_c(L))";
        }
    }
    Rgb rest{0.0f};
    for (int c = 0; c < 3; ++c) rest[c] = f[c] > 0.0f ? kPi * value[c] / f[c] : 0.0f;
    factors = {{{name, f}, {"pi D G / (4 N.V)", rest}}};
    return 2;
}

}  // namespace lightpath

namespace lightpath {
namespace {

constexpr Range kUnitInterval{0.0, 1.0, false, false};

MaterialSlot makeMicrofacet(const ParameterValues& values) {
    MicrofacetMaterial material(colorParameter(values, "base_color"), values.number("metallic"),
                                values.number("roughness"), values.colour("dielectric_f0"),
                                {values.number("clearcoat"), values.number("clearcoat_roughness")});
    readSurfaceRows(values, material);
    return material;
}

}  // namespace
}  // namespace lightpath

LIGHTPATH_REGISTER_MATERIAL(lightpath::MaterialType{
    {"material", "microfacet", "glTF's metallic-roughness: GGX microfacet specular over a diffuse base",
     {{"base_color", lightpath::ParameterType::Colour, "", "0.8", lightpath::kUnitInterval,
       "the metal's reflectance at normal incidence F0, the dielectric's diffuse albedo; may be a texture"},
      {"metallic", lightpath::ParameterType::Number, "", "1", lightpath::kUnitInterval,
       "1 a conductor (F0 = base_color, no base), 0 a dielectric (F0 = dielectric_f0 over a diffuse base_color)"},
      lightpath::kGgxRoughnessParameter,
      {"dielectric_f0", lightpath::ParameterType::Colour, "", "0.04", lightpath::kUnitInterval,
       "the dielectric's reflectance at normal incidence: ((n − 1)/(n + 1))² for an index of refraction n, 0.04 for "
       "1.5; glTF's KHR_materials_ior times KHR_materials_specular's specularColorFactor"},
      {"clearcoat", lightpath::ParameterType::Number, "", "0", lightpath::kUnitInterval,
       "a clear coat's weight over the surface (glTF's KHR_materials_clearcoat): a GGX layer of F0 0.04, `<RG>` or "
       "at clearcoat_roughness 0 `<RS>`; what it reflects, the layers below do not receive; 0: none"},
      {"clearcoat_roughness", lightpath::ParameterType::Number, "", "0", lightpath::kUnitInterval,
       "the clear coat's GGX roughness (alpha = clearcoat_roughness²); 0 a mirror-smooth coat"},
      lightpath::kEmissionParameter, lightpath::kTwoSidedEmissionParameter, lightpath::kAlphaParameter},
     "<R[DGS]>|O"},
    2, lightpath::makeMicrofacet,
    // F and G2 at the half vector, (1 - E(wo))(1 - E(wi)) and the coat's (1 - w E_c(wo))(1 - w E_c(wi))
    // are symmetric: reciprocal. F <= 1, G2 <= G1, the base's share 1 - E(wo) and what is below
    // the coat 1 - w E_c(wo): at most 1 from every direction.
    {{true, true, true, true, true}, [](const lightpath::ParameterValues&) { return true; }}})
