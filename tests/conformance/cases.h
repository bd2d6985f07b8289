#pragma once
// What the conformance kit runs its checks over: one function per family lists every case. Each
// registered material and light type (src/schema/) is checked at its defaults and at parameter sets
// drawn within its schema's ranges, besides hand-picked cases of the shipped types; integrators
// are every row of integrators() (src/integrators/registry.h).
#include <array>
#include <functional>
#include <string>
#include <string_view>

#include "integrators/registry.h"
#include "materials/material.h"
#include "materials/material_type.h"
#include "scene/scene.h"

namespace lightpath::conformance {

// What a material promises beyond the interface, which the checks hold it to.
struct MaterialClaims {
    // f(wo, wi) == f(wi, wo) for this smooth lobe (Helmholtz reciprocity), by index in Material::lobes().
    std::array<bool, kMaxLobes> reciprocal{};
    // Reflects at most what arrives, in every direction: a white furnace estimate of its albedo
    // stays <= 1 (for parameters that ask for it, e.g. kd + ks <= 1).
    bool conservesEnergy = false;
    // The events its schema says it produces (TypeSchema::events, e.g. "<R[DG]>"): every lobe it
    // declares must scatter by one of them, so `lightpath types` tells the truth.
    std::string events;
};

struct MaterialCase {
    std::string name;  // "type: parameters", for messages
    MaterialSlot material;
    MaterialClaims claims;
};

// A scene holding one light (and nothing else) as its type puts it there.
struct LightCase {
    std::string name;
    Scene scene;
};

// What a material type promises (MaterialType::promises) for these values.
MaterialClaims materialClaims(const MaterialType& type, const ParameterValues& values);

void forEachMaterialCase(const std::function<void(const MaterialCase&)>& visit);
void forEachLightCase(const std::function<void(const LightCase&)>& visit);

// One shape of a registered kind (scene/shape_type.h), drawn within its schema, in a scene of its
// own whose material emits: the shape checks take `shape`, and the light checks the scene (every
// kind can be an emitter), so a kind gets both by registering.
struct ShapeCase {
    std::string name;
    Scene scene;
    ShapeRecord record;  // the scene's one shape, as SceneGeometry's table holds it
    const ShapeRecord& shape() const { return record; }
};
void forEachShapeCase(const std::function<void(const ShapeCase&)>& visit);

}  // namespace lightpath::conformance

namespace lightpath::conformance {

// The scenes the integrator checks render: every kind of event (diffuse, glossy, mirror, glass,
// point and area lights, an emitting object, the ambient term, the background), small.
Scene integratorScene();
// The same without what only some methods gather (the ambient term, the sky): where every
// integrator's light on the paths it shares with the path tracer is the path tracer's. Its key
// light is a small sphere just behind the camera: the shadows it casts are hidden behind what
// casts them (the rasteriser has no shadows). No mirror or glass: their light under a small light is
// too noisy for the path tracer to be a sharp reference in a suite of seconds (tests/render/
// test_transport.cpp compares Whitted's on every shipped scene).
Scene agreementScene();
// How far an integrator's image mean may be from the path tracer's by design, relative: 0 for an
// unbiased method. Until the registry's rows carry it, the kit names the one approximation.
double agreementAllowance(const IntegratorInfo& integrator);

}  // namespace lightpath::conformance
