#include "cases.h"

#include <string>
#include <string_view>

#include "materials/modified_phong_material.h"
#include "materials/phong_material.h"
#include "scene/scene_loader.h"

namespace lightpath::conformance {
namespace {

MaterialCase phong(std::string parameters, Rgb kd, Rgb ks, float n, Rgb kr = Rgb{0.0f}, Rgb kt = Rgb{0.0f},
                   float ior = 1.5f, bool fresnel = false) {
    PhongMaterial m;
    m.kd = kd;
    m.ks = ks;
    m.n = n;
    m.kr = kr;
    m.kt = kt;
    m.ior = ior;
    m.fresnel = fresnel;
    return {"phong: " + std::move(parameters), MaterialSlot(std::move(m)), materialClaims("phong")};
}

MaterialCase modifiedPhong(std::string parameters, Rgb kd, Rgb ks, float n) {
    ModifiedPhongMaterial m;
    m.kd = kd;
    m.ks = ks;
    m.n = n;
    return {"modified-phong: " + std::move(parameters), MaterialSlot(std::move(m)), materialClaims("modified-phong")};
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

}  // namespace

MaterialClaims materialClaims(std::string_view type) {
    // Lambert's lobe is reciprocal; Szymczak's highlight ks (H.N)^n / pi is f |cos theta_i|, so
    // f itself carries 1/cos theta_i and is not. Phong does not conserve energy by design
    // (docs/design.md).
    if (type == "phong") return {{true, false}, false};
    // Lafortune and Willems 1994: both lobes reciprocal, and kd + ks <= 1 reflects at most 1.
    if (type == "modified-phong") return {{true, true}, true};
    return {};
}

void forEachMaterialCase(const std::function<void(const MaterialCase&)>& visit) {
    visit(phong("kd = 0.8", Rgb{0.8f}, Rgb{0.0f}, 1.0f));
    visit(phong("ks = 0.9, n = 1", Rgb{0.0f}, Rgb{0.9f}, 1.0f));
    visit(phong("ks = 0.5, n = 60", Rgb{0.0f}, Rgb{0.5f}, 60.0f));
    visit(phong("kd = [0.7, 0.2, 0.1], ks = [0.1, 0.1, 0.6], n = 5", {0.7f, 0.2f, 0.1f}, {0.1f, 0.1f, 0.6f}, 5.0f));
    visit(phong("kd = 0.3, kr = 0.5 (a mirror)", Rgb{0.3f}, Rgb{0.0f}, 20.0f, Rgb{0.5f}));
    visit(phong("kt = 0.9, kr = 0.1, ior = 1.5 (glass)", Rgb{0.0f}, Rgb{0.0f}, 20.0f, Rgb{0.1f}, Rgb{0.9f}, 1.5f));
    visit(phong("kt = 1, ior = 1.33, fresnel = true", Rgb{0.0f}, Rgb{0.0f}, 20.0f, Rgb{0.0f}, Rgb{1.0f}, 1.33f, true));
    visit(phong("kd = 0.2, ks = 0.2, n = 30, kt = 0.5, ior = 2.4, fresnel = true", Rgb{0.2f}, Rgb{0.2f}, 30.0f,
                Rgb{0.0f}, Rgb{0.5f}, 2.4f, true));
    visit(modifiedPhong("kd = 0.9", Rgb{0.9f}, Rgb{0.0f}, 20.0f));
    visit(modifiedPhong("ks = 0.95, n = 1", Rgb{0.0f}, Rgb{0.95f}, 1.0f));
    visit(modifiedPhong("kd = [0.5, 0.2, 0], ks = [0.5, 0.3, 0.8], n = 20", {0.5f, 0.2f, 0.0f}, {0.5f, 0.3f, 0.8f}, 20.0f));
    visit(modifiedPhong("kd = 0.1, ks = 0.8, n = 200", Rgb{0.1f}, Rgb{0.8f}, 200.0f));
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
