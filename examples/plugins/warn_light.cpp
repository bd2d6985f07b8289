// Example plugin (docs/extending.md): Warn's spotlight (Warn 1983, "Lighting controls for
// synthetic images"), a point light whose intensity about its axis is cos^n of the angle, the
// Phong lobe turned into a light: n = 0 lights a hemisphere evenly, a large n is a narrow beam
// with no hard edge. One file: the scene's description, the source the integrators sample, its
// schema and its registration.
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "lights/light.h"
#include "sampling/warp.h"
#include "scene/light_type.h"

namespace lightpath::examples {
namespace {

class WarnLight final : public SceneLight {
public:
    Vec3 location{0.0f};
    Vec3 axis{0.0f, -1.0f, 0.0f};  // unit, where the lobe points
    Rgb intensity{1.0f};
    float exponent = 1.0f;         // n of cos^n

    explicit WarnLight(std::string lightName) : SceneLight(std::move(lightName)) {}

    std::unique_ptr<SceneLight> clone() const override { return std::make_unique<WarnLight>(*this); }
    Vec3 position() const override { return location; }
    std::unique_ptr<Light> makeSource(std::uint32_t index) const override;

    // The share of the axis' intensity along unit `direction` leaving the light: cos^n, none behind.
    float lobe(const Vec3& direction) const {
        const float c = glm::dot(direction, axis);
        return c > 0.0f ? std::pow(c, exponent) : 0.0f;
    }
};

class WarnLightSource final : public Light {
public:
    WarnLightSource(const WarnLight& description, std::uint32_t index)
        : Light({lpe::EventType::Emitter, lpe::Scatter::None, Subject::SceneLight, index, description.location}),
          warn_(description) {}

    // Radiant intensity pi I cos^n (W/sr), as the point light's pi I (lights/point_light.h) on the
    // axis, so that kd (N.L) I of the lecture's formula holds there; it falls off as 1/d^2.
    LightSample sample(const Vec3& receiver, Vec2) const override {
        LightSample s;
        s.point = warn_.location;
        const Vec3 toLight = s.point - receiver;
        s.distance = glm::length(toLight);
        s.wi = toLight / s.distance;
        s.weight = axisIntensity() * (warn_.lobe(-s.wi) * falloff(s.distance));
        return s;
    }
    float pdf(const Vec3&, const Vec3&, const Vec3&) const override { return 0.0f; }

    // Directions in proportion to cos^n: cos theta = u^(1 / (n + 1)), density (n + 1) / (2 pi) cos^n
    // (the Phong lobe's sampling), so every light ray carries the same flux.
    EmittedRay sampleEmission(Vec2, Vec2 uDirection) const override {
        const float cosTheta = std::pow(std::max(uDirection.x, 1e-12f), 1.0f / (warn_.exponent + 1.0f));
        const float sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
        const float phi = 2.0f * kPi * uDirection.y;
        EmittedRay e;
        e.ray.origin = warn_.location;
        e.ray.direction = glm::normalize(
            Frame(warn_.axis).toWorld({sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta}));
        e.radiance = axisIntensity() * warn_.lobe(e.ray.direction);
        e.pdfPosition = 1.0f;
        e.pdfDirection = pdfEmissionDirection(Vec3{0.0f}, e.ray.direction);
        return e;
    }
    float pdfEmissionDirection(const Vec3&, const Vec3& direction) const override {
        return (warn_.exponent + 1.0f) / (2.0f * kPi) * warn_.lobe(direction);
    }
    EmittedRay emitAlong(const EmittedRay& from, const Vec3& direction) const override {
        EmittedRay e = from;
        e.ray.direction = direction;
        e.radiance = axisIntensity() * warn_.lobe(direction);
        e.pdfDirection = pdfEmissionDirection(Vec3{0.0f}, direction);
        return e;
    }
    Rgb radiance(const SurfaceHit&, const Vec3&) const override { return Rgb{0.0f}; }
    // Intensity times the lobe's solid angle: the integral of cos^n over the hemisphere, 2 pi / (n + 1).
    Rgb power() const override { return axisIntensity() * (2.0f * kPi / (warn_.exponent + 1.0f)); }
    bool isDelta() const override { return true; }

private:
    Rgb axisIntensity() const { return kPi * warn_.intensity; }

    WarnLight warn_;
};

std::unique_ptr<Light> WarnLight::makeSource(std::uint32_t index) const {
    return std::make_unique<WarnLightSource>(*this, index);
}

void addWarnLight(const ParameterValues& values, SceneBuilder& scene) {
    checkLightName(values);
    WarnLight light(values.has("name") ? values.text("name") : std::string());
    light.location = values.vec3("position");
    light.axis = Vec3(glm::normalize(glm::dvec3(values.vec3("direction"))));  // in double: a tiny vector squared underflows floats
    light.intensity = values.colour("intensity");
    light.exponent = float(values.number("exponent"));
    scene.addLight(std::move(light));
}

}  // namespace
}  // namespace lightpath::examples

LIGHTPATH_REGISTER_LIGHT(lightpath::LightType{
    {"light", "warn", "example plugin: Warn's spotlight, a point light whose intensity is cos^n of the angle to its axis",
     {lightpath::kLightNameParameter,
      {"position", lightpath::ParameterType::Point, "m", "", {}, "where the light is", true},
      {"direction", lightpath::ParameterType::Vector, "", "[0, -1, 0]", {}, "the lobe's axis"},
      {"intensity", lightpath::ParameterType::Colour, "", "1", lightpath::kNonNegative,
       "as the point light's: radiant intensity π I (W/sr) on the axis, falling off as 1/d²"},
      {"exponent", lightpath::ParameterType::Number, "", "10", {0.0, 10000.0, false, false},
       "n: the intensity at angle θ to the axis is π I cosⁿ θ, none behind the light"}},
     "<L.>"},
    100, lightpath::examples::addWarnLight})
