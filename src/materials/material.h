#pragma once
// What a surface does with light: the interface every material implements (Nori's BSDF
// sample/eval/pdf, one material per file). A material declares its lobes (materials/lobe.h); the
// per-hit Bsdf chooses among them and weighs the choice, so a material only describes each lobe.
// Adding a material is its own file, which registers its MaterialType (materials/material_type.h).
#include <memory>
#include <optional>
#include <string>

#include "materials/alpha.h"
#include "materials/lobe.h"
#include "materials/texture.h"
#include "math/types.h"
#include "util/polymorphic_value.h"

namespace lightpath {

class Material {
public:
    virtual ~Material() = default;

    std::string name;
    // Emitted radiance: makes the surface an emitter (`O`, or `L` when declared a light). Its light
    // (lights/area_light.h) reads a texture at the emitting point's uv; `textured` is not needed for it.
    ColorParameter emission;
    // Whether it emits from both sides of the surface (glTF's doubleSided, as Cycles' mesh lights
    // do) rather than the side its normal faces; a closed shape always emits from both.
    bool twoSidedEmission = false;
    // Some parameter is a texture (materials/texture.h): shading points then find their texture
    // coordinates and footprint, which an untextured material never pays for.
    bool textured = false;
    // Some parameter is multiplied by the mesh's vertex colour (glTF's COLOR_0 on the base colour):
    // shading points then find it (SurfaceSide::vertexColor), which no other material pays for.
    bool vertexColored = false;
    // A normal map (glTF's normalTexture) turning the shading normal; set with `textured`.
    NormalMap normalMap;
    // Where the surface is (materials/alpha.h): null when it is everywhere, as most are. Rays pass
    // through where it is not (SceneGeometry asks it at each hit); an emitter is never cut out.
    std::shared_ptr<const Alpha> alpha;

    virtual std::unique_ptr<Material> clone() const = 0;

    // The lobes this material declares (materials/lobe.h), at most kMaxLobes, the same list for
    // every instance of its type; `lobe` below is an index into it.
    virtual Lobes lobes() const = 0;
    // Whether the lobe scatters anything with these parameters (e.g. kd != 0).
    virtual bool has(int lobe) const = 0;
    // f(wo, wi) |cos theta_i| of a smooth lobe; zero where the lobe has no support (a reflection
    // lobe for wi below the surface, a transmission lobe for wi above it).
    virtual Rgb eval(int lobe, const SurfaceSide& side, const Vec3& wo, const Vec3& wi) const = 0;
    // The density of sample() returning wi, within the lobe.
    virtual float pdf(int lobe, const SurfaceSide& side, const Vec3& wo, const Vec3& wi) const = 0;
    // A direction within a smooth lobe; nullopt where eval() would be 0.
    virtual std::optional<LobeSample> sample(int lobe, const SurfaceSide& side, const Vec3& wo, Vec2 u) const = 0;
    // A smooth lobe's (estimated) albedo from wo: lobes are chosen in proportion to it.
    virtual float albedo(int lobe, const SurfaceSide& side, const Vec3& wo) const = 0;
    // Whether albedo() and the specular branches' albedos are the same for every wo on this side:
    // the Bsdf then chooses lobes once per hit, where bdpt's reverse densities ask from many wo.
    virtual bool lobeAlbedosIgnoreWo(const SurfaceSide& side) const {
        (void)side;
        return false;
    }
    // Whether the material chooses among its lobes itself, after sampling what the choice depends
    // on (Walter et al. 2007 choose reflection or refraction by the Fresnel factor at the sampled
    // microfacet): the Bsdf then asks it for every sample and density, and not albedo().
    virtual bool choosesLobe() const { return false; }
    // One direction through a lobe it chose; weight and pdf include the choice. Only when choosesLobe().
    virtual std::optional<ChosenLobeSample> sampleChosenLobe(const SurfaceSide& side, const Vec3& wo, float uLobe,
                                                             Vec2 u) const {
        (void)side, (void)wo, (void)uLobe, (void)u;
        return std::nullopt;
    }
    // The density of sampleChosenLobe returning wi through `lobe`, the choice included.
    virtual float chosenLobePdf(int lobe, const SurfaceSide& side, const Vec3& wo, const Vec3& wi) const {
        (void)lobe, (void)side, (void)wo, (void)wi;
        return 0.0f;
    }
    // The delta lobes' branches from wo, mirror ray first. Returns how many were written: none
    // when no delta lobe is present (has() false for each), as Bsdf does not ask then.
    virtual int specularBranches(const SurfaceSide& side, const Vec3& wo, SpecularBranches& branches) const {
        (void)side, (void)wo, (void)branches;
        return 0;
    }
    // pi eval(), the lobe's term in the lecture's formula under a point light of intensity I (whose
    // radiant intensity is pi I), as named factors (`explain`: kd and N.L); returns how many.
    virtual int factors(int lobe, const SurfaceSide& side, const Vec3& wo, const Vec3& wi,
                        NamedFactors& factors) const = 0;

    // The reflectance of the constant diffuse part, for radiosity; black when there is none.
    virtual Rgb diffuseReflectance() const = 0;
    // The same at one surface point (a textured kd varies; diffuseReflectance is then its mean):
    // radiosity's display and final gather read the texture the patch averages.
    virtual Rgb diffuseReflectanceAt(const SurfaceSide& side) const {
        (void)side;
        return diffuseReflectance();
    }
    // The diffuse part's albedo toward wo at one point, the rest of the hemisphere averaged: what
    // radiosity shows toward the eye. Lambertian, the same from every wo; a base under a specular
    // layer or a coat (MicrofacetMaterial) gets less of the light at grazing wo.
    virtual bool diffuseDependsOnView() const { return false; }
    virtual Rgb diffuseReflectanceToward(const SurfaceSide& side, const Vec3& wo) const {
        (void)wo;
        return diffuseReflectanceAt(side);
    }
    // pi f of the diffuse part for light from wi reflected toward wo (Lambertian: kd); radiosity's
    // final gather weighs each of its directions by it at the point the camera sees.
    virtual Rgb diffuseReflectanceBetween(const SurfaceSide& side, const Vec3& wo, const Vec3& wi) const {
        (void)wi;
        return diffuseReflectanceToward(side, wo);
    }
    // ka of the illumination formula's ambient term, which only the classic integrators add.
    virtual Rgb ambientReflectance() const { return Rgb{0.0f}; }
    // ka at one surface point (a textured ka varies; ambientReflectance is then its mean).
    virtual Rgb ambientReflectanceAt(const SurfaceSide& side) const {
        (void)side;
        return ambientReflectance();
    }
    // pbrt-v4's interface material (materials/interface_material.cpp): the surface only bounds a
    // medium, and rays cross it without an event.
    virtual bool isInterface() const { return false; }

protected:
    Material() = default;
    Material(const Material&) = default;
    Material& operator=(const Material&) = default;
};

// A scene's material: owned, polymorphic, and copied with the scene.
using MaterialSlot = PolymorphicValue<Material>;

}  // namespace lightpath
