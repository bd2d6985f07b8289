#include "integrators/event_symbols.h"

#include <algorithm>

namespace lightpath {

EventSymbols::EventSymbols(const Scene& scene, const lpe::Automaton& automaton)
    : automaton_(automaton), ambient_(automaton.labelClass(kAmbientLabel)) {
    for (const LightSlot& light : scene.lights) lights_.push_back(automaton.labelClass(light->name));
    for (std::uint32_t i = 0; i < scene.objects.size(); ++i) objects_.push_back(automaton.labelClass(scene.labelOf(i)));
    for (const MediumSlot& medium : scene.media) media_.push_back(automaton.labelClass(medium->name));
}

std::vector<std::string> sceneLabels(const Scene& scene) {
    std::vector<std::string> labels{kAmbientLabel};
    for (const LightSlot& light : scene.lights)
        if (!light->name.empty()) labels.push_back(light->name);
    for (std::uint32_t i = 0; i < scene.objects.size(); ++i) labels.push_back(scene.labelOf(i));
    for (const MediumSlot& medium : scene.media) labels.push_back(medium->name);
    std::sort(labels.begin(), labels.end());
    labels.erase(std::unique(labels.begin(), labels.end()), labels.end());
    return labels;
}

lpe::Event lpeEventOf(const Scene& scene, const PathEvent& e) {
    lpe::Event event{e.type, e.scatter, {}};
    if (e.subject == Subject::Ambient) event.label = kAmbientLabel;
    else if (e.subject == Subject::SceneLight) event.label = scene.lights[e.index]->name;
    else if (e.subject == Subject::Object) event.label = scene.labelOf(e.index);
    else if (e.subject == Subject::Medium) event.label = scene.media[e.index]->name;
    return event;
}

std::string subjectName(const Scene& scene, const PathEvent& event) {
    switch (event.subject) {
        case Subject::None:
            if (event.type == lpe::EventType::Background) return "background";
            if (event.type == lpe::EventType::Camera) return "camera";
            // A scattering event with no surface: radiosity's bounce between the surface seen and
            // the light, a sum over every patch (docs/integrators.md).
            return "every patch";
        case Subject::Ambient: return kAmbientLabel;
        case Subject::SceneLight: {
            const std::string& name = scene.lights[event.index]->name;
            return name.empty() ? "light #" + std::to_string(event.index) : name;
        }
        case Subject::Medium: return scene.media[event.index]->name;
        case Subject::Object: {
            const std::string& name = scene.objects[event.index].name;
            return name.empty() ? "object #" + std::to_string(event.index) + " (" + scene.labelOf(event.index) + ")" : name;
        }
    }
    return {};
}

}  // namespace lightpath
