#include "serve/scene_report.h"

#include <algorithm>
#include <cctype>
#include <limits>

#include "film/aov_presets.h"
#include "integrators/registry.h"
#include "integrators/event_symbols.h"
#include "lpe/analysis.h"
#include "scene/emission.h"
#include "serve/session.h"
#include "serve/settings.h"

namespace lightpath::serve {
namespace {

using nlohmann::json;

json point(const Vec3& p) { return json::array({p.x, p.y, p.z}); }
bool isBlackRgb(const Rgb& c) { return c.r <= 0.0f && c.g <= 0.0f && c.b <= 0.0f; }

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

std::vector<lpe::NamedExpression> lightGroups(const Scene& scene) {
    std::vector<lpe::NamedExpression> set;
    // One group per light and per emitting surface, in OSL's spelling <L.'key'>, <O.'lamp'>.
    const auto add = [&](char type, const std::string& label) {
        if (label.find('\'') != std::string::npos) return;  // cannot be quoted in an LPE
        set.push_back({identifierFor(label, set), std::string("E.*<") + type + ".'" + label + "'>"});
    };
    if (!isBlackRgb(scene.ambient)) add('L', kAmbientLabel);
    for (const LightSlot& light : scene.lights)
        if (!light->name.empty()) add('L', light->name);
    // An emitting surface ends its paths with the event the scene says: L for a [[lights]] quad or
    // sphere, O for another (scene/emission.h, which the light set and the command line read).
    std::vector<std::pair<std::string, char>> emissive;
    for (std::uint32_t i = 0; i < scene.objects.size(); ++i)
        if (const auto type = emissionEventOf(scene, i)) emissive.emplace_back(scene.labelOf(i), lpe::letter(*type));
    std::sort(emissive.begin(), emissive.end());
    emissive.erase(std::unique(emissive.begin(), emissive.end()), emissive.end());
    for (const auto& [label, type] : emissive) add(type, label);
    if (!isBlackRgb(scene.background)) set.push_back({identifierFor("background", set), "E.*B"});
    return set;
}

// Light by the number of scattering events between the eye and the emitter: a partition of E.*L.
}  // namespace

std::vector<std::pair<std::string, std::vector<lpe::NamedExpression>>> presets(const Scene& scene) {
    std::vector<std::pair<std::string, std::vector<lpe::NamedExpression>>> sets;
    for (const AovPreset& preset : aovPresets()) sets.emplace_back(preset.name, preset.expressions());
    sets.emplace_back("lights", lightGroups(scene));
    return sets;
}

json describeScene(const Scene& scene, const std::string& scenePath) {
    constexpr float kInf = std::numeric_limits<float>::infinity();
    std::vector<Vec3> low(scene.objects.size(), Vec3{kInf}), high(scene.objects.size(), Vec3{-kInf});
    const auto grow = [&](std::uint32_t object, const Vec3& a, const Vec3& b) {
        low[object] = glm::min(low[object], a);
        high[object] = glm::max(high[object], b);
    };
    for (const Sphere& s : scene.spheres) grow(s.object, s.center - Vec3{s.radius}, s.center + Vec3{s.radius});
    for (const ShapeRecord& s : scene.shapes) {
        const Bounds box = s.ops->bounds(s);
        grow(s.object, box.lo, box.hi);
    }
    for (const Triangle& t : scene.triangles) {
        grow(t.object, glm::min(t.a, glm::min(t.b, t.c)), glm::max(t.a, glm::max(t.b, t.c)));
    }
    json objects = json::array();
    for (std::uint32_t i = 0; i < scene.objects.size(); ++i) {
        json object = {{"name", scene.objects[i].name}, {"label", scene.labelOf(i)},
                       {"emissive", emissionEventOf(scene, i).has_value()}};
        if (low[i].x <= high[i].x) object["bounds"] = {point(low[i]), point(high[i])};
        objects.push_back(object);
    }
    for (const Plane& p : scene.planes)
        objects[p.object]["plane"] = {{"point", point(p.point)}, {"normal", point(p.normal)}};
    json lights = json::array();
    for (const LightSlot& light : scene.lights) lights.push_back({{"name", light->name}, {"position", point(light->position())}});
    json sets = json::array();
    for (const auto& [name, set] : presets(scene)) {
        json list = json::array();
        for (const auto& e : set) list.push_back({{"name", e.name}, {"expression", e.expression}});
        sets.push_back({{"name", name}, {"lpes", list}});
    }
    return {{"scene", scenePath},
            {"camera",
             {{"eye", point(scene.camera.eye)},
              {"lookAt", point(scene.camera.lookAt)},
              {"width", scene.camera.width},
              {"height", scene.camera.height}}},
            {"objects", objects},
            {"lights", lights},
            {"integrators", integratorNames()},
            {"presets", sets},
            {"limits", {{"side", kMaxSide}, {"spp", kMaxSamples}, {"lpes", kMaxExpressions}, {"samplesPerPass", kSamplesPerPass}}}};
}

}  // namespace lightpath::serve
