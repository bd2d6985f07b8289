#pragma once
// A metal by its complex index of refraction eta + i k per RGB channel (e.g. measured values of
// gold or copper at three wavelengths): the exact conductor Fresnel reflectance (materials/optics.h)
// on GGX microfacets with Smith's height-correlated masking-shadowing (materials/ggx.h, the same
// distribution as microfacet's), alpha = roughness^2:
//
//   f(wo, wi) cos theta_i = F(wo.h) D(h) G2(wo, wi) / (4 cos theta_o)
//
// F <= 1 and G2 <= G1 keep it at most 1 from every direction; F, D and G2 are symmetric in wo and
// wi: reciprocal. Lobes: Glossy (<RG>) and, at roughness 0, Mirror (<RS>), a delta.
#include <array>

#include "materials/material.h"

namespace lightpath {

class ConductorMaterial final : public Material {
public:
    ConductorMaterial(Rgb eta, Rgb k, float roughness);

    std::unique_ptr<Material> clone() const override { return std::make_unique<ConductorMaterial>(*this); }

    // Its lobes, in this order (the indices below).
    enum LobeIndex : int { kGlossy, kMirror };
    static constexpr std::array<LobeInfo, 2> kLobes{
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
    Rgb diffuseReflectance() const override { return Rgb{0.0f}; }  // no diffuse part

    // The exact conductor Fresnel reflectance per channel for cos theta = cosine.
    Rgb fresnel(float cosine) const;

    const Rgb& eta() const { return eta_; }
    const Rgb& k() const { return k_; }
    float roughness() const { return roughness_; }

private:
    // GGX's alpha: roughness^2, kept above ggx::kMinAlpha for a rough lobe.
    float alpha() const;
    bool smooth() const { return roughness_ == 0.0f; }

    // E(wo), the glossy lobe's directional albedo, at kAlbedoNodes equally spaced cosines,
    // integrated once per material over visible normals: albedo() weighs lobes by it.
    static constexpr int kAlbedoNodes = 17;
    std::array<Rgb, kAlbedoNodes> albedoTable_{};

    Rgb eta_{1.0f};
    Rgb k_{0.0f};
    float roughness_ = 0.5f;
};

}  // namespace lightpath
