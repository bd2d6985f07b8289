#include "cases.h"

#include "accel/scene_geometry.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "scene/light_type.h"
#include "scene/shape_type.h"
#include "materials/material_type.h"
#include "scene/scene_loader.h"
#include "schema/format.h"
#include "uniform_real.h"

namespace lightpath::conformance {
namespace {

// Cases drawn for every registered type, on top of the hand-picked ones below: a type the kit has
// never heard of is checked as soon as it registers.
constexpr int kDrawsPerMaterialType = 4;
constexpr int kDrawsPerLightType = 2;
constexpr int kDrawsPerShapeType = 3;
constexpr int kTriesPerDraw = 20;  // draws a type refuses as a combination (values.fail) are redrawn

using Value = std::variant<double, Vec3, bool, std::array<Vec3, 3>>;
struct Setting {
    std::string_view key;
    Value value;
};

std::string describe(const Value& value) {
    if (const double* x = std::get_if<double>(&value)) return formatNumber(*x);
    if (const Vec3* v = std::get_if<Vec3>(&value)) return formatVec3(*v);
    if (const auto* points = std::get_if<std::array<Vec3, 3>>(&value))
        return "[" + formatVec3((*points)[0]) + ", " + formatVec3((*points)[1]) + ", " + formatVec3((*points)[2]) + "]";
    return std::get<bool>(value) ? "true" : "false";
}

void apply(ParameterValues& values, const Setting& setting) {
    std::visit([&](const auto& v) { values.set(setting.key, v); }, setting.value);
}

// A seed from the type's name (FNV-1a): the same draws on every machine and in every run.
std::uint32_t seedOf(std::string_view name) {
    std::uint32_t hash = 2166136261u;
    for (const char c : name) hash = (hash ^ static_cast<unsigned char>(c)) * 16777619u;
    return hash;
}

// A value within the parameter's range, from what a lecture scene uses where the range is
// open-ended: colours (reflectances, radiances) in [0, 1], numbers (and each axis of a per-axis
// value) up to four times their default (at least 2 above the lower bound), points and vectors
// within 1 of the origin. Names and texts keep their defaults.
std::optional<Value> draw(const Parameter& p, std::mt19937& rng) {
    const auto within = [&](double low, double high, bool lowExclusive) {
        const double from = std::isfinite(p.range.low) ? std::max(low, p.range.low) : low;
        const double to = std::isfinite(p.range.high) ? std::min(high, p.range.high) : high;
        double x = test::UniformReal<double>(from, to)(rng);
        if (lowExclusive && x <= from) x = from + 0.01 * (to - from);
        return x;
    };
    switch (p.type) {
        case ParameterType::Colour: {
            Vec3 c;
            for (int i = 0; i < 3; ++i) c[i] = float(within(0.0, 1.0, p.range.lowExclusive));
            return c;
        }
        case ParameterType::Number:
        case ParameterType::Integer:
        case ParameterType::PerAxis: {
            const double low = std::isfinite(p.range.low) ? p.range.low : -2.0;
            const double fallback = p.defaultText.empty() ? 0.0 : std::stod(std::string(p.defaultText));
            const auto number = [&] { return within(low, std::max(4.0 * fallback, low + 2.0), p.range.lowExclusive); };
            if (p.type == ParameterType::PerAxis) return Vec3(float(number()), float(number()), float(number()));
            const double x = number();
            if (p.type == ParameterType::Integer) return double(std::lround(x));
            return x;
        }
        case ParameterType::Boolean: return std::bernoulli_distribution(0.5)(rng);
        case ParameterType::Point:
        case ParameterType::Vector: {
            Vec3 v;
            do {
                for (int i = 0; i < 3; ++i) v[i] = float(within(-1.0, 1.0, p.range.lowExclusive));
            } while (p.type == ParameterType::Vector && glm::length(v) < 0.1f);
            return v;
        }
        case ParameterType::ThreePoints: {
            std::array<Vec3, 3> points;
            for (Vec3& point : points)
                for (int i = 0; i < 3; ++i) point[i] = float(within(-1.0, 1.0, p.range.lowExclusive));
            return points;
        }
        case ParameterType::Name:
        case ParameterType::Text:
        case ParameterType::NumberOrTexture: return std::nullopt;  // a surface's coverage (alpha) is no Bsdf's business
    }
    return std::nullopt;
}

std::vector<Setting> drawSettings(const TypeSchema& schema, std::mt19937& rng) {
    std::vector<Setting> settings;
    for (const Parameter& p : schema.parameters)
        if (auto value = draw(p, rng)) settings.push_back({p.name, *value});
    return settings;
}

std::string nameOf(std::string_view type, const std::vector<Setting>& settings) {
    std::string name = std::string(type) + ":";
    for (const Setting& s : settings) name += " " + std::string(s.key) + " = " + describe(s.value) + ",";
    if (!settings.empty()) name.pop_back();
    return name;
}

// The case of `type` with `settings` applied to its defaults; nothing when the type refuses them.
std::optional<MaterialCase> materialCase(const MaterialType& type, const std::vector<Setting>& settings) {
    ParameterValues values(type.schema);
    try {
        for (const Setting& s : settings) apply(values, s);
        return MaterialCase{nameOf(type.schema.name, settings), type.make(values), materialClaims(type, values)};
    } catch (const std::exception&) {  // SchemaError, or the type's own refusal of the combination
        return std::nullopt;
    }
}

MaterialCase handPicked(std::string_view typeName, const std::vector<Setting>& settings) {
    const MaterialType* type = MaterialRegistry::instance().find(typeName);
    if (!type) throw std::logic_error("conformance: no material type \"" + std::string(typeName) + "\"");
    std::optional<MaterialCase> c = materialCase(*type, settings);
    if (!c) throw std::logic_error("conformance: " + nameOf(typeName, settings) + " is refused");
    return std::move(*c);
}

// The part of a light scene every case shares: a camera (the loader requires one), nothing else.
constexpr const char* kCamera = R"(
[camera]
eye = [0, 0, 10]
look_at = [0, 0, 0]
resolution = [8, 8]
)";

LightCase lightCase(std::string name, const std::string& toml) {
    return {std::move(name), loadSceneFromText(std::string(kCamera) + toml, "conformance-light.toml")};
}

// One [[lights]] declaration of `type` with `settings`, as a scene file writes it.
std::string lightDeclaration(std::string_view type, const std::vector<Setting>& settings) {
    std::string toml = "[[lights]]\ntype = \"" + std::string(type) + "\"\n";
    for (const Setting& s : settings) toml += std::string(s.key) + " = " + describe(s.value) + "\n";
    return toml;
}

}  // namespace

