#pragma once
// Szymczak's point light: intensity I at a position, attenuated by 1 / (c0 + c1 d + c2 d^2).
// Its radiant intensity is pi I (W/sr), so that the diffuse term kd (N.L) I of the illumination
// formula is exactly Lambert's (kd / pi) (N.L) (pi I) under it. With attenuation [0, 0, 1] it is
// a physical light; any other attenuation is the lecture's convenience, not physics.
#include "lights/light.h"
#include "scene/scene_light.h"

namespace lightpath {

// As the scene file declares it.
class PointLight final : public SceneLight {
public:
    Vec3 location{0.0f};
    Rgb intensity{1.0f};
    Vec3 attenuation{1.0f, 0.0f, 0.0f};  // (c0, c1, c2); the default is no attenuation

    explicit PointLight(std::string lightName = {}, Vec3 position = Vec3{0.0f}, Rgb lightIntensity = Rgb{1.0f},
                        Vec3 lightAttenuation = Vec3{1.0f, 0.0f, 0.0f})
        : SceneLight(std::move(lightName)), location(position), intensity(lightIntensity), attenuation(lightAttenuation) {}

    std::unique_ptr<SceneLight> clone() const override { return std::make_unique<PointLight>(*this); }
    Vec3 position() const override { return location; }
    std::unique_ptr<Light> makeSource(std::uint32_t index) const override;

    float attenuationAt(float distance) const {
        return 1.0f / (attenuation.x + distance * (attenuation.y + distance * attenuation.z));
    }
};

// The light source the integrators sample.
class PointLightSource final : public Light {
public:
    PointLightSource(const PointLight& description, std::uint32_t index);

    LightSample sample(const Vec3& receiver, Vec2 u) const override;
    float pdf(const Vec3&, const Vec3&, const Vec3&) const override { return 0.0f; }
    EmittedRay sampleEmission(Vec2 uPoint, Vec2 uDirection) const override;
    EmittedRay emitAlong(const EmittedRay& from, const Vec3& direction) const override {
        EmittedRay e = from;
        e.ray.direction = direction;  // the same intensity every way
        return e;
    }
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

// The point light in a scene's slot, for code that built the scene and edits it (tests); throws
// std::bad_cast for any other light.
inline PointLight& pointLightOf(const LightSlot& slot) { return dynamic_cast<PointLight&>(*slot); }

}  // namespace lightpath
