#include "lights/point_light.h"

#include <cmath>

#include "scene/light_type.h"
#include "sampling/warp.h"
#include "util/hot_path.h"

namespace lightpath {

PointLightSource::PointLightSource(const PointLight& description, std::uint32_t index)
    : Light({lpe::EventType::Emitter, lpe::Scatter::None, Subject::SceneLight, index, description.location}),
      description_(description) {}

std::unique_ptr<Light> PointLight::makeSource(std::uint32_t index) const {
    return std::make_unique<PointLightSource>(*this, index);
}

LIGHTPATH_HOT_PATH
LightSample PointLightSource::sample(const Vec3& receiver, Vec2) const {
    LightSample s;
    s.point = description_.location;
    const Vec3 toLight = s.point - receiver;
    s.distance = glm::length(toLight);
    s.wi = toLight / s.distance;
    s.weight = radiantIntensity() * falloff(s.distance);
    return s;
}

EmittedRay PointLightSource::sampleEmission(Vec2, Vec2 uDirection) const {
    EmittedRay e;
    e.ray.origin = description_.location;
    e.ray.direction = sampleUniformSphere(uDirection);
    e.radiance = radiantIntensity();
    e.pdfPosition = 1.0f;
    e.pdfDirection = 1.0f / (4.0f * kPi);
    return e;
}

Rgb PointLightSource::power() const { return 4.0f * kPi * radiantIntensity(); }

}  // namespace lightpath

namespace lightpath {
namespace {

// The smallest non-zero attenuation coefficient: 1 / c stays within the scene's largest number.
constexpr float kMinAttenuation = 1e-6f;

void addPointLight(const ParameterValues& values, SceneBuilder& scene) {
    checkLightName(values);
    PointLight light(values.has("name") ? values.text("name") : std::string(), values.vec3("position"),
                     values.colour("intensity"), values.vec3("attenuation"));
    if (light.attenuation == Vec3(0.0f)) {
        values.fail("attenuation", "expected c0, c1, c2 not all zero (1 / (c0 + c1 d + c2 d^2) would "
                                   "divide by zero), got " + formatVec3(light.attenuation));
    }
    // A coefficient of 1e-30 would make the light 1e30 times brighter: overflow, not light.
    for (int i = 0; i < 3; ++i) {
        if (light.attenuation[i] > 0.0f && light.attenuation[i] < kMinAttenuation) {
            values.fail("attenuation", "expected c0, c1, c2 each 0 or at least 1e-6 (1 / (c0 + c1 d + c2 d^2) "
                                       "would overflow), got " + formatVec3(light.attenuation));
        }
    }
    scene.addLight(std::move(light));
}

}  // namespace
}  // namespace lightpath

LIGHTPATH_REGISTER_LIGHT(lightpath::LightType{
    {"light", "point", "Szymczak's point light: intensity I at a position, attenuated by 1 / (c0 + c1 d + c2 d²)",
     {lightpath::kLightNameParameter,
      {"position", lightpath::ParameterType::Point, "m", "", {}, "where the light is", true},
      {"intensity", lightpath::ParameterType::Colour, "", "1", lightpath::kNonNegative,
       "the lecture's `I_l`; radiant intensity π I (W/sr)"},
      {"attenuation", lightpath::ParameterType::Point, "–, 1/m, 1/m²", "[1, 0, 0]", lightpath::kNonNegative,
       "`[c0, c1, c2]`: the light at distance d is `intensity / (c0 + c1 d + c2 d^2)`; each 0 or at least "
       "1e-6, not all zero"}},
     "<L.>"},
    0, lightpath::addPointLight})