MaterialClaims materialClaims(const MaterialType& type, const ParameterValues& values) {
    MaterialClaims claims;
    claims.reciprocal = type.promises.reciprocal;
    claims.conservesEnergy = type.promises.conservesEnergy && type.promises.conservesEnergy(values);
    claims.events = std::string(type.schema.events);
    return claims;
}

void forEachMaterialCase(const std::function<void(const MaterialCase&)>& visit) {
    // Hand-picked: the lecture's materials (matte, highlights of every width, mirror, glass,
    // Fresnel glass, a diamond-like index), and glTF metallic-roughness materials from a mirror to the roughest.
    using V = Vec3;
    visit(handPicked("phong", {{"kd", V{0.8f}}}));
    visit(handPicked("phong", {{"ks", V{0.9f}}, {"n", 1.0}}));
    visit(handPicked("phong", {{"ks", V{0.5f}}, {"n", 60.0}}));
    visit(handPicked("phong", {{"kd", V{0.7f, 0.2f, 0.1f}}, {"ks", V{0.1f, 0.1f, 0.6f}}, {"n", 5.0}}));
    visit(handPicked("phong", {{"kd", V{0.3f}}, {"kr", V{0.5f}}}));
    visit(handPicked("phong", {{"kt", V{0.9f}}, {"kr", V{0.1f}}, {"ior", 1.5}}));
    visit(handPicked("phong", {{"kt", V{1.0f}}, {"ior", 1.33}, {"fresnel", true}}));
    visit(handPicked("phong", {{"kd", V{0.2f}}, {"ks", V{0.2f}}, {"n", 30.0}, {"kt", V{0.5f}}, {"ior", 2.4}, {"fresnel", true}}));
    visit(handPicked("modified-phong", {{"kd", V{0.9f}}}));
    visit(handPicked("modified-phong", {{"ks", V{0.95f}}, {"n", 1.0}}));
    visit(handPicked("modified-phong", {{"kd", V{0.5f, 0.2f, 0.0f}}, {"ks", V{0.5f, 0.3f, 0.8f}}, {"n", 20.0}}));
    visit(handPicked("modified-phong", {{"kd", V{0.1f}}, {"ks", V{0.8f}}, {"n", 200.0}}));
    visit(handPicked("microfacet", {{"base_color", V{1.0f}}, {"metallic", 0.0}, {"roughness", 0.0}}));
    visit(handPicked("microfacet", {{"base_color", V{0.95f, 0.64f, 0.54f}}, {"roughness", 0.3}}));
    visit(handPicked("microfacet", {{"base_color", V{0.8f, 0.3f, 0.2f}}, {"metallic", 0.0}, {"roughness", 1.0}}));
    visit(handPicked("conductor", {{"roughness", 0.0}}));
    visit(handPicked("conductor", {{"eta", V{0.155f, 0.117f, 0.138f}}, {"k", V{4.828f, 3.122f, 2.147f}}, {"roughness", 0.3}}));
    visit(handPicked("conductor", {{"eta", V{2.0f}}, {"k", V{0.0f}}, {"roughness", 1.0}}));
    visit(handPicked("dielectric", {{"roughness", 0.0}}));
    visit(handPicked("dielectric", {{"ior", 1.33}, {"roughness", 0.2}, {"tint", V{0.9f, 0.95f, 1.0f}}}));
    visit(handPicked("dielectric", {{"ior", 2.4}, {"roughness", 1.0}}));

    // Drawn: every registered type, its defaults and kDrawsPerMaterialType sets within its schema.
    for (const MaterialType* type : MaterialRegistry::instance().entries()) {
        visit(*materialCase(*type, {}));
        std::mt19937 rng(seedOf(type->schema.name));
        for (int d = 0; d < kDrawsPerMaterialType; ++d) {
            std::optional<MaterialCase> c;
            for (int t = 0; t < kTriesPerDraw && !c; ++t) c = materialCase(*type, drawSettings(type->schema, rng));
            if (!c) throw std::runtime_error("conformance: material type \"" + std::string(type->schema.name) +
                                             "\" refused " + std::to_string(kTriesPerDraw) + " draws within its schema");
            visit(*c);
        }
    }
}

