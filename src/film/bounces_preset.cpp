// The `bounces` preset: the light by the number of events between the eye and the emitter.
#include "film/aov_presets.h"

namespace lightpath {

const std::vector<lpe::NamedExpression>& bouncesSet() {
    static const std::vector<lpe::NamedExpression> set = {
        {"emission", "EL"}, {"bounce1", "E.L"}, {"bounce2", "E..L"}, {"bounce3", "E...L"}, {"bounce4plus", "E.{4,}L"},
    };
    return set;
}

}  // namespace lightpath

LIGHTPATH_REGISTER_PRESET(lightpath::AovPreset{
    {"preset", "bounces", "by the number of events: emission, bounce1 .. bounce4plus", {}, "E.*L"},
    2, [](const lightpath::Scene*) { return lightpath::bouncesSet(); }})
