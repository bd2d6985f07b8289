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
// at roughness 0, Mirror (<RS>), a delta, so every LPE keeps its meaning.
#include <array>

#include "materials/material.h"
#include "materials/texture.h"

namespace lightpath {

class MicrofacetMaterial final : public Material {
public:
    MicrofacetMaterial(Rgb baseColor, float metallic, float roughness)
        : MicrofacetMaterial(ColorParameter(baseColor), metallic, roughness) {}
    // base_color may be a texture: F0 and the base then vary over the surface (per shading point).
    MicrofacetMaterial(ColorParameter baseColor, float metallic, float roughness);

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

    // Schlick's F(cos) = F0 + (1 - F0)(1 - cos)^5 (Schlick 1994).
    static Rgb fresnel(const Rgb& f0, float cosine);
    // E(w): the specular layer's directional albedo for cos theta = cosine (the table below).
    Rgb specularAlbedo(const Rgb& f0, float cosine) const;

    // F0 and the base of the untextured material (of a textured one: with its tint as base_color).
    const Rgb& f0() const { return f0_; }
    const Rgb& diffuseColor() const { return diffuseColor_; }
    float roughness() const { return roughness_; }

private:
    // GGX's alpha: roughness^2, kept above ggx::kMinAlpha for a rough lobe.
    float alpha() const;
    bool smooth() const { return roughness_ == 0.0f; }
    // F0 and the diffuse base at a shading point: the constants unless base_color is a texture.
    struct Colors {
        Rgb f0, diffuse, averageAlbedo;
    };
    Colors colorsAt(const SurfaceSide& side) const;
    Colors colorsOf(const Rgb& baseColor) const;
    Rgb diffuseWeight(const Colors& colors, float cosOut, float cosIn) const;

    // E = F0 a(cos) + b(cos), since Schlick's F = F0 (1 - (1 - c)^5) + (1 - c)^5: a and b at
    // kAlbedoNodes equally spaced cosines, integrated once per material over visible normals.
    static constexpr int kAlbedoNodes = 33;
    std::array<float, kAlbedoNodes> albedoScale_{}, albedoBias_{};
    Rgb averageAlbedo_{0.0f};  // E averaged over cosine-weighted directions: 2 integral E(mu) mu dmu
    // The same average as F0 averageScale_ + averageBias_, for a textured F0.
    float averageScale_ = 0.0f, averageBias_ = 0.0f;

    ColorParameter baseColor_;
    float metallic_ = 1.0f;
    Rgb f0_{0.04f};
    Rgb diffuseColor_{0.0f};
    float roughness_ = 0.5f;
};

}  // namespace lightpath
