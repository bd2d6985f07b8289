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

const std::vector<lpe::NamedExpression>& bouncesSet() {
    static const std::vector<lpe::NamedExpression> set = {
        {"emission", "EL"}, {"bounce1", "E.L"}, {"bounce2", "E..L"}, {"bounce3", "E...L"}, {"bounce4plus", "E.{4,}L"},
    };
    return set;
}

const std::vector<AovPreset>& aovPresets() {
    static const std::vector<AovPreset> presets = {
        {"classes", classesSet, "E(D|G|S)*L"},
        {"taxonomy", taxonomySet, "E.*L"},
        {"bounces", bouncesSet, "E.*L"},
    };
    return presets;
}

std::optional<AovPreset> findAovPreset(std::string_view name) {
    for (const AovPreset& preset : aovPresets())
        if (name == preset.name) return preset;
    return std::nullopt;
}

}  // namespace lightpath
