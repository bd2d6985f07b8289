// Example plugin (docs/extending.md): a translucent sheet (paper, a lampshade, a leaf), Lambert's
// diffuse reflection kd / pi on the side light arrives from and a diffuse transmission kt / pi to
// the other side (pbrt-v3 8.x's "translucent" without its glossy part). Its second lobe is a kind
// no shipped material has, `<TD>`: declared here as data, and every integrator reads it from the
// declaration. One file: the material, its schema, its registration.
#include <cmath>

#include "materials/lambert_lobe.h"
#include "materials/material_type.h"
#include "sampling/warp.h"

namespace lightpath::examples {
namespace {

// A diffuse transmission <TD>: the cosine lobe on the far side of the surface.
constexpr LobeInfo kTranslucency{{lpe::EventType::Transmission, lpe::Scatter::Diffuse}, "translucency", "kt"};

class TranslucentMaterial final : public Material {
public:
    Rgb kd{0.4f};  // diffuse reflectance
    Rgb kt{0.4f};  // diffuse transmittance

    enum LobeIndex : int { kDiffuse, kTransmission };
    static constexpr LobeInfo kLobes[] = {lobes::kDiffuse, kTranslucency};

    std::unique_ptr<Material> clone() const override { return std::make_unique<TranslucentMaterial>(*this); }
    Lobes lobes() const override { return kLobes; }
    bool has(int lobe) const override { return !isBlack(coefficient(lobe)); }

    // f |cos theta_i| = k / pi |cos theta_i|, where wi is on the lobe's side (the sheet is two-sided:
    // side.normal is on wo's side, whichever face that is).
    Rgb eval(int lobe, const SurfaceSide& side, const Vec3& wo, const Vec3& wi) const override {
        if (!supports(lobe, side, wo, wi)) return Rgb{0.0f};
        return coefficient(lobe) * (std::fabs(glm::dot(wi, side.normal)) / kPi);
    }

    float pdf(int lobe, const SurfaceSide& side, const Vec3& wo, const Vec3& wi) const override {
        if (!supports(lobe, side, wo, wi)) return 0.0f;
        return cosineHemispherePdf(std::fabs(glm::dot(wi, side.normal)));
    }

    // Cosine-weighted about the lobe's side of the normal: the weight eval / pdf is k.
    std::optional<LobeSample> sample(int lobe, const SurfaceSide& side, const Vec3& wo, Vec2 u) const override {
        if (!(glm::dot(wo, side.normal) > 0.0f)) return std::nullopt;  // eval() is 0 there
        const Vec3 axis = lobeAxis(lobe, side);
        LobeSample s;
        s.wi = Frame(axis).toWorld(sampleCosineHemisphere(u));
        const float cosIn = glm::dot(s.wi, axis);
        if (cosIn <= 0.0f) return std::nullopt;
        s.pdf = cosineHemispherePdf(cosIn);
        s.weight = coefficient(lobe);
        return s;
    }

    // Exact: a Lambertian lobe scatters k whatever wo.
    float albedo(int lobe, const SurfaceSide&, const Vec3&) const override { return maxComponent(coefficient(lobe)); }

    // The lecture's form: kd (N.L) from the lit side, kt |N.L| through the sheet.
    int factors(int lobe, const SurfaceSide& side, const Vec3& wo, const Vec3& wi, NamedFactors& factors) const override {
        (void)wo;
        if (lobe == kDiffuse) {
            factors = lambert::factors(kd, side, wi);
            return 2;
        }
        factors = {{{"kt", kt}, {"|N.L|", Rgb{std::fabs(glm::dot(side.normal, wi))}}}};
        return 2;
    }

    // Radiosity exchanges light by reflection only: what the sheet transmits it leaves out.
    Rgb diffuseReflectance() const override { return kd; }

private:
    const Rgb& coefficient(int lobe) const { return lobe == kDiffuse ? kd : kt; }
    Vec3 lobeAxis(int lobe, const SurfaceSide& side) const { return lobe == kDiffuse ? side.normal : -side.normal; }
    // wo on the normal's side, wi on the lobe's.
    bool supports(int lobe, const SurfaceSide& side, const Vec3& wo, const Vec3& wi) const {
        return glm::dot(wo, side.normal) > 0.0f && glm::dot(wi, lobeAxis(lobe, side)) > 0.0f;
    }
};

MaterialSlot makeTranslucent(const ParameterValues& values) {
    TranslucentMaterial material;
    material.kd = values.colour("kd");
    material.kt = values.colour("kt");
    material.emission = values.colour("emission");
    return material;
}

}  // namespace
}  // namespace lightpath::examples

LIGHTPATH_REGISTER_MATERIAL(lightpath::MaterialType{
    {"material", "translucent", "example plugin: a translucent sheet, diffuse reflection and diffuse transmission",
     {{"kd", lightpath::ParameterType::Colour, "", "0.4", lightpath::kNonNegative, "diffuse reflectance, f = kd/π"},
      {"kt", lightpath::ParameterType::Colour, "", "0.4", lightpath::kNonNegative,
       "diffuse transmittance to the other side, f = kt/π"},
      {"emission", lightpath::ParameterType::Colour, "W/(m² sr)", "0", lightpath::kNonNegative,
       "emitted radiance: the surface is an area light"}},
     "<RD>|<TD>"},
    // After the shipped types in listings. Both lobes are Lambertian, so reciprocal; kd + kt <= 1
    // scatters at most what arrives.
    101, lightpath::examples::makeTranslucent,
    {{true, true}, [](const lightpath::ParameterValues& v) {
         const lightpath::Rgb sum = v.colour("kd") + v.colour("kt");
         return sum.r <= 1.0f && sum.g <= 1.0f && sum.b <= 1.0f;
     }}})
