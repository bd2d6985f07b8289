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
        // Light that scattered in a medium at least once (issue #24). A volume scattering has no
        // surface scattering type (V is not D, G or S), so the five above hold only paths without
        // V and this one holds the rest: still a partition, of E.*L with media.
        {"volume", "E.*V.*L"},
    };
    return set;
}

}  // namespace lightpath

LIGHTPATH_REGISTER_PRESET(lightpath::AovPreset{
    {"preset", "classes", "the partition of docs/design.md: raycast, raytrace, mirror, emission, indirect, volume", {},
     "E(<[RT][DGS]>|<Vx>)*L"},
    0, [](const lightpath::Scene*) { return lightpath::classesSet(); }})
