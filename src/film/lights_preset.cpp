// The `lights` preset: light groups, one AOV per light and emitting surface of the scene, in
// OSL's spelling <L.'key'>, <O.'lamp'>, and the background. Made from the scene, so `lpe`, which has
// none, does not offer it.
#include <algorithm>
#include <cctype>

#include "film/aov_presets.h"
#include "scene/ambient_label.h"
#include "lpe/event.h"
#include "scene/emission.h"

namespace lightpath {
namespace {

// An AOV name for a label: AOV names are identifiers, labels may be any text.
std::string identifierFor(const std::string& label, const std::vector<lpe::NamedExpression>& taken) {
    std::string name;
    for (const char c : label) name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
    if (name.empty() || std::isdigit(static_cast<unsigned char>(name[0]))) name = "l_" + name;
    const auto used = [&](const std::string& n) {
        return n == "beauty" || n == "rest" ||
               std::any_of(taken.begin(), taken.end(), [&](const auto& e) { return e.name == n; });
    };
    std::string unique = name;
    for (int i = 2; used(unique); ++i) unique = name + "_" + std::to_string(i);
    return unique;
}

bool emitsNothing(const Rgb& c) { return c.r <= 0.0f && c.g <= 0.0f && c.b <= 0.0f; }

std::vector<lpe::NamedExpression> lightGroups(const Scene* scene) {
    std::vector<lpe::NamedExpression> set;
    if (scene == nullptr) return set;
    const auto add = [&](char type, const std::string& label) {
        if (label.find('\'') != std::string::npos) return;  // cannot be quoted in an LPE
        set.push_back({identifierFor(label, set), std::string("E.*<") + type + ".'" + label + "'>"});
    };
    if (!emitsNothing(scene->ambient)) add('L', kAmbientLabel);
    for (const LightSlot& light : scene->lights)
        if (!light->name.empty()) add('L', light->name);
    // An emitting surface ends its paths with the event the scene says: L for a [[lights]] quad or
    // sphere, O for another (scene/emission.h, which the light set and the command line read).
    std::vector<std::pair<std::string, char>> emissive;
    for (std::uint32_t i = 0; i < scene->objects.size(); ++i)
        if (const auto type = emissionEventOf(*scene, i)) emissive.emplace_back(scene->labelOf(i), lpe::letter(*type));
    std::sort(emissive.begin(), emissive.end());
    emissive.erase(std::unique(emissive.begin(), emissive.end()), emissive.end());
    for (const auto& [label, type] : emissive) add(type, label);
    if (!emitsNothing(scene->background)) set.push_back({identifierFor("background", set), "E.*B"});
    return set;
}

}  // namespace
}  // namespace lightpath

LIGHTPATH_REGISTER_PRESET(lightpath::AovPreset{
    {"preset", "lights", "light groups: one per named light, emitting surface, the ambient term and the background", {},
     "E.*L"},
    3, lightpath::lightGroups, true})
