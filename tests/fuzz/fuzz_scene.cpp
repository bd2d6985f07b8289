// libFuzzer target for the scene loader: any text either loads or is refused with a SceneError
// (scenes/README.md, "Errors"). A scene that loads must be usable as it is: consistent indices,
// valid labels, and a render (tiny, with every integrator) whose layers are finite, non-negative,
// drop no non-finite contribution and sum to the beauty (docs/design.md's promise; the tolerance of
// tests/render/test_aov_sums.cpp), with `rest` zero for the `classes` partition.
//
// Hermetic: the scene "lives" in a directory that does not exist, so no mesh file ever loads.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "film/aov_set.h"
#include "fuzz_support.h"
#include "lights/point_light.h"
#include "materials/conductor_material.h"
#include "materials/dielectric_material.h"
#include "materials/microfacet_material.h"
#include "materials/modified_phong_material.h"
#include "materials/phong_material.h"
#include "render/renderer.h"
#include "scene/scene_loader.h"
#include "film/aov_presets.h"

namespace {

using namespace lightpath;
using fuzz::broken;

const std::filesystem::path kScenePath = "/nonexistent-fuzz/scene.toml";

// Bounds on one execution: the text, and the render (every pixel runs every integrator).
constexpr std::size_t kMaxInput = 8192;
constexpr int kWidth = 4, kHeight = 3;
constexpr int kMaxDepth = 3;

bool finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
bool finiteNonNegative(const Rgb& c) { return finite(c) && c.r >= 0.0f && c.g >= 0.0f && c.b >= 0.0f; }

// The loader's limit (scenes/README.md): |x| <= kMaxMagnitude for every number of the file; points
// it derives (a quad's far corner) may add up to three of them.
bool within(const Vec3& v, double limit = kMaxMagnitude) {
    return glm::all(glm::lessThanEqual(glm::abs(v), Vec3(static_cast<float>(limit))));
}
bool colour(const Rgb& c) { return within(c) && c.r >= 0.0f && c.g >= 0.0f && c.b >= 0.0f; }

bool isName(const std::string& name) {
    const auto nameChar = [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-' || c == '.';
    };
    return !name.empty() && std::all_of(name.begin(), name.end(), nameChar);
}

void checkScene(const Scene& scene) {
    const CameraDescription& c = scene.camera;
    if (!within(c.eye) || !within(c.lookAt) || !within(c.up) || c.eye == c.lookAt)
        broken("camera accepted with a bad eye, look_at or up");
    if (!(c.verticalFovDegrees > 0.0f && c.verticalFovDegrees < 180.0f)) broken("camera fov accepted outside (0, 180)");
    if (!(c.orthographicHeight > 0.0f && c.orthographicHeight <= 1e6f)) broken("camera height accepted outside (0, 1e6]");
    if (c.width < 1 || c.width > 16384 || c.height < 1 || c.height > 16384) broken("resolution accepted outside 1..16384");
    if (!colour(scene.background) || !colour(scene.ambient)) broken("world colour accepted outside 0..1e6");

    for (const MaterialSlot& slot : scene.materials) {
        const std::string& name = slot->name;
        if (!isName(name)) broken("material name \"" + name + "\" is not a label");
        std::vector<Rgb> colours{slot->emission.constant()};
        float exponent = 0.0f, ior = 1.0f;
        if (const auto* m = dynamic_cast<const PhongMaterial*>(&*slot)) {
            colours.insert(colours.end(), {m->ka.constant(), m->kd.constant(), m->ks.constant(), m->kr.constant(), m->kt.constant()});
            exponent = m->n;
            ior = m->ior;
        } else if (const auto* m = dynamic_cast<const ModifiedPhongMaterial*>(&*slot)) {
            colours.insert(colours.end(), {m->kd.constant(), m->ks.constant()});
            exponent = m->n;
        } else if (const auto* m = dynamic_cast<const MicrofacetMaterial*>(&*slot)) {
            // F0 and the diffuse colour mix base_color by metallic: each within the base's bounds
            // (at a shading point, so a textured base colour is what is checked).
            const MicrofacetMaterial::Shading shading = m->shadingAt(SurfaceSide{});
            colours.insert(colours.end(), {shading.f0, shading.diffuse});
            if (!(m->roughness() >= 0.0f && m->roughness() <= 1.0f)) broken("material " + name + " accepted with roughness outside [0, 1]");
        } else if (const auto* m = dynamic_cast<const ConductorMaterial*>(&*slot)) {
            // eta and k: the schema's ranges, eta > 0 (Fresnel divides by it), k >= 0.
            const Rgb eta = m->eta(), k = m->k();
            for (int c = 0; c < 3; ++c)
                if (!(eta[c] > 0.0f && eta[c] <= 10.0f && k[c] >= 0.0f && k[c] <= 20.0f))
                    broken("conductor " + name + " accepted with eta or k outside its range");
            if (!(m->roughness() >= 0.0f && m->roughness() <= 1.0f)) broken("material " + name + " accepted with roughness outside [0, 1]");
        } else if (const auto* m = dynamic_cast<const DielectricMaterial*>(&*slot)) {
            colours.push_back(m->tint().constant());
            ior = m->ior();
            if (!(m->roughness() >= 0.0f && m->roughness() <= 1.0f)) broken("material " + name + " accepted with roughness outside [0, 1]");
        } else if (slot->isInterface()) {
            // An index-matched boundary: no keys, nothing to check but its emission (none).
            if (!slot->emission.black()) broken("interface material " + name + " accepted with an emission");
        } else {
            broken("material " + name + " has a type the fuzzer does not know");
        }
        for (const Rgb& c : colours)
            if (!colour(c)) broken("material " + name + " accepted with a colour outside 0..1e6");
        if (!(exponent >= 0.0f && exponent <= kMaxMagnitude)) broken("material " + name + " accepted with a bad exponent n");
        if (!(ior > 0.0f && ior <= kMaxMagnitude)) broken("material " + name + " accepted with a bad ior");
    }
    for (std::uint32_t i = 0; i < scene.lights.size(); ++i) {
        const SceneLight& any = *scene.lights[i];
        if (!any.name.empty() && (!isName(any.name) || any.name == "ambient")) broken("light name \"" + any.name + "\" accepted");
        const auto* point = dynamic_cast<const PointLight*>(&any);
        if (point == nullptr) {
            // A spot or directional light keeps its description in its own file: what integrators
            // read of it is its source's power and samples.
            const auto source = any.makeSource(i);
            if (!finiteNonNegative(source->power()) || !finiteNonNegative(source->sample(Vec3{0.5f}, Vec2{0.5f}).weight))
                broken("light accepted with a power or sample weight that is not finite");
            continue;
        }
        const PointLight& light = *point;
        if (!within(light.location) || !colour(light.intensity)) broken("light accepted with a bad position or intensity");
        if (!colour(light.attenuation) || light.attenuation == Vec3(0.0f)) broken("light accepted with bad attenuation");
        for (int i = 0; i < 3; ++i)
            if (light.attenuation[i] > 0.0f && light.attenuation[i] < 1e-6f) broken("light accepted with a tiny attenuation coefficient");
    }
    for (std::size_t o = 0; o < scene.objects.size(); ++o) {
        const SceneObject& object = scene.objects[o];
        if (object.material >= scene.materials.size()) broken("object " + std::to_string(o) + " has no material");
        if (!isName(scene.labelOf(static_cast<std::uint32_t>(o)))) broken("object " + std::to_string(o) + " has no label");
    }
    const auto checkObject = [&](std::uint32_t object, const char* shape) {
        if (object >= scene.objects.size()) broken(std::string(shape) + " refers to a missing object");
    };
    for (const Sphere& s : scene.spheres) {
        checkObject(s.object, "sphere");
        if (!within(s.center) || !(s.radius > 0.0f && s.radius <= kMaxMagnitude)) broken("sphere accepted with a bad centre or radius");
    }
    for (const Plane& p : scene.planes) {
        checkObject(p.object, "plane");
        if (!within(p.point) || !finite(p.normal) || std::abs(glm::length(p.normal) - 1.0f) > 1e-5f) broken("plane accepted with a bad point or normal");
    }
    for (const Triangle& t : scene.triangles) {
        checkObject(t.object, "triangle");
        if (!within(t.a, 3 * kMaxMagnitude) || !within(t.b, 3 * kMaxMagnitude) || !within(t.c, 3 * kMaxMagnitude))
            broken("triangle accepted with a corner beyond the limit");
    }
    if (!scene.triangleNormals.empty() && scene.triangleNormals.size() != scene.triangles.size())
        broken("triangle normals do not match the triangles");
    for (const std::string& warning : scene.warnings)
        if (!warning.starts_with(kScenePath.string() + ":")) broken("warning not located: " + warning);
}

// Per pixel and channel: every layer finite and >= 0, AOVs and `rest` summing to the beauty.
void checkFilm(const Film& film, const std::string& what, bool restIsZero) {
    for (int y = 0; y < film.height(); ++y) {
        for (int x = 0; x < film.width(); ++x) {
            Rgb sum{0.0f};
            for (std::size_t l = 0; l < film.layerCount(); ++l) {
                const Rgb& v = film.at(l, x, y);
                if (!finiteNonNegative(v))
                    broken(what + ": layer " + film.layerNames()[l] + " at " + std::to_string(x) + "," + std::to_string(y) +
                           " is " + std::to_string(v.r) + " " + std::to_string(v.g) + " " + std::to_string(v.b));
                if (l > 0) sum += v;
            }
            const Rgb beauty = film.at(0, x, y);
            for (int c = 0; c < 3; ++c) {
                const double error = std::fabs(double(sum[c]) - double(beauty[c]));
                if (error > 1e-5 * std::fabs(double(beauty[c])) + 1e-7)
                    broken(what + ": layers sum to " + std::to_string(sum[c]) + ", the beauty is " + std::to_string(beauty[c]) +
                           " at " + std::to_string(x) + "," + std::to_string(y));
            }
            if (restIsZero && film.at(film.layerCount() - 1, x, y) != Rgb(0.0f))
                broken(what + ": rest is not zero at " + std::to_string(x) + "," + std::to_string(y));
        }
    }
}

void render(const Scene& scene, const AovSet& aovs, const std::string& integrator, bool restIsZero) {
    RenderOptions options;
    options.integrator = integrator;
    options.maxDepth = kMaxDepth;
    options.samplesPerPixel = 1;
    options.threads = 1;
    const RenderResult result = Renderer(scene, aovs, options).render();
    const std::string what = integrator + " with " + aovs.layerNames()[1];
    if (result.stats.rays.nonFinite != 0)
        broken(what + ": " + std::to_string(result.stats.rays.nonFinite) + " non-finite contributions dropped");
    checkFilm(result.film, what, restIsZero);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size > kMaxInput) return 0;
    Scene scene;
    try {
        scene = loadSceneFromText(fuzz::asText(data, size), kScenePath);
    } catch (const SceneError&) {
        return 0;
    }
    checkScene(scene);

    scene.camera.width = kWidth;
    scene.camera.height = kHeight;
    static const AovSet classes(classesSet());
    for (const char* integrator : {"raycast", "whitted", "path"}) render(scene, classes, integrator, true);
    // Labels reach the automaton: the light touching the last object, and rest, sum to the beauty.
    if (!scene.objects.empty()) {
        const std::string label = scene.labelOf(static_cast<std::uint32_t>(scene.objects.size() - 1));
        render(scene, AovSet({{"touched", "E.*'" + label + "'.*"}}), "whitted", false);
    }
    return 0;
}
