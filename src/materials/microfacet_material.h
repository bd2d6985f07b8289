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
#include <array>
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

    std::unique_ptr<Material> clone() const override { return std::make_unique<MicrofacetMaterial>(*this); }

    // Its lobes, in this order (the indices below).
    enum LobeIndex : int { kDiffuse, kGlossy, kMirror };
    static constexpr std::array<LobeInfo, 3> kLobes{
        LobeInfo{{lpe::EventType::Reflection, lpe::Scatter::Diffuse}, "diffuse", "(1 - metallic) base_color"},
        LobeInfo{{lpe::EventType::Reflection, lpe::Scatter::Glossy}, "glossy", "roughness"},
        LobeInfo{{lpe::EventType::Reflection, lpe::Scatter::Specular}, "mirror", "roughness"}};
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

    // The F0 of its dielectric part (metallic 0).
    const Rgb& dielectricF0() const { return dielectricF0_; }
    // Schlick's F(cos) = F0 + (1 - F0)(1 - cos)^5 (Schlick 1994).
    static Rgb fresnel(const Rgb& f0, float cosine);
    // E(w): the specular layer's directional albedo for cos theta = cosine, at the untextured
    // roughness (a textured one: its factor).
    Rgb specularAlbedo(const Rgb& f0, float cosine) const;

    // F0, the base and the lobe at a shading point (`side`): what eval, sample, albedo and
    // radiosity read, textures looked up (the constants when nothing is textured).
    struct Shading {
        Rgb f0{0.0f}, diffuse{0.0f}, averageAlbedo{0.0f};
        float alpha = 0.0f;  // GGX's alpha: roughness^2, kept above ggx::kMinAlpha
        int node = 0;        // E between tables_[node] and tables_[node + 1] (one table: node 0)
        float blend = 0.0f;
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

    bool smooth() const { return !roughness_.textured() && roughness_.constant() == 0.0f; }
    Shading shadingOf(const Rgb& baseColor, float metallic, float roughness) const;
    Rgb specularAlbedo(const Rgb& f0, float cosine, const Shading& shading) const;
    Rgb diffuseWeight(const Shading& shading, float cosOut, float cosIn) const;

    std::vector<AlbedoTable> tables_;  // one (constant roughness) or kRoughnessNodes
    Shading constant_;                 // the shading of the untextured material

    ColorParameter baseColor_;
    ScalarParameter metallic_{1.0f};
    ScalarParameter roughness_{0.5f};
    Rgb dielectricF0_{kDielectricF0};
};

}  // namespace lightpath
