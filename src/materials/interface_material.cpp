// pbrt-v4's "interface" material: a surface that only marks where a medium begins and ends
// (an index-matched boundary). It has no lobes: integrators pass straight through it, switching
// to the medium beyond, and the crossing adds no event (as in OSL), so `E V <L.>` still matches.
#include "materials/interface_material.h"

#include "materials/material_type.h"

namespace lightpath {
namespace {

MaterialSlot makeInterface(const ParameterValues&) { return MaterialSlot(InterfaceMaterial{}); }

}  // namespace
}  // namespace lightpath

LIGHTPATH_REGISTER_MATERIAL(lightpath::MaterialType{
    {"material", "interface",
     "an index-matched boundary (pbrt-v4): no scattering, it only bounds a closed object's `interior` medium",
     {},
     ""},
    3, lightpath::makeInterface, {{}, nullptr}})
