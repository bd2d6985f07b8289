// OBJ/MTL meshes in scenes: the shipped Cornell boxes load with the triangle and material counts
// their files imply (counted here from the text, not by tinyobjloader), and a missing file is a
// clear error naming it.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "scene/scene_loader.h"

namespace lightpath {
namespace {

const std::filesystem::path kMeshes = LIGHTPATH_SOURCE_DIR "/scenes/meshes/cornell-box";

struct Counts {
    std::size_t triangles = 0;
    std::set<std::string> materials;  // names used by usemtl
};

// Every `f` line with k corners is k - 2 triangles once fanned.
Counts countObj(const std::filesystem::path& file) {
    Counts counts;
    std::ifstream in(file);
    for (std::string line; std::getline(in, line);) {
        std::istringstream words(line);
        std::string keyword;
        words >> keyword;
        if (keyword == "f") {
            std::size_t corners = 0;
            for (std::string corner; words >> corner;) ++corners;
            counts.triangles += corners - 2;
        } else if (keyword == "usemtl") {
            std::string name;
            words >> name;
            counts.materials.insert(name);
        }
    }
    return counts;
}

// A scene file in a temporary directory holding `body`.
std::filesystem::path writeScene(const std::string& name, const std::string& body) {
    const auto directory = std::filesystem::temp_directory_path() / "lightpath-accel-tests";
    std::filesystem::create_directories(directory);
    const auto path = directory / name;
    std::ofstream(path) << body;
    return path;
}

std::string meshScene(const std::filesystem::path& obj, const std::string& extra = "") {
    return "[[meshes]]\nfile = \"" + obj.generic_string() + "\"\n" + extra;
}

TEST_CASE("the Cornell boxes load with the right triangle and material counts") {
    for (const char* name : {"CornellBox-Original", "CornellBox-Mirror", "CornellBox-Sphere", "CornellBox-Glossy",
                             "CornellBox-Empty-RG", "CornellBox-Empty-CO", "CornellBox-Empty-White",
                             "CornellBox-Empty-Squashed"}) {
        CAPTURE(name);
        const auto obj = kMeshes / (std::string(name) + ".obj");
        const Counts expected = countObj(obj);
        const Scene scene = loadScene(writeScene("count.toml", meshScene(obj)));
        CHECK(scene.triangles.size() == expected.triangles);
        CHECK(scene.materials.size() == expected.materials.size());
        for (const PhongMaterial& m : scene.materials) CHECK(expected.materials.count(m.name) == 1);
    }
    CHECK(countObj(kMeshes / "CornellBox-Original.obj").triangles == 36);
}

TEST_CASE("MTL materials map to the Phong material") {
    const Scene scene = loadScene(LIGHTPATH_SOURCE_DIR "/scenes/cornell-sphere.toml");
    const auto find = [&](const std::string& name) -> const PhongMaterial& {
        for (const PhongMaterial& m : scene.materials)
            if (m.name == name) return m;
        FAIL("no material " << name);
        return scene.materials.front();
    };
    const PhongMaterial& mirror = find("leftSphere");  // illum 5, Ks 0.95
    CHECK(mirror.kr == Rgb(0.95f));
    CHECK(mirror.n == 1000.0f);
    const PhongMaterial& glass = find("rightSphere");  // illum 7, Tf 0.1, Ni 2.5
    CHECK(glass.kt == Rgb(0.1f));
    CHECK(glass.ior == 2.5f);
    CHECK(glass.kr == Rgb(0.3f));
    const PhongMaterial& light = find("light");  // illum 2 with Tf 1: no transmission; Ke 10
    CHECK(light.kt == Rgb(0.0f));
    CHECK(light.emission == Rgb(10.0f));
    const PhongMaterial& wall = find("leftWall");
    CHECK(wall.kd == Rgb(0.63f, 0.065f, 0.05f));
    CHECK(wall.kr == Rgb(0.0f));
    // The sphere meshes have vertex normals: smooth shading.
    CHECK(scene.triangleNormals.size() == scene.triangles.size());
}

TEST_CASE("a mesh is placed by scale, rotate_y and translate, and a TOML material overrides the MTL") {
    const auto obj = kMeshes / "CornellBox-Empty-White.obj";
    const Scene plain = loadScene(writeScene("plain.toml", meshScene(obj)));
    const Scene moved = loadScene(writeScene("moved.toml", "[materials.grey]\nkd = 0.5\n" +
                                                               meshScene(obj, "material = \"grey\"\nscale = 2\n"
                                                                              "rotate_y = 90\ntranslate = [1, 2, 3]\n")));
    REQUIRE(plain.triangles.size() == moved.triangles.size());
    const Vec3 p = plain.triangles[0].a, q = moved.triangles[0].a;
    // (x, y, z) * 2, turned 90 degrees about y: (2z, 2y, -2x), then moved.
    CHECK(q.x == doctest::Approx(2.0f * p.z + 1.0f));
    CHECK(q.y == doctest::Approx(2.0f * p.y + 2.0f));
    CHECK(q.z == doctest::Approx(-2.0f * p.x + 3.0f));
    CHECK(moved.materials.size() == 1);
    CHECK(moved.objects.size() == 1);
    CHECK(moved.labelOf(moved.triangles[0].object) == "grey");
}

TEST_CASE("a missing OBJ or MTL file is an error that names it") {
    const auto missingObj = writeScene("missing-obj.toml", meshScene("no-such-mesh.obj"));
    const std::string expected =
        "meshes[0].file: " + (missingObj.parent_path() / "no-such-mesh.obj").string() + ": cannot open mesh file";
    CHECK_THROWS_WITH_AS(loadScene(missingObj), doctest::Contains(expected.c_str()), SceneError);

    const auto directory = missingObj.parent_path();
    std::ofstream(directory / "lost-library.obj") << "mtllib gone.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl red\nf 1 2 3\n";
    CHECK_THROWS_WITH_AS(loadScene(writeScene("missing-mtl.toml", meshScene(directory / "lost-library.obj"))),
                         doctest::Contains("gone.mtl"), SceneError);

    std::ofstream(directory / "no-material.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    CHECK_THROWS_WITH_AS(loadScene(writeScene("no-material.toml", meshScene(directory / "no-material.obj"))),
                         doctest::Contains("give the mesh a `material`"), SceneError);
}

}  // namespace
}  // namespace lightpath
