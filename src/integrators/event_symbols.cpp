#include "integrators/event_symbols.h"

#include <algorithm>

namespace lightpath {

EventSymbols::EventSymbols(const Scene& scene, const lpe::Automaton& automaton)
    : automaton_(automaton), ambient_(automaton.labelClass(kAmbientLabel)) {
    for (const PointLight& light : scene.lights) lights_.push_back(automaton.labelClass(light.name));
    for (std::uint32_t i = 0; i < scene.objects.size(); ++i) objects_.push_back(automaton.labelClass(scene.labelOf(i)));
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
