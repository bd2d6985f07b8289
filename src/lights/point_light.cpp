#include "lights/point_light.h"

#include <cmath>

#include "sampling/warp.h"

namespace lightpath {

PointLightSource::PointLightSource(const PointLight& description, std::uint32_t index)
    : Light({lpe::EventType::Emitter, lpe::Scatter::None, Subject::SceneLight, index, description.location}),
      description_(description) {}

std::unique_ptr<Light> PointLight::makeSource(std::uint32_t index) const {
    return std::make_unique<PointLightSource>(*this, index);
}

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
