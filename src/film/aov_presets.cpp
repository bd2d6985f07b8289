#include "film/aov_presets.h"

namespace lightpath {

std::vector<const AovPreset*> aovPresets() { return AovPresetRegistry::instance().entries(); }

const AovPreset* findAovPreset(std::string_view name) { return AovPresetRegistry::instance().find(name); }

std::vector<std::string> aovPresetNames(bool withSceneOnly) {
    std::vector<std::string> names;
    for (const AovPreset* preset : aovPresets())
        if (withSceneOnly || !preset->fromScene) names.emplace_back(preset->schema.name);
    return names;
}

std::string aovPresetHelp() {
    std::string help;
    for (const AovPreset* preset : aovPresets())
        help += std::string(preset->schema.name) + " (" + std::string(preset->schema.summary) + "), ";
    return help + "or none";
}

}  // namespace lightpath
