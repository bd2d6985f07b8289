#include "lights/light_set.h"

#include <algorithm>

#include "scene/emission.h"
#include "scene/framing.h"
#include "util/hot_path.h"

namespace lightpath {

LightSet::LightSet(const Scene& scene, const SceneGeometry& geometry)
    : ofObject_(scene.objects.size(), nullptr), areaChoiceOfObject_(scene.objects.size(), 0.0f),
      guide_(specularTargets(scene)) {
    // What a light at infinity must cover: the bounded shapes and the eye (planes have no bounds).
    Bounds bounds = sceneBounds(scene);
    bounds.grow(scene.camera.eye);
    for (std::uint32_t i = 0; i < scene.lights.size(); ++i) {
        lights_.push_back(scene.lights[i]->makeSource(i));
        lights_.back()->preprocess(bounds);
    }

    // The emissive primitives of each object, by scene-wide id.
    std::vector<std::vector<std::uint32_t>> primitives(scene.objects.size());
    auto emits = [&](std::uint32_t object) { return emissionEventOf(scene, object).has_value(); };
    // An unbounded shape (a plane) has no finite area to sample: seen only where a ray hits it.
    for (std::uint32_t i = 0; i < geometry.shapes().size(); ++i) {
        const ShapeRecord& shape = geometry.shapes()[i];
        if (shape.ops->bounded && emits(shape.object)) primitives[shape.object].push_back(geometry.shapeId(i));
    }
    for (std::uint32_t i = 0; i < geometry.triangles().size(); ++i)
        if (emits(geometry.triangles()[i].object)) primitives[geometry.triangles()[i].object].push_back(geometry.triangleId(i));
    for (std::uint32_t object = 0; object < scene.objects.size(); ++object) {
        if (primitives[object].empty()) continue;
        const lpe::EventType type = *emissionEventOf(scene, object);
        const Material& material = *scene.materials[scene.objects[object].material];
        auto light = std::make_unique<AreaLightSource>(PathEvent{type, lpe::Scatter::None, Subject::Object, object},
                                                       material.emission, geometry, primitives[object],
                                                       material.twoSidedEmission);
        if (light->empty()) continue;
        ofObject_[object] = light.get();
        lights_.push_back(std::move(light));
    }
    // An emitter too small to sample (its warning came from the loader) is seen only where a ray
    // hits it: it is in no distribution, so every strategy's density of reaching it by choice is 0.
    std::vector<const Light*> sampled;
    for (const auto& light : lights_) {
        if (!light->sampleable()) continue;
        (light->isDelta() ? delta_ : area_).push_back(light.get());
        sampled.push_back(light.get());
    }
    areaChoices_ = distribution(area_);
    emitterChoices_ = distribution(sampled);
    // Indexed by object: a shapeless light's event index counts scene lights, another index space.
    for (const Choice& c : areaChoices_)
        if (c.light->event().subject == Subject::Object) areaChoiceOfObject_[c.light->event().index] = c.probability;
}

std::vector<LightSet::Choice> LightSet::distribution(std::span<const Light* const> lights) {
    std::vector<Choice> choices;
    float total = 0.0f;
    for (const Light* light : lights) total += maxComponent(light->power());
    float cumulative = 0.0f;
    for (const Light* light : lights) {
        const float p = total > 0.0f ? maxComponent(light->power()) / total : 1.0f / float(lights.size());
        cumulative += p;
        choices.push_back({light, cumulative, p});
    }
    if (!choices.empty()) choices.back().cumulative = 1.0f;
    return choices;
}

LIGHTPATH_HOT_PATH
ChosenLight LightSet::choose(const std::vector<Choice>& choices, float u) {
    if (choices.empty()) return {};
    // One light (every Cornell box's lamp): the search would return it for any u.
    if (choices.size() == 1) return {choices.front().light, choices.front().probability};
    auto it = std::upper_bound(choices.begin(), choices.end(), u,
                               [](float value, const Choice& c) { return value < c.cumulative; });
    if (it == choices.end()) --it;
    return {it->light, it->probability};
}

LIGHTPATH_HOT_PATH
ChosenLight LightSet::chooseAreaLight(float u) const { return choose(areaChoices_, u); }
ChosenLight LightSet::chooseEmitter(float u) const { return choose(emitterChoices_, u); }

float LightSet::emitterProbability(const Light& light) const {
    for (const Choice& c : emitterChoices_)
        if (c.light == &light) return c.probability;
    return 0.0f;
}

float LightSet::nextEventProbability(const Light& light) const {
    if (light.isDelta()) return 1.0f;
    for (const Choice& c : areaChoices_)
        if (c.light == &light) return c.probability;
    return 0.0f;
}

Rgb LightSet::radiance(const SurfaceHit& hit, const Vec3& towardViewer) const {
    const Light* light = lightOfObject(hit.object);
    return light ? light->radiance(hit, towardViewer) : Rgb{0.0f};
}

LIGHTPATH_HOT_PATH
float LightSet::pdf(const Vec3& receiver, const SurfaceHit& hit) const {
    const Light* light = lightOfObject(hit.object);
    if (!light) return 0.0f;
    return areaChoiceOfObject_[hit.object] * light->pdf(receiver, hit.point, hit.normal);
}

}  // namespace lightpath
