#pragma once
// Every light of a scene behind the one Light interface: each point light of [[lights]], and one
// area light per emissive object (a [[lights]] quad or sphere, or a surface whose material emits).
// Next-event estimation follows Szymczak's sum over point lights (every delta light, every time)
// plus one area light chosen in proportion to its power.
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "accel/scene_geometry.h"
#include "lights/area_light.h"
#include "lights/emission_guide.h"
#include "lights/light.h"
#include "scene/scene.h"

namespace lightpath {

struct ChosenLight {
    const Light* light = nullptr;  // nullptr when there is none to choose
    float probability = 0.0f;
};

class LightSet {
public:
    LightSet(const Scene& scene, const SceneGeometry& geometry);
    LightSet(const LightSet&) = delete;
    LightSet& operator=(const LightSet&) = delete;

    // All lights: the point lights in scene order, then the area lights in object order.
    std::span<const std::unique_ptr<Light>> all() const { return lights_; }
    std::span<const Light* const> deltaLights() const { return delta_; }
    bool hasAreaLights() const { return !area_.empty(); }
    // Whether chooseAreaLight has a choice to make: with one area light it returns that light,
    // whatever its number.
    bool choosesAmongAreaLights() const { return area_.size() > 1; }

    // One area light in proportion to its power.
    ChosenLight chooseAreaLight(float u) const;
    // Any light in proportion to its power: where light tracing starts.
    ChosenLight chooseEmitter(float u) const;
    float emitterProbability(const Light& light) const;
    // How often next-event estimation picks `light`: 1 for a delta light (each is sampled every
    // time), chooseAreaLight's probability for an area light.
    float nextEventProbability(const Light& light) const;

    // The area light that emissive `object` is, or nullptr.
    const Light* lightOfObject(std::uint32_t object) const {
        return object < ofObject_.size() ? ofObject_[object] : nullptr;
    }
    // Radiance an emitter hit by a ray sends back along it (zero for non-emitters).
    Rgb radiance(const SurfaceHit& hit, const Vec3& towardViewer) const;
    // The solid-angle density with which chooseAreaLight + Light::sample reach `hit` from
    // `receiver`: what MIS weighs a BSDF-sampled hit on an emitter against.
    float pdf(const Vec3& receiver, const SurfaceHit& hit) const;
    // Where light walks leave a light: a share aimed at the scene's specular objects.
    const EmissionGuide& emissionGuide() const { return guide_; }

private:
    struct Choice {
        const Light* light;
        float cumulative;  // of probabilities up to and including this one
        float probability;
    };
    static std::vector<Choice> distribution(std::span<const Light* const> lights);
    static ChosenLight choose(const std::vector<Choice>& choices, float u);

    std::vector<std::unique_ptr<Light>> lights_;
    std::vector<const Light*> delta_, area_;
    std::vector<Choice> areaChoices_, emitterChoices_;
    std::vector<const Light*> ofObject_;       // by scene object
    std::vector<float> areaChoiceOfObject_;    // chooseAreaLight's probability, by scene object
    EmissionGuide guide_;
};

}  // namespace lightpath
