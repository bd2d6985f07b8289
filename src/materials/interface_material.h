#pragma once
// pbrt-v4's "interface" material: a surface that only marks where a medium begins and ends
// (an index-matched boundary). It has no lobes: integrators pass straight through it, switching
// to the medium beyond, and the crossing adds no event (as in OSL), so `E V <L.>` still matches.
#include "materials/material.h"

namespace lightpath {

class InterfaceMaterial final : public Material {
public:
    std::unique_ptr<Material> clone() const override { return std::make_unique<InterfaceMaterial>(*this); }
    Lobes lobes() const override { return {}; }
    bool has(int) const override { return false; }
    Rgb eval(int, const SurfaceSide&, const Vec3&, const Vec3&) const override { return Rgb{0.0f}; }
    float pdf(int, const SurfaceSide&, const Vec3&, const Vec3&) const override { return 0.0f; }
    std::optional<LobeSample> sample(int, const SurfaceSide&, const Vec3&, Vec2) const override { return std::nullopt; }
    float albedo(int, const SurfaceSide&, const Vec3&) const override { return 0.0f; }
    int factors(int, const SurfaceSide&, const Vec3&, const Vec3&, NamedFactors&) const override { return 0; }
    Rgb diffuseReflectance() const override { return Rgb{0.0f}; }
    bool isInterface() const override { return true; }
};

}  // namespace lightpath
