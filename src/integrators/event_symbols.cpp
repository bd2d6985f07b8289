#include "integrators/event_symbols.h"

#include <algorithm>

namespace lightpath {

EventSymbols::EventSymbols(const Scene& scene, const lpe::Automaton& automaton) {
    using lpe::EventType;
    using lpe::Scatter;
    camera = automaton.symbol(EventType::Camera, Scatter::None, 0);
    background = automaton.symbol(EventType::Background, Scatter::None, 0);
    ambient = automaton.symbol(EventType::Emitter, Scatter::None, automaton.labelClass(kAmbientLabel));
    for (const PointLight& light : scene.lights)
        lights.push_back(automaton.symbol(EventType::Emitter, Scatter::None, automaton.labelClass(light.name)));
    for (std::uint32_t i = 0; i < scene.objects.size(); ++i) {
        const auto label = automaton.labelClass(scene.labelOf(i));
        objects.push_back({automaton.symbol(EventType::Reflection, Scatter::Diffuse, label),
                           automaton.symbol(EventType::Reflection, Scatter::Glossy, label),
                           automaton.symbol(EventType::Reflection, Scatter::Specular, label),
                           automaton.symbol(EventType::Transmission, Scatter::Specular, label),
                           automaton.symbol(EventType::Emitter, Scatter::None, label)});
    }
}

std::vector<std::string> sceneLabels(const Scene& scene) {
    std::vector<std::string> labels{kAmbientLabel};
    for (const PointLight& light : scene.lights)
        if (!light.name.empty()) labels.push_back(light.name);
    for (std::uint32_t i = 0; i < scene.objects.size(); ++i) labels.push_back(scene.labelOf(i));
    std::sort(labels.begin(), labels.end());
    labels.erase(std::unique(labels.begin(), labels.end()), labels.end());
    return labels;
}

}  // namespace lightpath
