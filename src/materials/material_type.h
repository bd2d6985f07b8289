#pragma once
// A material type a scene names with `[materials.NAME] type = "..."`: its schema and how to make
// it from checked values. Each material's .cpp registers its own with LIGHTPATH_REGISTER_MATERIAL.
#include <array>

#include "materials/material.h"
#include "schema/parameter_values.h"
#include "schema/registry.h"

namespace lightpath {

// What a material promises beyond the interface; the conformance kit (tests/conformance/) holds
// every registered type to it.
struct MaterialPromises {
    // f(wo, wi) == f(wi, wo) (Helmholtz reciprocity), per lobe in the order of Material::lobes().
    std::array<bool, kMaxLobes> reciprocal{};
    // Whether it reflects at most what arrives, from every direction, for these values (e.g.
    // kd + ks <= 1); null: never promised.
    bool (*conservesEnergy)(const ParameterValues& values) = nullptr;
};

// Rows several material types share, so their meaning is written once: any material may emit
// (an area light) and be cut out (alpha), and the GGX materials read roughness alike.
inline constexpr Parameter kEmissionParameter{"emission", ParameterType::Colour, "W/(m² sr)", "0", kNonNegative,
                                              "emitted radiance: the surface is an area light"};
inline constexpr Parameter kTwoSidedEmissionParameter{
    "two_sided_emission", ParameterType::Boolean, "", "false", {},
    "whether an emitting surface emits from both of its sides (glTF's doubleSided, Cycles' mesh lights); "
    "default: the side its normal faces (a triangle's winding); a sphere always emits from both"};
inline constexpr Parameter kAlphaParameter{
    "alpha", ParameterType::NumberOrTexture, "", "1", Range{0.0, 1.0, false, false},
    "coverage: where the surface is; a texture `{ texture = \"leaf.png\", cutoff = 0.5 }` reads its alpha "
    "channel (else its only one) and cuts out where it is below `cutoff` (glTF's MASK); without a cutoff, or "
    "as a number, the fraction of rays the surface stops (the rest pass as if it were not there); ignored on an "
    "emitter"};
inline constexpr Parameter kGgxRoughnessParameter{
    "roughness", ParameterType::Number, "", "0.5", Range{0.0, 1.0, false, false},
    "GGX alpha = roughness²; 0 is a perfect mirror (`<RS>`), above 0 a glossy lobe (`<RG>`)"};

// The values of those three rows, which every material type lists, set on `material`.
inline void readSurfaceRows(const ParameterValues& values, Material& material) {
    material.emission = colorParameter(values, "emission");
    material.twoSidedEmission = values.boolean("two_sided_emission");
    material.alpha = alphaParameter(values, "alpha");
}

struct MaterialType {
    TypeSchema schema;
    int rank = 0;  // listing order (lecture order); rank 0 is the default type
    // May refuse a combination with values.fail(key, ...); the loader sets the name.
    MaterialSlot (*make)(const ParameterValues& values) = nullptr;
    MaterialPromises promises;
};

using MaterialRegistry = TypeRegistry<MaterialType>;

}  // namespace lightpath

#define LIGHTPATH_REGISTER_MATERIAL(...) \
    namespace { const ::lightpath::Registrar<::lightpath::MaterialType> LIGHTPATH_SCHEMA_CONCAT(kMaterialRegistrar, __COUNTER__){__VA_ARGS__}; }
