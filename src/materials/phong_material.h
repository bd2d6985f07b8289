#pragma once
// The classic material of Szymczak's illumination formula
//   I = sum_l I_l / (c0 + c1 d + c2 d^2) * (kd (N.L) + ks (H.N)^n) + ka Ia
// extended with Whitted's mirror (kr) and refraction (kt, ior) weights. Per-channel RGB. Its lobes:
//
//   lobe        f(wo, wi) |cos theta_i|               event   Szymczak's term under a point light
//   Diffuse     kd / pi |cos theta_i|                  <RD>    kd (N.L) I
//   Highlight   ks (H.N)^n / pi                        <RG>    ks (H.N)^n I
//   Mirror      kr (+ kt F with Fresnel), a delta      <RS>    kr * (light from the mirror ray)
//   Refraction  kt (kt (1 - F) with Fresnel), a delta  <TS>    kt * (light from the refracted ray)
//
// A point light of `intensity` I has radiant intensity pi I (lights/point_light.h), so ray casting's
// formula is this BSDF under that light, term by term, and the path tracer reading the same numbers
// produces the same light on the same paths. kd is an albedo (Lambert), emission a radiance.
#include <array>

#include "materials/material.h"
#include "materials/texture.h"

namespace lightpath {

class PhongMaterial final : public Material {
public:
    // Each colour a constant or a texture (materials/texture.h), read at the shading point.
    ColorParameter ka{Rgb{0.0f}};  // ambient reflectance
    ColorParameter kd{Rgb{0.0f}};  // diffuse reflectance
    ColorParameter ks{Rgb{0.0f}};  // specular (highlight) reflectance
    float n = 20.0f;               // specular exponent, >= 0
    ColorParameter kr{Rgb{0.0f}};  // mirror reflection weight
    ColorParameter kt{Rgb{0.0f}};  // transmission (refraction) weight
    float ior = 1.5f;  // index of refraction of the inside, > 0
    // Fresnel glass: the mirror ray gains kt F and the refracted ray keeps kt (1 - F), F the
    // dielectric's reflectance at the angle of incidence; off, the weights are kr and kt exactly.
    bool fresnel = false;

    std::unique_ptr<Material> clone() const override { return std::make_unique<PhongMaterial>(*this); }

    // Its lobes, in this order (the indices below): lobes::kDiffuse, lobes::kHighlight, lobes::kMirror, lobes::kRefraction.
    enum LobeIndex : int { kDiffuse, kHighlight, kMirror, kRefraction };
    static constexpr std::array<LobeInfo, 4> kLobes{lobes::kDiffuse, lobes::kHighlight, lobes::kMirror, lobes::kRefraction};
    Lobes lobes() const override { return kLobes; }
    bool has(int lobe) const override;
    Rgb eval(int lobe, const SurfaceSide& side, const Vec3& wo, const Vec3& wi) const override;
    float pdf(int lobe, const SurfaceSide& side, const Vec3& wo, const Vec3& wi) const override;
    std::optional<LobeSample> sample(int lobe, const SurfaceSide& side, const Vec3& wo, Vec2 u) const override;
    float albedo(int lobe, const SurfaceSide& side, const Vec3& wo) const override;
    // Without a mirror or glass term: the smooth lobes' albedos are constants.
    bool lobeAlbedosIgnoreWo(const SurfaceSide&) const override { return kr.black() && kt.black(); }
    int specularBranches(const SurfaceSide& side, const Vec3& wo, SpecularBranches& branches) const override;
    int factors(int lobe, const SurfaceSide& side, const Vec3& wo, const Vec3& wi,
                NamedFactors& factors) const override;
    Rgb diffuseReflectance() const override { return kd.mean(); }
    Rgb diffuseReflectanceAt(const SurfaceSide& side) const override { return kd.at(side); }
    Rgb ambientReflectance() const override { return ka.mean(); }
    Rgb ambientReflectanceAt(const SurfaceSide& side) const override { return ka.at(side); }
};

// The Phong material in a scene's slot, for code that built the scene from Phong materials and
// edits them (tests); throws std::bad_cast for any other material.
inline PhongMaterial& phongOf(const MaterialSlot& slot) { return dynamic_cast<PhongMaterial&>(*slot); }

}  // namespace lightpath
