#pragma once
// A rough dielectric interface (glass, water) after Walter, Marschner, Li and Torrance 2007,
// "Microfacet Models for Refraction through Rough Surfaces" (EGSR), with the GGX distribution and
// Smith's height-correlated masking-shadowing of materials/ggx.h, alpha = roughness^2. With o the
// outgoing direction on the side of index n_o, i the other, eta = n_i / n_o and F the exact
// dielectric Fresnel reflectance (materials/optics.h) at the microfacet normal m:
//
//   reflection    f cos theta_i = F(o.m) D(m) G2(o, i) / (4 cos theta_o),   m = normalize(o + i)
//   transmission  f cos theta_i = tint (1 - F(o.m)) D(m) G2(o, i) |i.m| (o.m) / (cos theta_o (i.m + o.m / eta)^2)
//                                 m = normalize(eta i + o)  (the generalised half vector, eq. 16)
//
// that is the importance (adjoint) form; radiance is compressed by (n_o / n_i)^2 = 1 / eta^2 as it
// crosses (Veach 1997, 5.2), as the smooth glass does. So f(o, i) / n_o^2 = f(i, o) / n_i^2 in
// radiance. Directions are sampled through a visible normal m (Heitz 2018), mirrored or refracted.
// Lobes: glossy reflection <RG>, glossy transmission <TG> and, at roughness 0, the smooth glass's
// mirror <RS> and refraction <TS> (deltas), with the same directions and weights as the Phong
// material's Fresnel glass (fresnel = true, kt = tint) whenever tint is white.
#include <array>

#include "materials/material.h"
#include "materials/texture.h"

namespace lightpath {

class DielectricMaterial final : public Material {
public:
    DielectricMaterial(float ior, ColorParameter tint, float roughness);

    std::unique_ptr<Material> clone() const override { return std::make_unique<DielectricMaterial>(*this); }

    // Its lobes, in this order (the indices below).
    enum LobeIndex : int { kGlossyReflection, kGlossyTransmission, kMirror, kRefraction };
    static constexpr std::array<LobeInfo, 4> kLobes{
        LobeInfo{{lpe::EventType::Reflection, lpe::Scatter::Glossy}, "glossy reflection", "roughness"},
        LobeInfo{{lpe::EventType::Transmission, lpe::Scatter::Glossy}, "glossy transmission", "tint"},
        LobeInfo{{lpe::EventType::Reflection, lpe::Scatter::Specular}, "mirror", "roughness"},
        LobeInfo{{lpe::EventType::Transmission, lpe::Scatter::Specular}, "refraction", "tint"}};
    Lobes lobes() const override { return kLobes; }
    bool has(int lobe) const override;
    Rgb eval(int lobe, const SurfaceSide& side, const Vec3& wo, const Vec3& wi) const override;
    float pdf(int lobe, const SurfaceSide& side, const Vec3& wo, const Vec3& wi) const override;
    std::optional<LobeSample> sample(int lobe, const SurfaceSide& side, const Vec3& wo, Vec2 u) const override;
    float albedo(int lobe, const SurfaceSide& side, const Vec3& wo) const override;
    // Rough: reflection or transmission is chosen at the sampled visible normal m, with probability
    // F(o.m) / (F + (1 - F) t) of reflecting, t the tint's largest channel (Walter et al. 2007,
    // section 5.3): F's variation over m then leaves the weights, and a facet that totally
    // reflects always reflects.
    bool choosesLobe() const override { return !smooth(); }
    std::optional<ChosenLobeSample> sampleChosenLobe(const SurfaceSide& side, const Vec3& wo, float uLobe,
                                                     Vec2 u) const override;
    float chosenLobePdf(int lobe, const SurfaceSide& side, const Vec3& wo, const Vec3& wi) const override;
    int specularBranches(const SurfaceSide& side, const Vec3& wo, SpecularBranches& branches) const override;
    int factors(int lobe, const SurfaceSide& side, const Vec3& wo, const Vec3& wi,
                NamedFactors& factors) const override;
    Rgb diffuseReflectance() const override { return Rgb{0.0f}; }  // no diffuse part

    float ior() const { return ior_; }
    const ColorParameter& tint() const { return tint_; }
    float roughness() const { return roughness_; }

private:
    // The interface as wo sees it: a frame whose +z is the normal on wo's side (whichever side the
    // caller's normal is on: bdpt asks for reverse densities from the other side) and
    // eta = n_beyond / n_wo.
    struct View;
    View viewFrom(const SurfaceSide& side, const Vec3& wo) const;

    // The probability of reflecting at a facet of cosine c with o.
    float reflectionChoice(const View& view, const SurfaceSide& side, float c) const;

    // GGX's alpha: roughness^2, kept above ggx::kMinAlpha for a rough lobe.
    float alpha() const;
    bool smooth() const { return roughness_ == 0.0f; }

    // The glossy lobes' directional albedos (importance form, tint 1) at kAlbedoNodes equally spaced
    // cosines, from outside [0] and from inside [1], integrated once per material over visible
    // normals, for albedo().
    static constexpr int kAlbedoNodes = 17;
    std::array<std::array<float, kAlbedoNodes>, 2> reflectionAlbedo_{}, transmissionAlbedo_{};

    float ior_ = 1.5f;
    ColorParameter tint_{Rgb{1.0f}};
    float roughness_ = 0.5f;
};

}  // namespace lightpath
