// OBJ/MTL meshes in scenes: the shipped Cornell boxes load with the triangle and material counts
// their files imply (counted here from the text, not by tinyobjloader), and a missing file is a
// clear error naming it (a missing material library only a warning).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "materials/phong_material.h"
#include "shapes/obj_loader.h"
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

// The tests' own files live in the build tree (ctest's working area), never in the system's
// temporary directory, which the suite must leave as it found it.
const std::filesystem::path kTestFiles = LIGHTPATH_TEST_OUTPUT_DIR;

// A scene file holding `body`.
std::filesystem::path writeScene(const std::string& name, const std::string& body) {
    const auto directory = kTestFiles;
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
        for (const MaterialSlot& m : scene.materials) CHECK(expected.materials.count(m->name) == 1);
    }
    CHECK(countObj(kMeshes / "CornellBox-Original.obj").triangles == 36);
}

TEST_CASE("MTL materials map to the Phong material") {
    const Scene scene = loadScene(LIGHTPATH_SOURCE_DIR "/scenes/cornell-sphere.toml");
    const auto find = [&](const std::string& name) -> const PhongMaterial& {
        for (const MaterialSlot& m : scene.materials)
            if (m->name == name) return phongOf(m);
        FAIL("no material " << name);
        return phongOf(scene.materials.front());
    };
    const PhongMaterial& mirror = find("leftSphere");  // illum 5, Ks 0.95
    CHECK(mirror.kr.constant() == Rgb(0.95f));
    CHECK(mirror.n == 1000.0f);
    const PhongMaterial& glass = find("rightSphere");  // illum 7, Tf 0.1, Ni 2.5
    CHECK(glass.kt.constant() == Rgb(0.1f));
    CHECK(glass.ior == 2.5f);
    CHECK(glass.kr.constant() == Rgb(0.3f));
    const PhongMaterial& light = find("light");  // illum 2 with Tf 1: no transmission; Ke 10
    CHECK(light.kt.constant() == Rgb(0.0f));
    CHECK(light.emission.constant() == Rgb(10.0f));
    const PhongMaterial& wall = find("leftWall");
    CHECK(wall.kd.constant() == Rgb(0.63f, 0.065f, 0.05f));
    CHECK(wall.kr.constant() == Rgb(0.0f));
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

TEST_CASE("a missing OBJ file is an error that names it, a missing MTL file a warning that names it") {
    const auto missingObj = writeScene("missing-obj.toml", meshScene("no-such-mesh.obj"));
    const std::string expected =
        "meshes[0].file: " + (missingObj.parent_path() / "no-such-mesh.obj").string() + ": cannot open mesh file";
    CHECK_THROWS_WITH_AS(loadScene(missingObj), doctest::Contains(expected.c_str()), SceneError);

    const auto directory = missingObj.parent_path();
    std::ofstream(directory / "lost-library.obj") << "mtllib gone.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl red\nf 1 2 3\n";
    // As other tools read OBJ files (issue #26): the faces are grey, and a warning says why.
    const Scene scene = loadScene(writeScene("missing-mtl.toml", meshScene(directory / "lost-library.obj")));
    CHECK(scene.objects.size() == 1);
    CHECK(std::any_of(scene.warnings.begin(), scene.warnings.end(),
                      [](const std::string& w) { return w.find("gone.mtl") != std::string::npos; }));
}

// Found by tests/fuzz: tinyobjloader passes negative numbers on and reads 1e39 as infinity; such
// a material would put negative or infinite light into the image.
TEST_CASE("MTL values outside the scene file's limits are refused, naming the material") {
    const std::string triangle = "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl red\nf 1 2 3\n";
    const auto errorOf = [&](const std::string& mtl) -> std::string {
        try {
            loadObjFromText(triangle, "newmtl red\n" + mtl, "mesh.obj");
        } catch (const SceneError& e) {
            return e.what();
        }
        return "(loaded)";
    };
    CHECK(errorOf("Kd -1 0 0\n") == "mesh.obj: material \"red\": Kd: expected 3 numbers from 0 to 1e6, got [-1, 0, 0]");
    CHECK(errorOf("Ke 0 1e39 0\n") == "mesh.obj: material \"red\": Ke: expected 3 numbers from 0 to 1e6, got [0, inf, 0]");
    CHECK(errorOf("Ns 1e39\n") == "mesh.obj: material \"red\": Ns: expected a number from -1e6 to 1e6, got inf");
    // What the loader always tolerated still loads: a negative Ns is 0, an Ni of 0 is ignored.
    const ObjMesh mesh = loadObjFromText(triangle, "newmtl red\nKd 1e6 0 0\nNs -5\nNi 0\nillum 7\n", "mesh.obj");
    REQUIRE(mesh.materials.size() == 1);
    CHECK(mesh.materials[0].kd.constant() == Rgb(1e6f, 0.0f, 0.0f));
    CHECK(mesh.materials[0].n == 0.0f);
    CHECK(mesh.materials[0].ior == 1.5f);
}

// Found by tests/fuzz: a normal with an infinite component became NaN, one of 3e38 per component
// lost its length to overflow in float.
TEST_CASE("vertex normals are finite and normalised whatever their length") {
    const std::string corners = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    CHECK_THROWS_WITH_AS(loadObjFromText(corners + "vn 0 0 1e39\nf 1//1 2//1 3//1\n", "", "mesh.obj"),
                         "mesh.obj: normal 1 has a component that is not a finite single-precision number", SceneError);
    const ObjMesh mesh = loadObjFromText(corners + "vn 3e38 3e38 0\nvn 0 1e-40 0\nf 1//1 2//2 3//1\n", "", "mesh.obj");
    REQUIRE(mesh.normals.size() == 1);
    const float half = std::sqrt(0.5f);
    CHECK(mesh.normals[0].a.x == doctest::Approx(half));
    CHECK(mesh.normals[0].a.y == doctest::Approx(half));
    CHECK(mesh.normals[0].b == Vec3(0.0f, 1.0f, 0.0f));
}

TEST_CASE("a mesh placed beyond the scene limit of 1e6 is refused") {
    const auto directory = kTestFiles;
    std::filesystem::create_directories(directory);
    std::ofstream(directory / "far.obj") << "v 0 0 0\nv 1 0 0\nv 0 1e5 0\nf 1 2 3\n";
    const std::string mesh = meshScene(directory / "far.obj", "material = \"grey\"\n");
    CHECK_NOTHROW(loadScene(writeScene("near.toml", "[materials.grey]\n" + mesh + "scale = 10\n")));
    CHECK_THROWS_WITH_AS(loadScene(writeScene("far.toml", "[materials.grey]\n" + mesh + "scale = 100\n")),
                         doctest::Contains("triangle 1 has a corner at [0, 1e+07, 0] once placed; expected "
                                           "coordinates from -1e6 to 1e6"),
                         SceneError);
}

}  // namespace
}  // namespace lightpath
