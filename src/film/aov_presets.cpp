#include "film/aov_presets.h"

namespace lightpath {

const std::vector<lpe::NamedExpression>& classesSet() {
    static const std::vector<lpe::NamedExpression> set = {
        {"raycast", "E(D|G)L"},
        {"raytrace", "ES+(D|G)L"},
        {"mirror", "ES+L"},
        {"emission", "EL"},
        {"indirect", "ES*(D|G)(D|G|S)+L"},
    };
    return set;
}

const std::vector<lpe::NamedExpression>& taxonomySet() {
    static const std::vector<lpe::NamedExpression> set = {
        {"raycasting", "E(D|G)L"},
        {"raytracing", "E[S*](D|G)L"},
        {"radiosity", "ED*L"},
        {"pathtracing", "E(D|G|S)*L"},
    };
    return set;
}

const std::vector<AovPreset>& aovPresets() {
    static const std::vector<AovPreset> presets = {
        {"classes", classesSet, "E(D|G|S)*L"},
        {"taxonomy", taxonomySet, "E.*L"},
    };
    return presets;
}

std::optional<AovPreset> findAovPreset(std::string_view name) {
    for (const AovPreset& preset : aovPresets())
        if (name == preset.name) return preset;
    return std::nullopt;
}

}  // namespace lightpath
