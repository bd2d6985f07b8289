#pragma once
// glTF 2.0's metallic-roughness material (glTF 2.0 specification, appendix B): a GGX
// (Trowbridge-Reitz) microfacet specular layer with Smith's height-correlated masking-shadowing,
// sampled by its visible normals (materials/ggx.h; Heitz 2018; pbrt-v4 9.6), over a Lambertian base:
//
//   specular  F(wo.h) D(h) G2(wo, wi) / (4 cos theta_o cos theta_i),  alpha = roughness^2
//   diffuse   (1 - metallic) base_color / pi (1 - E(wo)) (1 - E(wi))
//
// with Schlick's F = F0 + (1 - F0)(1 - cos)^5, F0 = mix(0.04, base_color, metallic), and E(w) the
// specular layer's directional albedo, so the base gets only what the layer does not reflect, on
// the way in and on the way out (Kelemen and Szirmay-Kalos 2001; Kulla and Conty 2017). That keeps
// the sum at most 1 from every direction (E(wo) + (1 - E(wo)) * at most 1), and reciprocal, where
// the appendix's (1 - F(wo.h)) weighting reflects more than 1 at grazing angles.
// alpha = roughness^2 is glTF's (and Burley's) remapping: perceptually even steps.
// metallic = 1 is a conductor whose F0 is base_color. Lobes: Diffuse (<RD>), Glossy (<RG>) and,
// at roughness 0, Mirror (<RS>), a delta, so every LPE keeps its meaning. base_color, metallic and
// roughness may be textures (glTF's baseColorTexture and metallicRoughnessTexture); a textured
// roughness is glossy everywhere (a texel of 0 is the sharpest glossy lobe, ggx::kMinAlpha), and
// E is then interpolated between tables at kRoughnessNodes roughnesses.
//
// A clear coat (glTF's KHR_materials_clearcoat, Blender's Principled Clearcoat) lies over all of
// it: a second GGX layer of index 1.5 (F0 0.04) and its own roughness, weighted by `clearcoat` w:
//
//   coat      w F_c(wo.h) D_c(h) G2_c(wo, wi) / (4 cos theta_o cos theta_i)
//   below     everything above, times (1 - w E_c(wo)) (1 - w E_c(wi))
//
// with E_c the coat's directional albedo: what it reflects, the layers below never receive, on the
// way in and on the way out. The extension's sample weighs the base by 1 - w F_c(N.V) once; taking
// both crossings keeps the material reciprocal (bdpt and light tracing read it from the other end)
// and is what a layer does (Weidlich and Wilkie 2007). Lobes: Glossy (<RG>) or, at clearcoat
// roughness 0, Mirror (<RS>), after the base's three.
#include <array>
#include <utility>
#include <vector>

#include "materials/material.h"
#include "materials/texture.h"

namespace lightpath {

class MicrofacetMaterial final : public Material {
public:
    // glTF 2.0 appendix B: a dielectric's reflectance at normal incidence (index of refraction 1.5).
    static constexpr float kDielectricF0 = 0.04f;

    MicrofacetMaterial(Rgb baseColor, float metallic, float roughness)
        : MicrofacetMaterial(ColorParameter(baseColor), ScalarParameter(metallic), ScalarParameter(roughness)) {}
    // Any of the first three may be a texture: F0, the base and the lobe then vary over the
    // surface. `dielectricF0`: the F0 of its dielectric part (glTF's KHR_materials_ior and
    // KHR_materials_specular set it).
    MicrofacetMaterial(ColorParameter baseColor, ScalarParameter metallic, ScalarParameter roughness,
                       const Rgb& dielectricF0 = Rgb{kDielectricF0});

    // A clear coat of weight `clearcoat` (0: none) and GGX roughness `roughness`; either may be a
    // texture (glTF's clearcoatTexture and clearcoatRoughnessTexture).
    struct Clearcoat {
        ScalarParameter weight{0.0f};
        ScalarParameter roughness{0.0f};
    };
    MicrofacetMaterial(ColorParameter baseColor, ScalarParameter metallic, ScalarParameter roughness,
                       const Rgb& dielectricF0, Clearcoat clearcoat);

    std::unique_ptr<Material> clone() const override { return std::make_unique<MicrofacetMaterial>(*this); }

    // Its lobes, in this order (the indices below).
    enum LobeIndex : int { kDiffuse, kGlossy, kMirror, kCoatGlossy, kCoatMirror };
    static constexpr std::array<LobeInfo, 5> kLobes{
        LobeInfo{{lpe::EventType::Reflection, lpe::Scatter::Diffuse}, "diffuse", "(1 - metallic) base_color"},
        LobeInfo{{lpe::EventType::Reflection, lpe::Scatter::Glossy}, "glossy", "roughness"},
        LobeInfo{{lpe::EventType::Reflection, lpe::Scatter::Specular}, "mirror", "roughness"},
        LobeInfo{{lpe::EventType::Reflection, lpe::Scatter::Glossy}, "clear coat", "clearcoat"},
        LobeInfo{{lpe::EventType::Reflection, lpe::Scatter::Specular}, "clear coat mirror", "clearcoat"}};
    Lobes lobes() const override { return kLobes; }
    bool has(int lobe) const override;
    Rgb eval(int lobe, const SurfaceSide& side, const Vec3& wo, const Vec3& wi) const override;
    float pdf(int lobe, const SurfaceSide& side, const Vec3& wo, const Vec3& wi) const override;
    std::optional<LobeSample> sample(int lobe, const SurfaceSide& side, const Vec3& wo, Vec2 u) const override;
    float albedo(int lobe, const SurfaceSide& side, const Vec3& wo) const override;
    int specularBranches(const SurfaceSide& side, const Vec3& wo, SpecularBranches& branches) const override;
    int factors(int lobe, const SurfaceSide& side, const Vec3& wo, const Vec3& wi,
                NamedFactors& factors) const override;
    // Radiosity's constant reading of the base: its albedo averaged over cosine-weighted wo.
    Rgb diffuseReflectance() const override;
    Rgb diffuseReflectanceAt(const SurfaceSide& side) const override;
    // c (1 - E(wo)) (1 - mean E), times (1 - w E_c(wo)) (1 - mean w E_c) under a coat.
    bool diffuseDependsOnView() const override { return has(kDiffuse); }
    Rgb diffuseReflectanceToward(const SurfaceSide& side, const Vec3& wo) const override;
    // c (1 - E(wo)) (1 - E(wi)), times (1 - w E_c(wo)) (1 - w E_c(wi)) under a coat: pi times the base.
    Rgb diffuseReflectanceBetween(const SurfaceSide& side, const Vec3& wo, const Vec3& wi) const override;