void forEachLightCase(const std::function<void(const LightCase&)>& visit) {
    visit(lightCase("point: intensity 2, no attenuation", R"(
[[lights]]
type = "point"
name = "bulb"
position = [0, 2, 0]
intensity = [2, 1, 0.5]
)"));
    visit(lightCase("point: attenuation [0, 0, 1] (inverse square)", R"(
[[lights]]
name = "bulb"
position = [1, 1, 1]
intensity = 5
attenuation = [0, 0, 1]
)"));
    visit(lightCase("quad: 2 x 1, radiance [4, 2, 1]", R"(
[[lights]]
type = "quad"
name = "panel"
corner = [-1, 2, -0.5]
edge1 = [2, 0, 0]
edge2 = [0, 0, 1]
radiance = [4, 2, 1]
)"));
    visit(lightCase("sphere: radius 0.5, radiance 3", R"(
[[lights]]
type = "sphere"
name = "globe"
center = [0, 3, 0]
radius = 0.5
radiance = 3
)"));
    visit(lightCase("emissive object: a sphere whose material emits 2 (O)", R"(
[materials.lamp]
emission = 2
[[spheres]]
name = "lamp"
center = [0, 0, -3]
radius = 1
material = "lamp"
)"));
    visit(lightCase("emissive object: a quad whose material emits 2 from both sides (two_sided_emission)", R"(
[materials.lamp]
emission = 2
two_sided_emission = true
[[triangles]]
name = "panel"
material = "lamp"
vertices = [[-1, 2, -1], [1, 2, -1], [1, 2, 0]]
[[triangles]]
name = "panel"
material = "lamp"
vertices = [[-1, 2, -1], [1, 2, 0], [-1, 2, 0]]
)"));

    // Drawn: every registered type, kDrawsPerLightType declarations within its schema.
    for (const LightType* type : LightRegistry::instance().entries()) {
        std::mt19937 rng(seedOf(type->schema.name));
        for (int d = 0; d < kDrawsPerLightType; ++d) {
            std::optional<LightCase> c;
            for (int t = 0; t < kTriesPerDraw && !c; ++t) {
                const std::vector<Setting> settings = drawSettings(type->schema, rng);
                try {
                    c = lightCase(nameOf(type->schema.name, settings), lightDeclaration(type->schema.name, settings));
                } catch (const SceneError&) {  // a combination the type refuses
                }
            }
            if (!c) throw std::runtime_error("conformance: light type \"" + std::string(type->schema.name) +
                                             "\" refused " + std::to_string(kTriesPerDraw) + " draws within its schema");
            visit(*c);
        }
    }
    // Every registered shape kind as an emitting object.
    // An unbounded kind (a plane) is no light: infinite area, never sampled.
    forEachShapeCase([&](const ShapeCase& c) {
        if (c.shape().ops->bounded) visit(LightCase{c.name, c.scene});
    });
}

void forEachShapeCase(const std::function<void(const ShapeCase&)>& visit) {
    for (const ShapeType* type : ShapeRegistry::instance().entries()) {
        // Triangles and meshes are no records of a ShapeOps table: tests/accel checks triangles,
        // and the quad light's light cases check them as emitters.
        if (type->storage != ShapeStorage::records) continue;
        std::mt19937 rng(seedOf(type->schema.name));
        for (int d = 0; d < kDrawsPerShapeType; ++d) {
            std::optional<ShapeCase> c;
            for (int t = 0; t < kTriesPerDraw && !c; ++t) {
                const std::vector<Setting> settings = drawSettings(type->schema, rng);
                std::string toml = "[materials.lamp]\nemission = 2\n[[" + std::string(type->section) +
                                   "]]\nmaterial = \"lamp\"\n";
                for (const Setting& s : settings) toml += std::string(s.key) + " = " + describe(s.value) + "\n";
                try {
                    Scene scene = loadSceneFromText(std::string(kCamera) + toml, "conformance-shape.toml");
                    // The record as the renderer's geometry holds it: spheres and planes come to
                    // SceneGeometry as values and become records of its one table there.
                    const SceneGeometry geometry(scene.spheres, scene.planes, {}, {}, Accelerator::BruteForce, {}, 0,
                                                 scene.shapes);
                    if (geometry.shapes().size() == 1) {
                        const ShapeRecord record = geometry.shapes().front();
                        c = ShapeCase{nameOf(type->schema.name, settings), std::move(scene), record};
                    }
                } catch (const SceneError&) {  // a combination the type refuses
                }
            }
            if (!c) throw std::runtime_error("conformance: shape type \"" + std::string(type->schema.name) +
                                             "\" refused " + std::to_string(kTriesPerDraw) + " draws within its schema");
            visit(*c);
        }
    }
}

}  // namespace lightpath::conformance

namespace lightpath::conformance {
namespace {

constexpr const char* kStage = R"(
[camera]
eye = [0, 1.2, 6]
look_at = [0, 0.6, 0]
fov = 45
resolution = [24, 18]

[materials.floor]
kd = [0.6, 0.5, 0.4]
ks = 0.2
n = 10
[materials.wall]
type = "modified-phong"
kd = 0.5
ks = 0.3
n = 8
[materials.chrome]
kr = 0.9
[materials.glass]
kt = 1
ior = 1.5
fresnel = true
[materials.lamp]
emission = [3, 3, 2]

[[planes]]
name = "floor"
point = [0, 0, 0]
normal = [0, 1, 0]
material = "floor"
[[planes]]
name = "back"
point = [0, 0, -3]
normal = [0, 0, 1]
material = "wall"
[[spheres]]
name = "bulb"
center = [0.3, 2.3, -2.2]
radius = 0.5
material = "lamp"
)";

// A mirror ball and a glass ball on the floor.
constexpr const char* kSpecularBalls = R"(
[[spheres]]
name = "ball"
center = [-1.3, 0.6, 0]
radius = 0.6
material = "chrome"
[[spheres]]
name = "lens"
center = [1.2, 0.6, 0.5]
radius = 0.6
material = "glass"
)";

}  // namespace

Scene integratorScene() {
    return loadSceneFromText(std::string(kStage) + kSpecularBalls + R"(
[[lights]]
name = "key"
position = [0.3, 1.5, 6]
intensity = 8
attenuation = [0, 0, 1]
[world]
ambient = 0.05
background = [0.1, 0.15, 0.3]
[[lights]]
type = "quad"
name = "panel"
corner = [-1, 3, -1]
edge1 = [2, 0, 0]
edge2 = [0, 0, 1]
radiance = 2
)", "conformance-integrators.toml");
}

double agreementAllowance(const IntegratorInfo& integrator) {
    // Radiosity's patches hold one radiosity each: its images differ from the path tracer's by
    // the mesh's error, within 5% at the default mesh (tests/render/test_radiosity.cpp).
    return std::string_view(integrator.name) == "radiosity" ? 0.05 : 0.0;
}

Scene agreementScene() {
    return loadSceneFromText(std::string(kStage) + R"(
[[lights]]
type = "sphere"
name = "key"
center = [0, 1.2, 6.5]
radius = 0.3
radiance = 40
)", "conformance-agreement.toml");
}

}  // namespace lightpath::conformance
