#include "serve/scene_report.h"

#include <algorithm>
#include <limits>

#include "film/aov_presets.h"
#include "integrators/registry.h"
#include "lpe/analysis.h"
#include "scene/emission.h"
#include "serve/json_point.h"
#include "serve/session.h"
#include "serve/settings.h"

namespace lightpath::serve {
namespace {

using nlohmann::json;


}  // namespace

// Every preset of the registry (film/aov_presets.h), the light groups made from this scene.
std::vector<std::pair<std::string, std::vector<lpe::NamedExpression>>> presets(const Scene& scene) {
    std::vector<std::pair<std::string, std::vector<lpe::NamedExpression>>> sets;
    for (const AovPreset* preset : aovPresets()) sets.emplace_back(preset->schema.name, preset->expressions(&scene));
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
            {"integratorParameters", integratorParametersJson()},
            {"presets", sets},
            {"limits", {{"side", kMaxSide}, {"spp", kMaxSamples}, {"lpes", kMaxExpressions}, {"samplesPerPass", kSamplesPerPass}}}};
}

}  // namespace lightpath::serve
