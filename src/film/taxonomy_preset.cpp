// The `taxonomy` preset: the lecture's four methods (Magnusson), overlapping on purpose.
#include "film/aov_presets.h"

namespace lightpath {

const std::vector<lpe::NamedExpression>& taxonomySet() {
    static const std::vector<lpe::NamedExpression> set = {
        {"raycasting", "E(D|G)L"},
        {"raytracing", "E[S*](D|G)L"},
        {"radiosity", "ED*L"},
        {"pathtracing", "E(D|G|S)*L"},
    };
    return set;
}

}  // namespace lightpath

LIGHTPATH_REGISTER_PRESET(lightpath::AovPreset{
    {"preset", "taxonomy", "the lecture's four methods, overlapping", {}, "E.*L"},
    1, [](const lightpath::Scene*) { return lightpath::taxonomySet(); }})
