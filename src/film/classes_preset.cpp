// The `classes` preset: the default AOV partition of docs/design.md.
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

}  // namespace lightpath

LIGHTPATH_REGISTER_PRESET(lightpath::AovPreset{
    {"preset", "classes", "the partition of docs/design.md: raycast, raytrace, mirror, emission, indirect", {},
     "E(D|G|S)*L"},
    0, [](const lightpath::Scene*) { return lightpath::classesSet(); }})
