#pragma once
// The modified Phong model of Lafortune and Willems (1994), the energy-conserving form of the
// lecture's formula:
//
//   f(wo, wi) = kd / pi + ks (n + 2) / (2 pi) cos^n(alpha),  alpha = angle(wi, mirror of wo)
//
// Normalised so that it reflects exactly kd + ks at normal incidence and never more anywhere:
// with kd + ks <= 1 per channel it conserves energy, which Szymczak's classic highlight
// ks (H.N)^n does not. Its lobes are Diffuse (<RD>) and Highlight (<RG>); it has no delta lobes.
#include <array>

#include "materials/material.h"
#include "materials/texture.h"

namespace lightpath {

class ModifiedPhongMaterial final : public Material {
public:
    ColorParameter kd{Rgb{0.0f}};  // diffuse albedo, a constant or a texture
    ColorParameter ks{Rgb{0.0f}};  // specular albedo at normal incidence
    float n = 20.0f;  // specular exponent, >= 0

    std::unique_ptr<Material> clone() const override { return std::make_unique<ModifiedPhongMaterial>(*this); }

    // Its lobes, in this order (the indices below): lobes::kDiffuse, lobes::kHighlight.
    enum LobeIndex : int { kDiffuse, kHighlight };
    static constexpr std::array<LobeInfo, 2> kLobes{lobes::kDiffuse, lobes::kHighlight};
    Lobes lobes() const override { return kLobes; }
    bool has(int lobe) const override;
    Rgb eval(int lobe, const SurfaceSide& side, const Vec3& wo, const Vec3& wi) const override;
    float pdf(int lobe, const SurfaceSide& side, const Vec3& wo, const Vec3& wi) const override;
    std::optional<LobeSample> sample(int lobe, const SurfaceSide& side, const Vec3& wo, Vec2 u) const override;
    float albedo(int lobe, const SurfaceSide& side, const Vec3& wo) const override;
    bool lobeAlbedosIgnoreWo(const SurfaceSide&) const override { return true; }  // constants, no delta lobe
    int factors(int lobe, const SurfaceSide& side, const Vec3& wo, const Vec3& wi,
                NamedFactors& factors) const override;
    Rgb diffuseReflectance() const override { return kd.mean(); }
    Rgb diffuseReflectanceAt(const SurfaceSide& side) const override { return kd.at(side); }
};

}  // namespace lightpath
