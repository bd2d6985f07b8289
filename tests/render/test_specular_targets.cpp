// The targets light walks are aimed at (lights/specular_targets.h): every bounded mirror or glass
// object and nothing else, bounded by its own sphere or its box's, and at most the largest
// kMaxSpecularTargets of them.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include "scene/scene_loader.h"
#include "lights/specular_targets.h"

using lightpath::SpecularTarget;

namespace {

std::vector<SpecularTarget> targetsOf(const std::string& text) {
    const auto path = std::filesystem::temp_directory_path() /
                      ("lightpath-targets-" + std::to_string(std::random_device{}()) + ".toml");
    std::ofstream(path) << text;
    const lightpath::Scene scene = lightpath::loadScene(path);
    std::filesystem::remove(path);
    return lightpath::specularTargets(scene);
}

const std::string kMaterials = R"(
[camera]
eye = [0, 0, 10]
look_at = [0, 0, 0]
[materials.mirror]
kr = 0.9
[materials.glass]
kt = 0.9
ior = 1.5
[materials.matte]
kd = 0.5
[[lights]]
position = [0, 5, 0]
intensity = 1
)";

}  // namespace

TEST_CASE("specular targets: mirror and glass spheres and meshes, not matte objects or planes") {
    const auto targets = targetsOf(kMaterials + R"(
[[spheres]]
center = [1, 2, 3]
radius = 0.5
material = "mirror"
[[spheres]]
center = [4, 0, 0]
radius = 2
material = "matte"
[[planes]]
point = [0, -1, 0]
normal = [0, 1, 0]
material = "mirror"
[[triangles]]
vertices = [[0, 0, 0], [2, 0, 0], [0, 2, 0]]
material = "glass"
)");
    REQUIRE(targets.size() == 2);
    CHECK(targets[0].centre == lightpath::Vec3{1, 2, 3});
    CHECK(targets[0].radius == 0.5f);
    // The triangle's box [0, 2] x [0, 2] x [0, 0]: its centre, half its diagonal.
    CHECK(targets[1].centre == lightpath::Vec3{1, 1, 0});
    CHECK(targets[1].radius == doctest::Approx(std::sqrt(2.0f)));
}

TEST_CASE("specular targets: of many, the largest kMaxSpecularTargets, the first among equals") {
    std::string text = kMaterials;
    const int count = int(lightpath::kMaxSpecularTargets) + 4;
    for (int i = 0; i < count; ++i) {
        // Radii 0.10, 0.11, ... with two of the smallest kept size repeated: scene order decides.
        const float radius = i == count - 1 ? 0.13f : 0.1f + 0.01f * float(i);
        text += "[[spheres]]\ncenter = [" + std::to_string(3 * i) + ", 0, 0]\nradius = " + std::to_string(radius) +
                "\nmaterial = \"" + (i % 2 ? "glass" : "mirror") + "\"\n";
    }
    const auto targets = targetsOf(text);
    REQUIRE(targets.size() == lightpath::kMaxSpecularTargets);
    CHECK(targets.front().radius == doctest::Approx(0.1f + 0.01f * float(count - 2)));
    // Radii 0.14 .. 0.28 are 15 of them; the 16th is the first 0.13 (index 3), not the last sphere's.
    CHECK(targets.back().radius == doctest::Approx(0.13f));
    CHECK(targets.back().centre.x == 9.0f);
}
