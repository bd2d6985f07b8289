// Example plugin (docs/extending.md): a spot light, a point light whose intensity falls off over a
// cone around its axis with a smooth edge (pbrt-v4 12.2.2: smoothstep between the falloff start and
// the cone's edge). One file: the scene's description, the source the integrators sample, its schema
// and its registration.
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "lights/light.h"
#include "sampling/warp.h"
#include "scene/light_type.h"

namespace lightpath::examples {
namespace {

class SpotLight final : public SceneLight {
public:
    Vec3 location{0.0f};
    Vec3 axis{0.0f, -1.0f, 0.0f};  // unit, where the cone points
    Rgb intensity{1.0f};
    float cosEdge = 0.0f;           // cos of the cone's half angle: nothing outside it
    float cosFalloffStart = 0.0f;   // cos of the angle up to which the full intensity shines

    SpotLight(std::string lightName) : SceneLight(std::move(lightName)) {}

    std::unique_ptr<SceneLight> clone() const override { return std::make_unique<SpotLight>(*this); }
    Vec3 position() const override { return location; }
    std::unique_ptr<Light> makeSource(std::uint32_t index) const override;

    // The share of the axis' intensity along unit `direction` leaving the light: 1 inside the
    // falloff start, 0 outside the edge, smoothstep between.
    float cone(const Vec3& direction) const {
        const float c = glm::dot(direction, axis);
        if (c >= cosFalloffStart) return 1.0f;
        if (c <= cosEdge) return 0.0f;
        const float t = (c - cosEdge) / (cosFalloffStart - cosEdge);
        return t * t * (3.0f - 2.0f * t);
    }
};

class SpotLightSource final : public Light {
public:
    SpotLightSource(const SpotLight& description, std::uint32_t index)
        : Light({lpe::EventType::Emitter, lpe::Scatter::None, Subject::SceneLight, index, description.location}),
          spot_(description) {}

    // Radiant intensity pi I (W/sr) on the axis, as the point light's (lights/point_light.h), so
    // that kd (N.L) I of the lecture's formula holds inside the cone; it falls off as 1/d^2.
    LightSample sample(const Vec3& receiver, Vec2) const override {
        LightSample s;
        s.point = spot_.location;
        const Vec3 toLight = s.point - receiver;
        s.distance = glm::length(toLight);
        s.wi = toLight / s.distance;
        s.weight = axisIntensity() * (spot_.cone(-s.wi) * falloff(s.distance));
        return s;
    }
    float pdf(const Vec3&, const Vec3&, const Vec3&) const override { return 0.0f; }

    // Directions uniformly within the cone's edge (pbrt-v4 12.2.2).
    EmittedRay sampleEmission(Vec2, Vec2 uDirection) const override {
        const float cosTheta = 1.0f - uDirection.x * (1.0f - spot_.cosEdge);
        const float sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
        const float phi = 2.0f * kPi * uDirection.y;
        EmittedRay e;
        e.ray.origin = spot_.location;
        e.ray.direction = glm::normalize(
            Frame(spot_.axis).toWorld({sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta}));
        e.radiance = axisIntensity() * spot_.cone(e.ray.direction);
        e.pdfPosition = 1.0f;
        e.pdfDirection = coneDensity();
        return e;
    }
    float pdfEmissionDirection(const Vec3&, const Vec3& direction) const override {
        return glm::dot(direction, spot_.axis) >= spot_.cosEdge ? coneDensity() : 0.0f;
    }
    Rgb radiance(const SurfaceHit&, const Vec3&) const override { return Rgb{0.0f}; }
    // Intensity times the cone's solid angle: the full 2 pi (1 - cos start) and, under the
    // smoothstep, half of 2 pi (cos start - cos edge) (smoothstep integrates to 1/2 over [0, 1]).
    Rgb power() const override {
        return axisIntensity() *
               (2.0f * kPi * ((1.0f - spot_.cosFalloffStart) + 0.5f * (spot_.cosFalloffStart - spot_.cosEdge)));
    }
    bool isDelta() const override { return true; }

private:
    Rgb axisIntensity() const { return kPi * spot_.intensity; }
    float coneDensity() const { return 1.0f / (2.0f * kPi * (1.0f - spot_.cosEdge)); }

    SpotLight spot_;
};

std::unique_ptr<Light> SpotLight::makeSource(std::uint32_t index) const {
    return std::make_unique<SpotLightSource>(*this, index);
}

float cosOfDegrees(float degrees) { return std::cos(degrees * kPi / 180.0f); }

void addSpotLight(const ParameterValues& values, SceneBuilder& scene) {
    checkLightName(values);
    SpotLight light(values.has("name") ? values.text("name") : std::string());
    light.location = values.vec3("position");
    light.axis = glm::normalize(values.vec3("direction"));
    light.intensity = values.colour("intensity");
    const float coneAngle = values.number("cone_angle"), falloffStart = values.number("falloff_start");
    if (falloffStart > coneAngle) {
        values.fail("falloff_start", "expected at most cone_angle (" + formatNumber(coneAngle) + "°), got " +
                                         formatNumber(falloffStart) + "°");
    }
    light.cosEdge = cosOfDegrees(coneAngle);
    light.cosFalloffStart = cosOfDegrees(falloffStart);
    scene.addLight(std::move(light));
}

}  // namespace
}  // namespace lightpath::examples

LIGHTPATH_REGISTER_LIGHT(lightpath::LightType{
    {"light", "spot", "example plugin: a spot light, a point light shining into a cone with a smooth edge",
     {lightpath::kLightNameParameter,
      {"position", lightpath::ParameterType::Point, "m", "", {}, "where the light is", true},
      {"direction", lightpath::ParameterType::Vector, "", "[0, -1, 0]", {}, "the cone's axis"},
      {"intensity", lightpath::ParameterType::Colour, "", "1", lightpath::kNonNegative,
       "as the point light's: radiant intensity π I (W/sr) on the axis, falling off as 1/d²"},
      {"cone_angle", lightpath::ParameterType::Number, "°", "30", {0.0, 90.0, true, false},
       "the cone's half angle: no light outside it"},
      {"falloff_start", lightpath::ParameterType::Number, "°", "20", lightpath::kNonNegative,
       "the half angle of full intensity, at most `cone_angle`; smoothstep between the two"}},
     "<L.>"},
    100, lightpath::examples::addSpotLight})
