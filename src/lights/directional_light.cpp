// A directional light: parallel rays of irradiance E (W/m^2) on a surface perpendicular to them,
// a delta in direction, as the sun is to a room (glTF's KHR_lights_punctual "directional", whose
// lux lightpath reads as W/m^2: shapes/gltf.cpp). A Lambertian surface of albedo rho at angle
// theta to the rays reflects radiance rho / pi E cos theta. Its light walks start on a disk
// across the scene's bounding sphere (pbrt-v4 12.4, DistantLight).
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "lights/light.h"
#include "sampling/warp.h"
#include "scene/light_type.h"

namespace lightpath {
namespace {

class DirectionalLight final : public SceneLight {
public:
    Vec3 direction{0.0f, -1.0f, 0.0f};  // unit, where the light travels
    Rgb irradiance{1.0f};

    explicit DirectionalLight(std::string lightName) : SceneLight(std::move(lightName)) {}

    std::unique_ptr<SceneLight> clone() const override { return std::make_unique<DirectionalLight>(*this); }
    // It has no place: the origin stands in for drawings; bounds do not need it.
    Vec3 position() const override { return Vec3{0.0f}; }
    std::unique_ptr<Light> makeSource(std::uint32_t index) const override;
};

class DirectionalLightSource final : public Light {
public:
    DirectionalLightSource(const DirectionalLight& description, std::uint32_t index)
        : Light({lpe::EventType::Emitter, lpe::Scatter::None, Subject::SceneLight, index, Vec3{0.0f}}),
          light_(description) {}

    void preprocess(const Bounds& bounds) override {
        centre_ = bounds.empty() ? Vec3{0.0f} : bounds.centroid();
        radius_ = bounds.empty() ? 1.0f : 0.5f * glm::length(bounds.hi - bounds.lo);
        if (!(radius_ > 0.0f) || !std::isfinite(radius_)) radius_ = 1.0f;
    }

    // The light's point stands beyond the scene's bounding sphere, against the rays, so that a
    // shadow ray towards it crosses everything that could shade the receiver.
    LightSample sample(const Vec3& receiver, Vec2) const override {
        LightSample s;
        s.wi = -light_.direction;
        s.distance = glm::length(receiver - centre_) + 2.0f * radius_;
        s.point = receiver + s.wi * s.distance;
        s.weight = light_.irradiance;
        return s;
    }
    float pdf(const Vec3&, const Vec3&, const Vec3&) const override { return 0.0f; }

    // A point on the disk of the bounding sphere's radius across the rays, moved back out of the
    // sphere; pdfDirection is per unit area of that disk (lights/light.h's light at infinity).
    EmittedRay sampleEmission(Vec2 uPoint, Vec2) const override {
        const Vec2 d = sampleConcentricDisk(uPoint);
        const Frame frame(light_.direction);
        EmittedRay e;
        e.ray.origin = centre_ + radius_ * (frame.toWorld({d.x, d.y, 0.0f}) - light_.direction);
        e.ray.direction = light_.direction;
        e.radiance = light_.irradiance;
        e.pdfPosition = 1.0f;
        e.pdfDirection = diskDensity();
        return e;
    }
    // Only along the rays: the receiver lies in the disk's cylinder when the scene's bounds hold it.
    float pdfEmissionDirection(const Vec3&, const Vec3& direction) const override {
        return glm::dot(direction, light_.direction) > kParallel ? diskDensity() : 0.0f;
    }
    // Its rays are parallel: along any other direction it sends nothing.
    EmittedRay emitAlong(const EmittedRay& from, const Vec3& direction) const override {
        EmittedRay e = from;
        e.ray.direction = direction;
        e.pdfDirection = pdfEmissionDirection(e.normal, direction);
        if (!(e.pdfDirection > 0.0f)) e.radiance = Rgb{0.0f};
        return e;
    }
    // Within the cylinder the disk sweeps along the rays.
    bool emitsTowards(const Vec3& receiver) const override {
        const Vec3 offset = receiver - centre_;
        const Vec3 across = offset - glm::dot(offset, light_.direction) * light_.direction;
        return glm::dot(across, across) <= radius_ * radius_;
    }
    Rgb radiance(const SurfaceHit&, const Vec3&) const override { return Rgb{0.0f}; }
    // The flux through the disk.
    Rgb power() const override { return light_.irradiance * (kPi * radius_ * radius_); }
    bool isDelta() const override { return true; }
    bool atInfinity() const override { return true; }

private:
    // A direction from a receiver to the light's point in sample() is the rays' up to rounding.
    static constexpr float kParallel = 0.9999f;
    float diskDensity() const { return 1.0f / (kPi * radius_ * radius_); }

    DirectionalLight light_;
    Vec3 centre_{0.0f};
    float radius_ = 1.0f;
};

std::unique_ptr<Light> DirectionalLight::makeSource(std::uint32_t index) const {
    return std::make_unique<DirectionalLightSource>(*this, index);
}

void addDirectionalLight(const ParameterValues& values, SceneBuilder& scene) {
    checkLightName(values);
    DirectionalLight light(values.has("name") ? values.text("name") : std::string());
    light.direction = Vec3(glm::normalize(glm::dvec3(values.vec3("direction"))));  // in double: a tiny vector squared underflows floats
    light.irradiance = values.colour("irradiance");
    scene.addLight(std::move(light));
}

}  // namespace
}  // namespace lightpath

LIGHTPATH_REGISTER_LIGHT(lightpath::LightType{
    {"light", "directional", "a directional light: parallel rays of irradiance E, as the sun's",
     {lightpath::kLightNameParameter,
      {"direction", lightpath::ParameterType::Vector, "", "[0, -1, 0]", {}, "where the light travels"},
      {"irradiance", lightpath::ParameterType::Colour, "W/m²", "1", lightpath::kNonNegative,
       "E on a surface perpendicular to the rays: a Lambertian surface of albedo ρ at angle θ reflects ρ/π E cos θ"}},
     "<L.>"},
    4, lightpath::addDirectionalLight})
