// Example plugin (docs/extending.md): a rough diffuse material, Oren and Nayar's qualitative model
// (Oren & Nayar 1994, "Generalization of Lambert's reflectance model", eq. 30; pbrt-v3 8.4.2).
// Microfacets of slope deviation sigma make a rough surface brighter towards the viewer than
// Lambert's; sigma = 0 is Lambert's kd / pi. One file: the material, its schema, its registration.
#include <algorithm>
#include <cmath>

#include "materials/material_type.h"
#include "sampling/warp.h"

namespace lightpath::examples {
namespace {

class OrenNayarMaterial final : public Material {
public:
    Rgb kd{0.5f};
    float a = 1.0f, b = 0.0f;  // the model's A and B, from sigma (make() below)

    std::unique_ptr<Material> clone() const override { return std::make_unique<OrenNayarMaterial>(*this); }

    // One lobe, index 0: a diffuse reflection (<RD>), as Lambert's.
    static constexpr LobeInfo kLobes[] = {lobes::kDiffuse};
    Lobes lobes() const override { return kLobes; }
    bool has(int lobe) const override { return lobe == 0 && !isBlack(kd); }

    // f |cos theta_i| = kd / pi (A + B max(0, cos(phi_i - phi_o)) sin(alpha) tan(beta)) cos theta_i,
    // alpha = max(theta_i, theta_o), beta = min(theta_i, theta_o).
    Rgb eval(int lobe, const SurfaceSide& side, const Vec3& wo, const Vec3& wi) const override {
        if (lobe != 0 || !side.bothAbove(wo, wi)) return Rgb{0.0f};
        return kd * (roughness(side, wo, wi) * glm::dot(wi, side.normal) / kPi);
    }

    float pdf(int lobe, const SurfaceSide& side, const Vec3& wo, const Vec3& wi) const override {
        if (lobe != 0 || !side.bothAbove(wo, wi)) return 0.0f;
        return cosineHemispherePdf(glm::dot(wi, side.normal));
    }

    // Cosine-weighted, as Lambert's: the weight is eval / pdf = kd (A + B ...).
    std::optional<LobeSample> sample(int lobe, const SurfaceSide& side, const Vec3& wo, Vec2 u) const override {
        if (lobe != 0 || !(glm::dot(wo, side.normal) > 0.0f)) return std::nullopt;
        LobeSample s;
        s.wi = Frame(side.normal).toWorld(sampleCosineHemisphere(u));
        const float cosIn = glm::dot(s.wi, side.normal);
        if (cosIn <= 0.0f) return std::nullopt;
        s.pdf = cosineHemispherePdf(cosIn);
        s.weight = kd * roughness(side, wo, s.wi);
        return s;
    }

    // The reflectance at normal incidence, kd A (theta_o = 0 leaves only the A term).
    float albedo(int lobe, const SurfaceSide&, const Vec3&) const override {
        return lobe == 0 ? maxComponent(kd) * a : 0.0f;
    }

    int factors(int lobe, const SurfaceSide& side, const Vec3& wo, const Vec3& wi, NamedFactors& factors) const override {
        if (lobe != 0) return 0;
        factors = {{{"kd", kd}, {"(A+B...)N.L", Rgb{roughness(side, wo, wi) * glm::dot(side.normal, wi)}}}};
        return 2;
    }

    Rgb diffuseReflectance() const override { return kd * a; }

private:
    // A + B max(0, cos(phi_i - phi_o)) sin(alpha) tan(beta), in the frame of the shading normal.
    float roughness(const SurfaceSide& side, const Vec3& wo, const Vec3& wi) const {
        const Frame frame(side.normal);
        const Vec3 o = frame.toLocal(wo), i = frame.toLocal(wi);
        const float sinO = std::sqrt(std::max(0.0f, 1.0f - o.z * o.z));
        const float sinI = std::sqrt(std::max(0.0f, 1.0f - i.z * i.z));
        if (sinO < 1e-4f || sinI < 1e-4f) return a;  // phi is undefined at the pole; the B term is 0
        const float cosPhiDifference = std::max(0.0f, (o.x * i.x + o.y * i.y) / (sinO * sinI));
        // alpha is the larger angle (smaller cosine), beta the smaller one.
        const bool inIsSteeper = i.z > o.z;
        const float sinAlpha = inIsSteeper ? sinO : sinI;
        const float tanBeta = inIsSteeper ? sinI / i.z : sinO / o.z;
        return a + b * cosPhiDifference * sinAlpha * tanBeta;
    }
};

MaterialSlot makeOrenNayar(const ParameterValues& values) {
    OrenNayarMaterial material;
    material.kd = values.colour("kd");
    const float sigma = values.number("sigma") * kPi / 180.0f;
    const float sigma2 = sigma * sigma;
    material.a = 1.0f - sigma2 / (2.0f * (sigma2 + 0.33f));
    material.b = 0.45f * sigma2 / (sigma2 + 0.09f);
    material.emission = values.colour("emission");
    return material;
}

}  // namespace
}  // namespace lightpath::examples

LIGHTPATH_REGISTER_MATERIAL(lightpath::MaterialType{
    {"material", "oren-nayar", "example plugin: rough diffuse (Oren-Nayar), Lambert's at sigma = 0",
     {{"kd", lightpath::ParameterType::Colour, "", "0.5", lightpath::kNonNegative, "diffuse reflectance"},
      {"sigma", lightpath::ParameterType::Number, "°", "20", {0.0, 90.0, false, false},
       "roughness: the standard deviation of the microfacets' slope angle"},
      {"emission", lightpath::ParameterType::Colour, "W/(m² sr)", "0", lightpath::kNonNegative,
       "emitted radiance: the surface is an area light"}},
     "<RD>"},
    // After the shipped types in listings. The model is symmetric in wo and wi (reciprocal); its
    // energy balance is not promised (the qualitative model does not conserve energy exactly).
    100, lightpath::examples::makeOrenNayar, {{true, false}, nullptr}})