    // The F0 of its dielectric part (metallic 0).
    const Rgb& dielectricF0() const { return dielectricF0_; }
    // Schlick's F(cos) = F0 + (1 - F0)(1 - cos)^5 (Schlick 1994).
    static Rgb fresnel(const Rgb& f0, float cosine);
    // E(w): the specular layer's directional albedo for cos theta = cosine, at the untextured
    // roughness (a textured one: its factor).
    Rgb specularAlbedo(const Rgb& f0, float cosine) const;
    // E_c(w): the clear coat's directional albedo at weight 1, at its untextured roughness.
    float coatAlbedo(float cosine) const;
    bool coated() const { return coated_; }

    // F0, the base and the lobe at a shading point (`side`): what eval, sample, albedo and
    // radiosity read, textures looked up (the constants when nothing is textured).
    struct Shading {
        Rgb f0{0.0f}, diffuse{0.0f}, averageAlbedo{0.0f};
        float alpha = 0.0f;  // GGX's alpha: roughness^2, kept above ggx::kMinAlpha
        int node = 0;        // E between tables_[node] and tables_[node + 1] (one table: node 0)
        float blend = 0.0f;
        // The clear coat: its weight w (0: none), alpha and table nodes as the base's, and w E_c
        // averaged over cosine-weighted directions.
        float coat = 0.0f, coatAlpha = 0.0f;
        int coatNode = 0;
        float coatBlend = 0.0f, coatAverage = 0.0f;
    };
    Shading shadingAt(const SurfaceSide& side) const;
    // The roughness, or a textured one's factor.
    float roughness() const { return roughness_.constant(); }

private:
    // E = F0 a(cos) + b(cos), since Schlick's F = F0 (1 - (1 - c)^5) + (1 - c)^5: a and b at
    // kAlbedoNodes equally spaced cosines, integrated over visible normals for one roughness.
    static constexpr int kAlbedoNodes = 33;
    struct AlbedoTable {
        std::array<float, kAlbedoNodes> scale{}, bias{};
        // E averaged over cosine-weighted directions as F0 averageScale + averageBias.
        float averageScale = 0.0f, averageBias = 0.0f;
    };
    static AlbedoTable albedoTable(float roughness, int strata);
    // Tables at these roughnesses (0 to 1, equally spaced) for a textured roughness.
    static constexpr int kRoughnessNodes = 9;
    // One table for a constant roughness, kRoughnessNodes for a textured one.
    static std::vector<AlbedoTable> albedoTables(const ScalarParameter& roughness);
    // The table node and blend of a roughness in 0..1, among kRoughnessNodes tables.
    static std::pair<int, float> roughnessNode(float roughness);
    // E = F0 scale + bias's scale and bias at `cosine`, between tables[node] and tables[node + 1].
    static std::pair<float, float> albedoTerms(const std::vector<AlbedoTable>& tables, int node, float blend,
                                               float cosine);
    // The same for E's average over cosine-weighted directions.
    static std::pair<float, float> averageTerms(const std::vector<AlbedoTable>& tables, int node, float blend);

    bool smooth() const { return !roughness_.textured() && roughness_.constant() == 0.0f; }
    bool coatSmooth() const { return !coat_.roughness.textured() && coat_.roughness.constant() == 0.0f; }
    Shading shadingOf(const Rgb& baseColor, float metallic, float roughness, float coat, float coatRoughness) const;
    Rgb specularAlbedo(const Rgb& f0, float cosine, const Shading& shading) const;
    // w E_c(cos): what the coat reflects from that direction.
    float coatAlbedo(float cosine, const Shading& shading) const;
    // (1 - w E_c(wo)) (1 - w E_c(wi)): the share of the layers below the coat lets through; 1 uncoated.
    float coatTransmission(const Shading& shading, float cosOut, float cosIn) const;
    Rgb diffuseWeight(const Shading& shading, float cosOut, float cosIn) const;
    // The base's albedo toward wo (cos theta_o = cosOut), and averaged over wo too.
    Rgb baseAlbedoToward(const Shading& shading, float cosOut) const;
    static Rgb meanBaseAlbedo(const Shading& shading);

    std::vector<AlbedoTable> tables_;      // one (constant roughness) or kRoughnessNodes
    std::vector<AlbedoTable> coatTables_;  // the coat's (F0 0.04); none uncoated
    Shading constant_;                     // the shading of the untextured material

    ColorParameter baseColor_;
    ScalarParameter metallic_{1.0f};
    ScalarParameter roughness_{0.5f};
    Rgb dielectricF0_{kDielectricF0};
    Clearcoat coat_;
    bool coated_ = false;
};

}  // namespace lightpath
