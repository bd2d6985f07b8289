// A spot light: a point light whose intensity falls off between an inner and an outer cone around
// its axis as glTF's KHR_lights_punctual spot does (the extension's "Inner and Outer Cone Angles"
// appendix: the square of a ramp, linear in the cosine, from 0 at the outer cone to 1 at the inner),
// so that a TOML spot and a glTF spot of the same angles are the same light.
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "lights/light.h"
#include "sampling/warp.h"
#include "scene/light_type.h"

namespace lightpath {
namespace {

class SpotLight final : public SceneLight {
public:
    Vec3 location{0.0f};
    Vec3 axis{0.0f, -1.0f, 0.0f};  // unit, where the cone points
    Rgb intensity{1.0f};
    float cosOuter = 0.0f;  // cos of the outer cone's half angle: nothing outside it
    float cosInner = 1.0f;  // cos of the inner cone's half angle: full intensity inside it

    explicit SpotLight(std::string lightName) : SceneLight(std::move(lightName)) {}

    std::unique_ptr<SceneLight> clone() const override { return std::make_unique<SpotLight>(*this); }
    Vec3 position() const override { return location; }
    std::unique_ptr<Light> makeSource(std::uint32_t index) const override;

    // The share of the axis' intensity along unit `direction` leaving the light: glTF's
    // t = (cos - cos outer) / (cos inner - cos outer) clamped to [0, 1], squared. Equal cones
    // make a hard edge.
    float cone(const Vec3& direction) const {
        const float c = glm::dot(direction, axis);
        if (c >= cosInner) return 1.0f;
        if (c <= cosOuter) return 0.0f;
        const float t = (c - cosOuter) / (cosInner - cosOuter);
        return t * t;
    }
};

class SpotLightSource final : public Light {
public:
    SpotLightSource(const SpotLight& description, std::uint32_t index)
        : Light({lpe::EventType::Emitter, lpe::Scatter::None, Subject::SceneLight, index, description.location}),
          spot_(description) {}

    // Radiant intensity pi I (W/sr) on the axis, as the point light's (lights/point_light.h), so
    // that kd (N.L) I of the lecture's formula holds inside the inner cone; it falls off as 1/d^2.
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

    // Directions uniformly within the outer cone (pbrt-v4 12.2.2): 1 / (2 pi (1 - cos outer)).
    EmittedRay sampleEmission(Vec2, Vec2 uDirection) const override {
        const float cosTheta = 1.0f - uDirection.x * (1.0f - spot_.cosOuter);
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
        return glm::dot(direction, spot_.axis) > spot_.cosOuter ? coneDensity() : 0.0f;
    }
    EmittedRay emitAlong(const EmittedRay& from, const Vec3& direction) const override {
        EmittedRay e = from;
        e.ray.direction = direction;
        e.radiance = axisIntensity() * spot_.cone(direction);
        e.pdfDirection = pdfEmissionDirection(e.normal, direction);
        return e;
    }
    Rgb radiance(const SurfaceHit&, const Vec3&) const override { return Rgb{0.0f}; }
    float intensityShare(const Vec3& leaving) const override { return spot_.cone(leaving); }
    // Intensity times the cone's solid angle: the full 2 pi (1 - cos inner) and, under the ramp
    // squared, a third of 2 pi (cos inner - cos outer) (t^2 integrates to 1/3 over [0, 1]).
    Rgb power() const override {
        return axisIntensity() *
               (2.0f * kPi * ((1.0f - spot_.cosInner) + (spot_.cosInner - spot_.cosOuter) / 3.0f));
    }
    bool isDelta() const override { return true; }

private:
    Rgb axisIntensity() const { return kPi * spot_.intensity; }
    float coneDensity() const { return 1.0f / (2.0f * kPi * (1.0f - spot_.cosOuter)); }

    SpotLight spot_;
};

std::unique_ptr<Light> SpotLight::makeSource(std::uint32_t index) const {
    return std::make_unique<SpotLightSource>(*this, index);
}

float cosOfDegrees(double degrees) { return float(std::cos(degrees * kPi / 180.0)); }

void addSpotLight(const ParameterValues& values, SceneBuilder& scene) {
    checkLightName(values);
    SpotLight light(values.has("name") ? values.text("name") : std::string());
    light.location = values.vec3("position");
    light.axis = Vec3(glm::normalize(glm::dvec3(values.vec3("direction"))));  // in double: a tiny vector squared underflows floats
    light.intensity = values.colour("intensity");
    const double outer = values.number("cone_angle"), inner = values.number("falloff_start");
    if (inner > outer) {
        values.fail("falloff_start", "expected at most cone_angle (" + formatNumber(outer) + "°), got " +
                                         formatNumber(inner) + "°");
    }
    light.cosOuter = cosOfDegrees(outer);
    light.cosInner = cosOfDegrees(inner);
    scene.addLight(std::move(light));
}

}  // namespace
}  // namespace lightpath

LIGHTPATH_REGISTER_LIGHT(lightpath::LightType{
    {"light", "spot", "a spot light: a point light shining into a cone, fading between an inner and an outer cone as glTF's",
     {lightpath::kLightNameParameter,
      {"position", lightpath::ParameterType::Point, "m", "", {}, "where the light is", true},
      {"direction", lightpath::ParameterType::Vector, "", "[0, -1, 0]", {}, "the cone's axis"},
      {"intensity", lightpath::ParameterType::Colour, "", "1", lightpath::kNonNegative,
       "as the point light's: radiant intensity π I (W/sr) on the axis, falling off as 1/d²"},
      {"cone_angle", lightpath::ParameterType::Number, "°", "45", {0.0, 90.0, true, false},
       "the outer cone's half angle (glTF `outerConeAngle`): no light outside it"},
      {"falloff_start", lightpath::ParameterType::Number, "°", "0", lightpath::kNonNegative,
       "the inner cone's half angle (glTF `innerConeAngle`), at most `cone_angle`: full intensity inside it, "
       "between the two the intensity is t², t = (cos θ − cos outer) / (cos inner − cos outer)"}},
     "<L.>"},
    3, lightpath::addSpotLight})
