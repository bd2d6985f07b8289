#pragma once
// The one reading of a material that every integrator shares (docs/design.md, "One light
// transport"): a material's lobes at one surface hit, the choice among them in proportion to
// their albedo (or the material's own, Material::choosesLobe), and the densities that choice
// implies. Results name their lobe (its index in the material's lobes()), and so its event
// (materials/lobe.h): an integrator never maps lobes to events by hand.
#include <array>
#include <cstdint>
#include <optional>

#include "materials/material.h"

namespace lightpath {

struct BsdfSample {
    Vec3 wi{0.0f};      // unit, world space, away from the surface
    Rgb weight{0.0f};   // f |cos theta_i| / pdf: what the path throughput is multiplied by
    float pdf = 0.0f;   // solid-angle density, the lobe choice included; 0 for a delta lobe
    int lobe = 0;       // its index in the material's lobes()
};

class Bsdf {
public:
    // `normal`: unit shading normal on the side of the path's outgoing direction. `entering`: that
    // side is the outside of the material (it refracts from 1 into its index of refraction).
    // `texture`: where its textured parameters are looked up (zero when it has none).
    // `present`: the material's has(l) for every lobe, when the caller knows them (the scene's
    // analysis, MaterialTerms::lobes): read instead of one virtual call per lobe and question.
    Bsdf(const Material& material, const Vec3& normal, bool entering,
         TransportMode mode = TransportMode::Radiance, const TextureFootprint& texture = {},
         const std::array<bool, kMaxLobes>* present = nullptr, const Rgb& vertexColor = Rgb(1.0f))
        : material_(material), lobes_(material.lobes()), side_{normal, entering, mode, texture, vertexColor},
          present_(present) {}

    Lobes lobes() const { return lobes_; }
    const LobeInfo& lobe(int index) const { return lobes_[index]; }
    bool has(int lobe) const { return present_ != nullptr ? (*present_)[lobe] : material_.has(lobe); }
    // Whether a smooth (non-delta) lobe scatters anything: light sampling can reach this point.
    bool hasSmoothLobe() const {
        for (int l = 0; l < int(lobes_.size()); ++l)
            if (!lobes_[l].delta() && has(l)) return true;
        return false;
    }

    // f(wo, wi) |cos theta_i| of a smooth lobe; zero where the lobe has no support.
    Rgb eval(int lobe, const Vec3& wo, const Vec3& wi) const { return material_.eval(lobe, side_, wo, wi); }
    // The density of sample() returning wi through `lobe` (a smooth one), its choice included.
    float pdf(int lobe, const Vec3& wo, const Vec3& wi) const;
    // One lobe in proportion to its weight, then a direction within it; nullopt when the material
    // scatters nothing or the direction falls below the surface.
    std::optional<BsdfSample> sample(const Vec3& wo, float uLobe, Vec2 u) const;

    // The delta lobes' branches from wo: the mirror ray, then the refracted ray (none on total
    // internal reflection, whose share the mirror ray carries). Returns how many were written.
    int specularBranches(const Vec3& wo, SpecularBranches& branches) const {
        return material_.specularBranches(side_, wo, branches);
    }
    // pi eval(), the lobe's term under a point light, as the lecture's named factors; returns how many.
    int factors(int lobe, const Vec3& wo, const Vec3& wi, NamedFactors& factors) const {
        return material_.factors(lobe, side_, wo, wi, factors);
    }

    const Vec3& normal() const { return side_.normal; }
    // ka of the ambient term here (the material's, a texture read at this point).
    Rgb ambientReflectance() const { return material_.ambientReflectanceAt(side_); }
    // The constant diffuse part's reflectance here (radiosity's; a texture read at this point).
    Rgb diffuseReflectance() const { return material_.diffuseReflectanceAt(side_); }
    // The same toward wo, the rest of the hemisphere averaged (Material::diffuseReflectanceToward).
    Rgb diffuseReflectanceToward(const Vec3& wo) const { return material_.diffuseReflectanceToward(side_, wo); }
    Rgb diffuseReflectanceBetween(const Vec3& wo, const Vec3& wi) const {
        return material_.diffuseReflectanceBetween(side_, wo, wi);
    }

private:
    // Probability of choosing each lobe for wo, in proportion to its albedo. Integrators ask
    // for the same wo again and again (pdf per lobe in next-event estimation, then sample), so
    // answers are kept: for Fresnel glass it costs a Fresnel evaluation. Two of them: the first
    // wo asked (the hit's own) and the last other one, so bdpt's joins, which alternate the
    // hit's wo with the reverse density's wo (wo and wi swapped), keep the first. Where the
    // material's lobe albedos ignore wo (Material::lobeAlbedosIgnoreWo), the first serves every wo.
    const std::array<float, kMaxLobes>& lobeProbabilities(const Vec3& wo) const;

    struct LobeChoice {
        Vec3 wo{0.0f};  // zero: not yet asked (a wo is unit)
        std::array<float, kMaxLobes> probabilities{};
    };
    void computeLobeProbabilities(LobeChoice& choice) const;

    const Material& material_;
    Lobes lobes_;  // asked once per hit: integrators read a lobe's event at every step
    SurfaceSide side_;
    const std::array<bool, kMaxLobes>* present_;
    mutable LobeChoice first_, last_;
    enum class WoDependence : std::uint8_t { Unknown, Ignored, Used };
    mutable WoDependence woDependence_ = WoDependence::Unknown;  // asked on the first miss only
};

}  // namespace lightpath
