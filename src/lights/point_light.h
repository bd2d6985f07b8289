#pragma once
// Szymczak's point light: intensity I at a position, attenuated by 1 / (c0 + c1 d + c2 d^2).
// Its radiant intensity is pi I (W/sr), so that the diffuse term kd (N.L) I of the illumination
// formula is exactly Lambert's (kd / pi) (N.L) (pi I) under it. With attenuation [0, 0, 1] it is
// a physical light; any other attenuation is the lecture's convenience, not physics.
#include "lights/light.h"
#include "scene/light.h"

namespace lightpath {

class PointLightSource final : public Light {
public:
    PointLightSource(const PointLight& description, std::uint32_t index);

    LightSample sample(const Vec3& receiver, Vec2 u) const override;
    float pdf(const Vec3&, const Vec3&, const Vec3&) const override { return 0.0f; }
    EmittedRay sampleEmission(Vec2 uPoint, Vec2 uDirection) const override;
    float pdfEmissionDirection(const Vec3&, const Vec3&) const override { return 1.0f / (4.0f * kPi); }
    Rgb radiance(const SurfaceHit&, const Vec3&) const override { return Rgb{0.0f}; }
    float falloff(float distance) const override { return description_.attenuationAt(distance); }
    Rgb power() const override;
    bool isDelta() const override { return true; }

    // Radiant intensity, W/sr: pi times the scene file's `intensity`.
    Rgb radiantIntensity() const { return kPi * description_.intensity; }

private:
    PointLight description_;
};

}  // namespace lightpath
