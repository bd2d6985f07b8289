// The scene loader: every shipped scene loads, a written scene reads back exactly, and every
// kind of mistake a student makes is reported with file, line, column, key path and a message
// that says what was expected and what was found.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <string_view>

#include "lights/point_light.h"
#include "materials/modified_phong_material.h"
#include "materials/phong_material.h"
#include "media/homogeneous_medium.h"
#include "scene/scene_loader.h"
#include "shapes/obj_loader.h"

namespace fs = std::filesystem;
using lightpath::ModifiedPhongMaterial;
using lightpath::Rgb;
using lightpath::Scene;
using lightpath::SceneError;
using lightpath::Vec3;

namespace {

// Scene files written by one test, in a folder of their own that is removed afterwards. The
// folder name is random because ctest may run several test processes at once.
class SceneFiles {
public:
    SceneFiles()
        : dir_(fs::temp_directory_path() /
               ("lightpath-scene-tests-" + std::to_string(std::random_device{}()))) {
        fs::create_directories(dir_);
    }
    ~SceneFiles() {
        std::error_code ignored;
        fs::remove_all(dir_, ignored);
    }
    SceneFiles(const SceneFiles&) = delete;
    SceneFiles& operator=(const SceneFiles&) = delete;

    const fs::path& dir() const { return dir_; }

    fs::path write(std::string_view name, std::string_view text) const {
        const fs::path path = dir_ / name;
        std::ofstream(path) << text;
        return path;
    }

    Scene load(std::string_view text) const {
        return lightpath::loadScene(write("scene.toml", text));
    }

    // The error loading `text` gives, with the folder left out: "scene.toml:3:10: key: message".
    std::string errorOf(std::string_view text) const {
        try {
            lightpath::loadScene(write("scene.toml", text));
        } catch (const SceneError& error) {
            return withoutFolder(error.what());
        }
        return "(loaded without error)";
    }

    std::string withoutFolder(std::string message) const {
        const std::string folder = dir_.string() + "/";
        if (message.starts_with(folder)) message.erase(0, folder.size());
        return message;
    }

private:
    fs::path dir_;
};

bool hasMirrorMaterial(const Scene& scene) {
    for (const auto& m : scene.materials) {
        if (!lightpath::isBlack(lightpath::phongOf(m).kr.constant())) return true;
    }
    return false;
}

bool hasGlassMaterial(const Scene& scene) {
    for (const auto& m : scene.materials) {
        if (!lightpath::isBlack(lightpath::phongOf(m).kt.constant())) return true;
    }
    return false;
}

}  // namespace

TEST_CASE("every shipped scene loads and names its lights, point or area") {
    int count = 0;
    for (const auto& entry : fs::directory_iterator(LIGHTPATH_SOURCE_DIR "/scenes")) {
        if (entry.path().extension() != ".toml") continue;
        CAPTURE(entry.path().string());
        Scene scene;
        REQUIRE_NOTHROW(scene = lightpath::loadScene(entry.path()));
        CHECK(scene.source == entry.path());
        CHECK_FALSE(scene.objects.empty());
        for (const auto& light : scene.lights) CHECK_FALSE(light->name.empty());
        // Area lights are emissive objects; a shipped scene has some light, and names it.
        bool hasAreaLight = false;
        for (std::uint32_t i = 0; i < scene.objects.size(); ++i) {
            if (scene.materials[scene.objects[i].material]->emission.black()) continue;
            hasAreaLight = true;
            CHECK_FALSE(scene.labelOf(i).rfind("area-light-", 0) == 0);
        }
        CHECK((!scene.lights.empty() || hasAreaLight));
        ++count;
    }
    CHECK(count >= 5);
}

TEST_CASE("the lecture room has what the default AOVs need") {
    const Scene scene = lightpath::loadScene(LIGHTPATH_SOURCE_DIR "/scenes/lecture-room.toml");
    CHECK_FALSE(lightpath::isBlack(scene.background));  // the emission and mirror AOVs see it
    CHECK_FALSE(lightpath::isBlack(scene.ambient));
    CHECK(hasMirrorMaterial(scene));  // raytrace and mirror need specular paths
    CHECK(hasGlassMaterial(scene));
    CHECK(scene.camera.width == 640);
    CHECK(scene.camera.height == 480);
}

// The format reference must not document a file the loader refuses.
TEST_CASE_FIXTURE(SceneFiles, "the example in scenes/README.md loads as described") {
    std::ifstream readme(LIGHTPATH_SOURCE_DIR "/scenes/README.md");
    const std::string text((std::istreambuf_iterator<char>(readme)), {});
    const std::string fence = "```toml\n";
    const std::size_t begin = text.find(fence);
    REQUIRE(begin != std::string::npos);
    const std::size_t end = text.find("```", begin + fence.size());
    REQUIRE(end != std::string::npos);

    const Scene scene = load(text.substr(begin + fence.size(), end - begin - fence.size()));
    REQUIRE(scene.objects.size() == 3);
    CHECK(scene.labelOf(scene.spheres.at(0).object) == "ball");
    CHECK(scene.labelOf(scene.planes.at(0).object) == "floor");
    CHECK(scene.labelOf(scene.triangles.at(0).object) == "red");
    REQUIRE(scene.lights.size() == 1);
    CHECK(scene.lights[0]->name == "key");
    CHECK(pointLightOf(scene.lights[0]).attenuation == Vec3(1, 0.1f, 0.01f));
}

TEST_CASE_FIXTURE(SceneFiles, "a scene reads back with exactly the values written") {
    const Scene scene = load(R"(
[camera]
eye = [1, 2, 3]
look_at = [0, 0.5, -1]
up = [0, 2, 0]
fov = 30.5
resolution = [320, 200]

[world]
background = [0.25, 0.5, 0.75]
ambient = 0.125

[materials.red]
ka = [0.1, 0, 0]
kd = [0.7, 0.25, 0.5]
ks = 0.3
n = 50
kr = 0.125
kt = [0, 0.5, 1]
ior = 1.25

[materials.plain]

[[lights]]
name = "key"
type = "point"
position = [2, 4, 3]
intensity = [1, 0.5, 0.25]
attenuation = [1, 0.1, 0.01]

[[lights]]
position = [-1, 1, 0]
intensity = 2

[[spheres]]
name = "ball"
center = [0, 1, -2]
radius = 2
material = "red"

[[planes]]
point = [0, -1, 0]
normal = [0, 3, 4]
material = "plain"

[[triangles]]
name = "tri"
vertices = [[0, 0, 0], [1, 0, 0], [0, 1, 0]]
material = "red"
)");
    CHECK(scene.source == dir() / "scene.toml");

    SUBCASE("camera") {
        CHECK(scene.camera.eye == Vec3(1, 2, 3));
        CHECK(scene.camera.lookAt == Vec3(0, 0.5f, -1));
        CHECK(scene.camera.up == Vec3(0, 2, 0));  // the camera normalises it, not the loader
        CHECK(scene.camera.verticalFovDegrees == 30.5f);
        CHECK(scene.camera.width == 320);
        CHECK(scene.camera.height == 200);
    }
    SUBCASE("world: one number is grey") {
        CHECK(scene.background == Rgb(0.25f, 0.5f, 0.75f));
        CHECK(scene.ambient == Rgb(0.125f, 0.125f, 0.125f));
    }
    SUBCASE("materials, per channel and in file order") {
        REQUIRE(scene.materials.size() == 2);
        const auto& red = phongOf(scene.materials[0]);
        CHECK(red.name == "red");
        CHECK(red.ka.constant() == Rgb(0.1f, 0, 0));
        CHECK(red.kd.constant() == Rgb(0.7f, 0.25f, 0.5f));
        CHECK(red.ks.constant() == Rgb(0.3f, 0.3f, 0.3f));
        CHECK(red.n == 50.0f);
        CHECK(red.kr.constant() == Rgb(0.125f));
        CHECK(red.kt.constant() == Rgb(0, 0.5f, 1));
        CHECK(red.ior == 1.25f);
        CHECK(scene.materials[1]->name == "plain");
    }
    SUBCASE("lights") {
        REQUIRE(scene.lights.size() == 2);
        const auto& key = pointLightOf(scene.lights[0]);
        CHECK(key.name == "key");
        CHECK(key.position() == Vec3(2, 4, 3));
        CHECK(key.intensity == Rgb(1, 0.5f, 0.25f));
        CHECK(key.attenuation == Vec3(1, 0.1f, 0.01f));
        CHECK(scene.lights[1]->name.empty());
        CHECK(pointLightOf(scene.lights[1]).intensity == Rgb(2, 2, 2));
    }
    SUBCASE("shapes and their objects") {
        REQUIRE(scene.objects.size() == 3);
        REQUIRE(scene.spheres.size() == 1);
        REQUIRE(scene.planes.size() == 1);
        REQUIRE(scene.triangles.size() == 1);

        CHECK(scene.spheres[0].center == Vec3(0, 1, -2));
        CHECK(scene.spheres[0].radius == 2.0f);
        CHECK(scene.planes[0].point == Vec3(0, -1, 0));
        CHECK(scene.planes[0].normal.x == 0.0f);
        CHECK(scene.planes[0].normal.y == doctest::Approx(0.6));
        CHECK(scene.planes[0].normal.z == doctest::Approx(0.8));
        CHECK(scene.triangles[0].a == Vec3(0, 0, 0));
        CHECK(scene.triangles[0].b == Vec3(1, 0, 0));
        CHECK(scene.triangles[0].c == Vec3(0, 1, 0));

        // Spheres are numbered first, then planes, then triangles.
        CHECK(scene.spheres[0].object == 0);
        CHECK(scene.planes[0].object == 1);
        CHECK(scene.triangles[0].object == 2);
        CHECK(scene.objects[0].material == 0);
        CHECK(scene.objects[1].material == 1);
        CHECK(scene.objects[2].material == 0);
    }
    SUBCASE("labels: the object's name, else its material's") {
        CHECK(scene.labelOf(0) == "ball");
        CHECK(scene.labelOf(1) == "plain");
        CHECK(scene.labelOf(2) == "tri");
    }
}

TEST_CASE_FIXTURE(SceneFiles, "keys left out take the documented defaults") {
    const Scene scene = load(R"(
[materials.plain]
[[lights]]
position = [0, 3, 0]
[[spheres]]
center = [0, 0, 0]
radius = 1
material = "plain"
)");
    CHECK(scene.camera.eye == Vec3(0, 0, 5));
    CHECK(scene.camera.lookAt == Vec3(0, 0, 0));
    CHECK(scene.camera.up == Vec3(0, 1, 0));
    CHECK(scene.camera.verticalFovDegrees == 45.0f);
    CHECK(scene.camera.width == 640);
    CHECK(scene.camera.height == 480);
    CHECK(scene.background == Rgb(0));
    CHECK(scene.ambient == Rgb(0));

    REQUIRE(scene.materials.size() == 1);
    const auto& plain = phongOf(scene.materials[0]);
    CHECK(plain.ka.constant() == Rgb(0));
    CHECK(plain.kd.constant() == Rgb(0));
    CHECK(plain.ks.constant() == Rgb(0));
    CHECK(plain.kr.constant() == Rgb(0));
    CHECK(plain.kt.constant() == Rgb(0));
    CHECK(plain.n == 20.0f);
    CHECK(plain.ior == 1.5f);

    REQUIRE(scene.lights.size() == 1);
    CHECK(scene.lights[0]->name.empty());
    CHECK(pointLightOf(scene.lights[0]).intensity == Rgb(1));
    CHECK(pointLightOf(scene.lights[0]).attenuation == Vec3(1, 0, 0));
    CHECK(scene.objects[0].name.empty());
}

TEST_CASE_FIXTURE(SceneFiles, "an empty file is an empty scene") {
    const Scene scene = load("# nothing yet\n");
    CHECK(scene.objects.empty());
    CHECK(scene.lights.empty());
    CHECK(scene.materials.empty());
}

TEST_CASE_FIXTURE(SceneFiles, "a TOML syntax error reports toml++'s position and description") {
    CHECK(errorOf("[camera]\nfov = [1, 2\n") ==
          "scene.toml:2:13: TOML syntax error: Error while parsing array: encountered "
          "end-of-file");
    CHECK(errorOf("[camera]\nfov = 40\nfov = 50\n") ==
          "scene.toml:3:7: TOML syntax error: Error while parsing key-value pair: cannot "
          "redefine existing integer 'fov'");
}

TEST_CASE_FIXTURE(SceneFiles, "a file that cannot be opened says why") {
    const fs::path missing = dir() / "missing.toml";
    CHECK_THROWS_WITH_AS(lightpath::loadScene(missing),
                         (missing.string() + ": cannot open scene file (No such file or directory)")
                             .c_str(),
                         SceneError);
    CHECK_THROWS_WITH_AS(lightpath::loadScene(dir()),
                         (dir().string() + ": cannot open scene file (Is a directory)").c_str(),
                         SceneError);
}

TEST_CASE_FIXTURE(SceneFiles, "an unknown key is named, with a suggestion when one is close") {
    CHECK(errorOf("[materials.red]\n[[spheres]]\ncenter = [0, 0, 0]\nraduis = 1\n") ==
          "scene.toml:4:1: spheres[0].raduis: unknown key \"raduis\"; did you mean \"radius\"?");
    CHECK(errorOf("[camera]\n  zoom = 2\n") ==
          "scene.toml:2:3: camera.zoom: unknown key \"zoom\" "
          "(known: eye, look_at, up, projection, fov, height, resolution)");
    CHECK(errorOf("[materials.red]\nkd = 1\nKs = 0.5\n") ==
          "scene.toml:3:1: materials.red.Ks: unknown key \"Ks\"; did you mean \"ks\"?");
}

TEST_CASE_FIXTURE(SceneFiles, "an orthographic camera: its height read; a field of view or an unknown projection refused") {
    const auto camera = [&](std::string_view text) { return load(text).camera; };
    const lightpath::CameraDescription ortho = camera("[camera]\nprojection = \"orthographic\"\nheight = 3.5\n");
    CHECK(ortho.projection == lightpath::Projection::Orthographic);
    CHECK(ortho.orthographicHeight == 3.5f);
    CHECK(camera("[camera]\nprojection = \"perspective\"\n").projection == lightpath::Projection::Perspective);
    CHECK(errorOf("[camera]\nprojection = \"fisheye\"\n") ==
          "scene.toml:2:14: camera.projection: expected \"perspective\" or \"orthographic\", got a string (\"fisheye\")");
    CHECK(errorOf("[camera]\nprojection = \"orthographic\"\nfov = 40\n") ==
          "scene.toml:3:7: camera.fov: an orthographic camera has no field of view: `height` sets how much of the "
          "scene it shows");
    CHECK(errorOf("[camera]\nheight = 2\n") ==
          "scene.toml:2:10: camera.height: `height` is an orthographic camera's; a perspective one's extent is `fov` "
          "(or set projection = \"orthographic\")");
    CHECK(errorOf("[camera]\nprojection = \"orthographic\"\nheight = 0\n") ==
          "scene.toml:3:10: camera.height: expected the view's height in scene units, > 0, got 0");
}

TEST_CASE_FIXTURE(SceneFiles, "an unknown top-level table is an error") {
    CHECK(errorOf("[camera]\nfov = 40\n\n[[sphere]]\nradius = 1\n") ==
          "scene.toml:4:3: sphere: unknown key \"sphere\"; did you mean \"spheres\"?");
    CHECK(errorOf("[render]\nspp = 4\n") ==
          "scene.toml:1:2: render: unknown key \"render\" (known: camera, world, materials, "
          "media, lights, spheres, planes, disks, triangles, meshes, gltf)");
}

TEST_CASE_FIXTURE(SceneFiles, "a value of the wrong type says what was expected and found") {
    CHECK(errorOf("[materials.red]\n[[spheres]]\ncenter = \"origin\"\n") ==
          "scene.toml:3:10: spheres[0].center: expected an array of 3 numbers, got a string "
          "(\"origin\")");
    CHECK(errorOf("[[spheres]]\ncenter = [0, 1]\n") ==
          "scene.toml:2:10: spheres[0].center: expected an array of 3 numbers, got an array of "
          "2 elements");
    CHECK(errorOf("[[spheres]]\ncenter = [0, true, 0]\n") ==
          "scene.toml:2:14: spheres[0].center[1]: expected a number, got a boolean");
    CHECK(errorOf("[materials.red]\nkd = \"red\"\n") ==
          "scene.toml:2:6: materials.red.kd: expected a number or an array of 3 numbers, got a "
          "string (\"red\")");
    CHECK(errorOf("[[lights]]\nname = 7\nposition = [0, 0, 0]\n") ==
          "scene.toml:2:8: lights[0].name: expected a string, got 7");
    CHECK(errorOf("camera = 5\n") == "scene.toml:1:10: camera: expected a table, got 5");
}

TEST_CASE_FIXTURE(SceneFiles, "single brackets where an array of tables was meant") {
    CHECK(errorOf("[spheres]\nradius = 1\n") ==
          "scene.toml:1:1: spheres: expected an array of tables ([[spheres]] sections), got a "
          "table");
}

TEST_CASE_FIXTURE(SceneFiles, "a negative radius is refused") {
    CHECK(errorOf("[materials.red]\n\n[[spheres]]\ncenter = [0, 0, 0]\nradius = -1\n") ==
          "scene.toml:5:10: spheres[0].radius: expected a positive number, got -1");
    CHECK(errorOf("[[spheres]]\ncenter = [0, 0, 0]\nradius = 0.0\n") ==
          "scene.toml:3:10: spheres[0].radius: expected a positive number, got 0");
}

TEST_CASE_FIXTURE(SceneFiles, "nan and inf are refused by name") {
    CHECK(errorOf("[[spheres]]\ncenter = [0, 0, 0]\nradius = nan\n") ==
          "scene.toml:3:10: spheres[0].radius: expected a finite number, got nan");
    CHECK(errorOf("[materials.red]\nka = [0, -inf, 0]\n") ==
          "scene.toml:2:10: materials.red.ka[1]: expected a finite number, got -inf");
    CHECK(errorOf("[camera]\neye = [0, 0, 1e300]\n") ==
          "scene.toml:2:14: camera.eye[2]: expected a number from -1e6 to 1e6, got 1e+300");
}

// Found by tests/fuzz: 3e38 radiance and 1e30 coordinates are finite floats, but their products
// overflow to infinity in the renderer (an infinite pixel, dropped contributions).
TEST_CASE_FIXTURE(SceneFiles, "numbers beyond 1e6 in magnitude are refused") {
    CHECK(errorOf("[materials.hot]\nemission = 3e38\n") ==
          "scene.toml:2:12: materials.hot.emission: expected a number from -1e6 to 1e6, got 3e+38");
    CHECK(errorOf("[[spheres]]\ncenter = [0, -1e30, 0]\n") ==
          "scene.toml:2:14: spheres[0].center[1]: expected a number from -1e6 to 1e6, got -1e+30");
    const Scene scene = load("[world]\nbackground = 1e6\n[camera]\neye = [-1e6, 0, 1e6]\n");
    CHECK(scene.background == Rgb(1e6f));
    CHECK(scene.camera.eye == Vec3(-1e6f, 0.0f, 1e6f));
}

TEST_CASE_FIXTURE(SceneFiles, "a tiny plane normal is normalised, not lost to underflow") {
    const Scene scene = load("[materials.grey]\n[[planes]]\npoint = [0, 0, 0]\nnormal = [0, 1e-30, 0]\n"
                             "material = \"grey\"\n");
    REQUIRE(scene.planes.size() == 1);
    CHECK(scene.planes[0].normal == Vec3(0.0f, 1.0f, 0.0f));
}

TEST_CASE_FIXTURE(SceneFiles, "a zero plane normal is refused") {
    CHECK(errorOf("[[planes]]\npoint = [0, 0, 0]\nnormal = [0, 0, 0]\n") ==
          "scene.toml:3:10: planes[0].normal: expected a non-zero vector, got [0, 0, 0]");
}

TEST_CASE_FIXTURE(SceneFiles, "the camera's up vector must be usable") {
    SUBCASE("zero") {
        CHECK(errorOf("[camera]\nup = [0, 0, 0]\n") ==
              "scene.toml:2:6: camera.up: expected a non-zero vector, got [0, 0, 0]");
    }
    SUBCASE("parallel to the view direction, written") {
        CHECK(errorOf("[camera]\neye = [0, 0, 5]\nup = [0, 0, -2]\n") ==
              "scene.toml:3:6: camera.up: expected a vector not parallel to look_at - eye = "
              "[0, 0, -5], got [0, 0, -2]");
    }
    SUBCASE("parallel to the view direction, by default: located at the camera table") {
        CHECK(errorOf("\n[camera]\neye = [0, 10, 0]\n") ==
              "scene.toml:2:1: camera.up: expected a vector not parallel to look_at - eye = "
              "[0, -10, 0], got [0, 1, 0]");
    }
    SUBCASE("eye and look_at coincide") {
        CHECK(errorOf("[camera]\neye = [1, 1, 1]\nlook_at = [1, 1, 1]\n") ==
              "scene.toml:3:11: camera.look_at: expected a point other than camera.eye, got the "
              "same point [1, 1, 1]");
    }
}

TEST_CASE_FIXTURE(SceneFiles, "the field of view must lie strictly between 0 and 180 degrees") {
    for (const std::string fov : {"0", "180", "-5", "200.5"}) {
        CAPTURE(fov);
        CHECK(errorOf("[camera]\nfov = " + fov + "\n") ==
              "scene.toml:2:7: camera.fov: expected a vertical field of view in degrees, "
              "0 < fov < 180, got " + fov);
    }
    CHECK(load("[camera]\nfov = 179.5\n").camera.verticalFovDegrees == 179.5f);
}

// Found by tests/fuzz: the ranges held for the double the file wrote, not for the float the scene
// keeps, so fov = 179.999999 became 180 and a radius of 1e-50 became 0.
TEST_CASE_FIXTURE(SceneFiles, "ranges hold for numbers as stored in single precision") {
    CHECK(errorOf("[camera]\nfov = 179.999999\n") ==
          "scene.toml:2:7: camera.fov: expected a vertical field of view in degrees, 0 < fov < 180, "
          "got 179.999999, which is 180 in single precision");
    CHECK(errorOf("[[spheres]]\ncenter = [0, 0, 0]\nradius = 1e-50\n") ==
          "scene.toml:3:10: spheres[0].radius: expected a positive number, got 1e-50, which is 0 in "
          "single precision");
}

TEST_CASE_FIXTURE(SceneFiles, "the resolution must be two integers from 1 to 16384") {
    CHECK(errorOf("[camera]\nresolution = [0, 480]\n") ==
          "scene.toml:2:15: camera.resolution[0]: expected an integer from 1 to 16384, got 0");
    CHECK(errorOf("[camera]\nresolution = [640, 16385]\n") ==
          "scene.toml:2:20: camera.resolution[1]: expected an integer from 1 to 16384, got "
          "16385");
    CHECK(errorOf("[camera]\nresolution = [640.5, 480]\n") ==
          "scene.toml:2:15: camera.resolution[0]: expected an integer from 1 to 16384, got "
          "640.5");
    CHECK(errorOf("[camera]\nresolution = 640\n") ==
          "scene.toml:2:14: camera.resolution: expected an array of 2 integers [width, height], "
          "got 640");
    const Scene extreme = load("[camera]\nresolution = [1, 16384]\n");
    CHECK(extreme.camera.width == 1);
    CHECK(extreme.camera.height == 16384);
}

TEST_CASE_FIXTURE(SceneFiles, "an unknown material gets a suggestion and the list of known ones") {
    const std::string materials = "[materials.red]\n[materials.grey]\n";
    CHECK(errorOf(materials +
                  "[[spheres]]\ncenter = [0, 0, 0]\nradius = 1\nmaterial = \"rde\"\n") ==
          "scene.toml:6:12: spheres[0].material: unknown material \"rde\"; did you mean "
          "\"red\"? (known: grey, red)");
    CHECK(errorOf(materials + "[[triangles]]\nvertices = [[0,0,0], [1,0,0], [0,1,0]]\n"
                              "material = \"gold\"\n") ==
          "scene.toml:5:12: triangles[0].material: unknown material \"gold\" (known: grey, red)");
    CHECK(errorOf("[[planes]]\npoint = [0, 0, 0]\nnormal = [0, 1, 0]\nmaterial = \"grey\"\n") ==
          "scene.toml:4:12: planes[0].material: unknown material \"grey\" (known: none)");
}

TEST_CASE_FIXTURE(SceneFiles, "a missing required key is located at its table") {
    CHECK(errorOf("[materials.red]\n\n[[spheres]]\nradius = 1\nmaterial = \"red\"\n") ==
          "scene.toml:3:1: spheres[0]: missing required key \"center\"");
    const std::string sphere = "[[spheres]]\ncenter = [0, 0, 0]\nradius = 1\nmaterial = \"red\"\n";
    CHECK(errorOf("[materials.red]\n" + sphere + sphere + "[[spheres]]\ncenter = [0, 0, 0]\n") ==
          "scene.toml:10:1: spheres[2]: missing required key \"radius\"");
    CHECK(errorOf("[[planes]]\npoint = [0, 0, 0]\nnormal = [0, 1, 0]\n") ==
          "scene.toml:1:1: planes[0]: missing required key \"material\"");
    CHECK(errorOf("[[triangles]]\nmaterial = \"red\"\n") ==
          "scene.toml:1:1: triangles[0]: missing required key \"vertices\"");
    CHECK(errorOf("[[lights]]\nname = \"key\"\n") ==
          "scene.toml:1:1: lights[0]: missing required key \"position\"");
}

TEST_CASE_FIXTURE(SceneFiles, "attenuation coefficients must not all be zero") {
    CHECK(errorOf("[[lights]]\nposition = [0, 1, 0]\nattenuation = [0, 0, 0]\n") ==
          "scene.toml:3:15: lights[0].attenuation: expected c0, c1, c2 not all zero "
          "(1 / (c0 + c1 d + c2 d^2) would divide by zero), got [0, 0, 0]");
    CHECK(errorOf("[[lights]]\nposition = [0, 1, 0]\nattenuation = [1, -0.5, 0]\n") ==
          "scene.toml:3:19: lights[0].attenuation[1]: expected a number >= 0, got -0.5");
    CHECK(errorOf("[[lights]]\nposition = [0, 1, 0]\nattenuation = [1e-30, 0, 0]\n") ==
          "scene.toml:3:15: lights[0].attenuation: expected c0, c1, c2 each 0 or at least 1e-6 "
          "(1 / (c0 + c1 d + c2 d^2) would overflow), got [1e-30, 0, 0]");
}

TEST_CASE_FIXTURE(SceneFiles, "a material's type picks its model and its keys") {
    const Scene scene = load("[materials.classic]\nkd = 0.5\n[materials.plastic]\ntype = \"modified-phong\"\n"
                             "kd = 0.4\nks = [0.5, 0.4, 0.3]\nn = 50\nemission = 2\n");
    REQUIRE(scene.materials.size() == 2);
    CHECK(phongOf(scene.materials[0]).kd.constant() == Rgb(0.5f));
    const auto* plastic = dynamic_cast<const ModifiedPhongMaterial*>(&*scene.materials[1]);
    REQUIRE(plastic != nullptr);
    CHECK(plastic->name == "plastic");
    CHECK(plastic->kd.constant() == Rgb(0.4f));
    CHECK(plastic->ks.constant() == Rgb(0.5f, 0.4f, 0.3f));
    CHECK(plastic->n == 50.0f);
    CHECK(plastic->emission.constant() == Rgb(2.0f));

    CHECK(errorOf("[materials.m]\ntype = \"modified-phong\"\nkr = 0.5\n") ==
          "scene.toml:3:1: materials.m.kr: unknown key \"kr\"; did you mean \"kd\"?");
    CHECK(errorOf("[materials.m]\ntype = \"modified-phog\"\n") ==
          "scene.toml:2:8: materials.m.type: unknown material type \"modified-phog\"; did you mean "
          "\"modified-phong\"? (known: phong, modified-phong, microfacet, interface, conductor, dielectric)");
    CHECK(errorOf("[materials.m]\ntype = 3\n") == "scene.toml:2:8: materials.m.type: expected a string, got 3");
}

TEST_CASE_FIXTURE(SceneFiles, "material parameters are range-checked") {
    CHECK(errorOf("[materials.shiny]\nn = -3\n") ==
          "scene.toml:2:5: materials.shiny.n: expected a number >= 0, got -3");
    CHECK(errorOf("[materials.glass]\nior = 0\n") ==
          "scene.toml:2:7: materials.glass.ior: expected a positive number, got 0");
    CHECK(errorOf("[materials.glass]\nior = -1.5\n") ==
          "scene.toml:2:7: materials.glass.ior: expected a positive number, got -1.5");
    CHECK(errorOf("[materials.red]\nkd = [0.7, 0, -0.1]\n") ==
          "scene.toml:2:15: materials.red.kd[2]: expected a number >= 0, got -0.1");
    CHECK(errorOf("[materials.red]\nks = -1\n") ==
          "scene.toml:2:6: materials.red.ks: expected a number >= 0, got -1");
}

TEST_CASE_FIXTURE(SceneFiles, "an unknown light type is refused, naming the known ones") {
    CHECK(errorOf("[[lights]]\ntype = \"area\"\nposition = [0, 1, 0]\n") ==
          "scene.toml:2:8: lights[0].type: unknown light type \"area\" (known: point, quad, sphere, spot, directional)");
    CHECK(errorOf("[[lights]]\ntype = \"pont\"\nposition = [0, 1, 0]\n") ==
          "scene.toml:2:8: lights[0].type: unknown light type \"pont\"; did you mean "
          "\"point\"? (known: point, quad, sphere, spot, directional)");
}

TEST_CASE_FIXTURE(SceneFiles, "names must be usable as light path labels") {
    CHECK(errorOf("[[lights]]\nname = \"ambient\"\nposition = [0, 1, 0]\n") ==
          "scene.toml:2:8: lights[0].name: expected a light name other than \"ambient\", which "
          "is reserved for the ambient term");
    CHECK(errorOf("[materials.red]\n[[spheres]]\ncenter = [0, 0, 0]\nradius = 1\n"
                  "name = \"my ball\"\n") ==
          "scene.toml:5:8: spheres[0].name: expected a name of letters, digits, '_', '-' or "
          "'.', got a string (\"my ball\")");
    CHECK(errorOf("[materials.\"it's red\"]\n") ==
          "scene.toml:1:1: materials.it's red: expected a material name of letters, digits, "
          "'_', '-' or '.', got \"it's red\"");
}

TEST_CASE_FIXTURE(SceneFiles, "a triangle without area is kept, with a located warning") {
    const Scene scene = load("[materials.grey]\n[[triangles]]\n"
                             "vertices = [[0, 0, 0], [1, 1, 1], [2, 2, 2]]\nmaterial = \"grey\"\n");
    CHECK(scene.triangles.size() == 1);
    REQUIRE(scene.warnings.size() == 1);
    CHECK(scene.warnings[0].ends_with(
        "scene.toml:3:12: triangles[0].vertices: the 3 points lie on one line: the triangle has no area "
        "and is never seen"));
    CHECK(errorOf("[[triangles]]\nvertices = [[0, 0, 0], [1, 1]]\n") ==
          "scene.toml:2:12: triangles[0].vertices: expected an array of 3 points "
          "[[x,y,z], [x,y,z], [x,y,z]], got an array of 2 elements");
}

// The dragon's case: its OBJ names a material library that is not there. The warning is located
// at the mesh's `file` and names the OBJ file and line and the library; the mesh gets the scene's
// material, else a grey.
TEST_CASE_FIXTURE(SceneFiles, "a missing material library is a located warning, and the mesh still loads") {
    write("lost.obj", "mtllib gone.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    const std::string expectedWarning =
        "meshes[0].file: " + (dir() / "lost.obj").string() +
        ":1: cannot open material library \"" + (dir() / "gone.mtl").string() + "\"; ";

    const Scene given = load("[materials.clay]\nkd = 0.7\n[[meshes]]\nfile = \"lost.obj\"\nmaterial = \"clay\"\n");
    REQUIRE(given.triangles.size() == 1);
    CHECK(given.labelOf(given.triangles[0].object) == "clay");
    REQUIRE(given.warnings.size() == 1);
    CHECK(withoutFolder(given.warnings[0]) == "scene.toml:4:8: " + expectedWarning + "the mesh's `material` is used");

    const Scene grey = load("[[meshes]]\nname = \"lost\"\nfile = \"lost.obj\"\n");
    REQUIRE(grey.triangles.size() == 1);
    const auto& material = phongOf(grey.materials[grey.objects[grey.triangles[0].object].material]);
    CHECK(material.kd.constant() == Rgb(0.5f));
    CHECK(material.ks.constant() == Rgb(0.0f));
    REQUIRE(grey.warnings.size() == 1);
    CHECK(withoutFolder(grey.warnings[0]) == "scene.toml:3:8: " + expectedWarning + "its faces are grey");
}

// Blender, assimp and every viewer open such files with a default material (issue #26).
TEST_CASE_FIXTURE(SceneFiles, "a usemtl material no library defines is a warning naming its line, its faces are grey") {
    write("lost.obj", "mtllib gone.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl red\nf 1 2 3\n");
    const Scene lost = load("[[meshes]]\nfile = \"lost.obj\"\n");
    REQUIRE(lost.triangles.size() == 1);
    CHECK(phongOf(lost.materials[lost.objects[lost.triangles[0].object].material]).kd.constant() == Rgb(0.5f));
    REQUIRE(lost.warnings.size() == 2);
    CHECK(withoutFolder(lost.warnings[1]) == "scene.toml:2:8: meshes[0].file: " + (dir() / "lost.obj").string() +
                                                 ":5: usemtl \"red\" names no material of its material libraries; "
                                                 "its faces are grey");
    // The library is there but lacks the material: the same warning, at its line; the faces that
    // name a known material keep it.
    write("m.mtl", "newmtl blue\nKd 0 0 1\n");
    write("wrong.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl blue\nf 1 2 3\n# red\nusemtl red\nf 1 3 2\n");
    const Scene wrong = load("[[meshes]]\nfile = \"wrong.obj\"\n");
    REQUIRE(wrong.triangles.size() == 2);
    CHECK(wrong.labelOf(wrong.triangles[0].object) == "blue");
    CHECK(phongOf(wrong.materials[wrong.objects[wrong.triangles[1].object].material]).kd.constant() == Rgb(0.5f));
    REQUIRE(wrong.warnings.size() == 1);
    CHECK(wrong.warnings[0].ends_with("wrong.obj:8: usemtl \"red\" names no material of its material libraries; "
                                      "its faces are grey"));
    // With the scene's material, the unknown usemtl is not needed.
    const Scene given = load("[materials.clay]\n[[meshes]]\nfile = \"lost.obj\"\nmaterial = \"clay\"\n");
    REQUIRE(given.triangles.size() == 1);
    CHECK(given.labelOf(given.triangles[0].object) == "clay");
    // Faces without any usemtl, and no scene material: grey, and no warning (nothing is missing).
    write("plain.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    const Scene plain = load("[[meshes]]\nfile = \"plain.obj\"\n");
    REQUIRE(plain.triangles.size() == 1);
    CHECK(phongOf(plain.materials[plain.objects[plain.triangles[0].object].material]).kd.constant() == Rgb(0.5f));
    CHECK(plain.warnings.empty());
}

// Polygons fanned into triangles, negative (relative) indices, faces with and without texture
// coordinates and normals, `o`/`g` groups, `s` lines, CRLF line ends and comments: whatever
// tinyobjloader reads.
TEST_CASE_FIXTURE(SceneFiles, "OBJ files read as tinyobjloader reads them: polygons, relative indices, CRLF") {
    write("tools.obj",
          "# exported\r\no square\r\nv 0 0 0\r\nv 1 0 0\r\nv 1 1 0\r\nv 0 1 0\r\ng front\r\ns 1\r\n"
          "f -4 -3 -2 -1\r\nvt 0 0\r\nvn 0 0 1\r\ns off\r\n# untextured\r\ng\r\nf 1/1/1 2/1/1 3/1/1\r\nf 1//1 3//1 4//1\r\n");
    const Scene scene = load("[[meshes]]\nfile = \"tools.obj\"\n");
    REQUIRE(scene.triangles.size() == 4);  // the quad's two (either diagonal), then two
    const auto area = [](const lightpath::Triangle& t) { return 0.5f * glm::length(glm::cross(t.b - t.a, t.c - t.a)); };
    CHECK(area(scene.triangles[0]) + area(scene.triangles[1]) == 1.0f);  // the unit square
    CHECK(scene.triangles[0].a == Vec3(0, 0, 0));  // -4 is the first of the four vertices
    CHECK(scene.triangles[2].a == Vec3(0, 0, 0));
    CHECK(scene.triangles[2].b == Vec3(1, 0, 0));
    CHECK(scene.triangles[2].c == Vec3(1, 1, 0));
    CHECK(scene.triangles[3].b == Vec3(1, 1, 0));
    CHECK(scene.triangles[3].c == Vec3(0, 1, 0));
    REQUIRE(scene.triangleNormals.size() == 4);
    CHECK(scene.triangleNormals[0].a == Vec3(0.0f));  // the quad has no `vn`: shaded flat
    CHECK(scene.triangleNormals[2].a == Vec3(0, 0, 1));
    CHECK(scene.warnings.empty());
}

// A Latin-1 and a UTF-8 "Terraindäk" (issue #26 found the first in a public test collection) and
// a name that is already a label: each gets a label, numbered where two collide, and a warning at
// its usemtl line says which. (tinyobjloader keeps an empty name only as a file's one material:
// assimp's empty_mat.obj, below.)
TEST_CASE_FIXTURE(SceneFiles, "material names that are no labels become labels, numbered on collision, each said") {
    write("names.mtl", "newmtl Terraind\xe4k\nKd 1 0 0\nnewmtl Terraind\xc3\xa4k\nKd 0 1 0\n"
                       "newmtl Terraind_k\nKd 0 0 1\n");
    const fs::path obj = write("names.obj", "mtllib names.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"
                                            "usemtl Terraind\xe4k\nf 1 2 3\nusemtl Terraind\xc3\xa4k\nf 1 3 2\n"
                                            "usemtl Terraind_k\nf 2 1 3\n");
    const Scene scene = load("[[meshes]]\nfile = \"names.obj\"\n");
    REQUIRE(scene.triangles.size() == 3);
    CHECK(scene.labelOf(scene.triangles[0].object) == "Terraind_k-2");
    CHECK(scene.labelOf(scene.triangles[1].object) == "Terraind_k-3");
    CHECK(scene.labelOf(scene.triangles[2].object) == "Terraind_k");
    CHECK(phongOf(scene.materials[scene.objects[scene.triangles[0].object].material]).kd.constant() == Rgb(1, 0, 0));
    CHECK(phongOf(scene.materials[scene.objects[scene.triangles[2].object].material]).kd.constant() == Rgb(0, 0, 1));
    const std::string at = "scene.toml:2:8: meshes[0].file: " + obj.string();
    const std::string notLabel = "\" is no label of letters, digits, '_', '-' or '.'; it is labelled \"";
    REQUIRE(scene.warnings.size() == 2);
    CHECK(withoutFolder(scene.warnings[0]) == at + ":5: material \"Terraind\\xE4k" + notLabel + "Terraind_k-2\"");
    CHECK(withoutFolder(scene.warnings[1]) == at + ":7: material \"Terraind\\xC3\\xA4k" + notLabel + "Terraind_k-3\"");
    CHECK(lightpath::labelFromName("  Hard Shiny  Plastic ") == "Hard_Shiny_Plastic");
}

TEST_CASE_FIXTURE(SceneFiles, "an OBJ file is a scene of that mesh, without camera or light, its messages its own") {
    write("lost.obj", "mtllib gone.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    const Scene scene = lightpath::loadScene(dir() / "lost.obj");
    CHECK(scene.triangles.size() == 1);
    CHECK(!scene.cameraGiven);
    CHECK(scene.lights.empty());
    REQUIRE(scene.warnings.size() == 1);
    CHECK(scene.warnings[0] == (dir() / "lost.obj").string() + ":1: cannot open material library \"" +
                                   (dir() / "gone.mtl").string() + "\"; its faces are grey");
    CHECK(load("[camera]\n").cameraGiven);
    CHECK(!load("").cameraGiven);
    write("broken.OBJ", "v 0 0 0\nf 1 2 3\n");
    try {
        lightpath::loadScene(dir() / "broken.OBJ");
        FAIL("a face of vertices the file lacks loaded");
    } catch (const SceneError& error) {
        CHECK(std::string(error.what()) == (dir() / "broken.OBJ").string() + ": face 1 refers to vertex 2, but the file has 1");
    }
}

// Copies of four of assimp's test models (tests/scene/data/assimp-obj/LICENSE), each a case
// issue #26 found refused: they load, with the warnings and labels expected of them.
TEST_CASE("assimp's test OBJ files load with at most warnings (copies under tests/)") {
    const fs::path folder = fs::path(LIGHTPATH_SOURCE_DIR) / "tests/scene/data/assimp-obj";
    const Scene box = lightpath::loadScene(folder / "box.obj");
    CHECK(box.triangles.size() == 12);
    REQUIRE(box.warnings.size() == 1);
    CHECK(box.warnings[0] == (folder / "box.obj").string() +
                                 ":22: usemtl \"Default\" names no material of its material libraries; its faces are grey");

    const Scene cube = lightpath::loadScene(folder / "cube_mtllib_after_g.obj");
    CHECK(cube.triangles.size() == 12);
    REQUIRE(cube.warnings.size() == 2);
    CHECK(cube.warnings[0] == (folder / "cube_mtllib_after_g.obj").string() + ":2: cannot open material library \"" +
                                  (folder / "cube_mtllib_after_g.mat").string() + "\"; its faces are grey");
    CHECK(cube.warnings[1].ends_with(":3: usemtl \"MyMaterial\" names no material of its material libraries; its faces are grey"));

    const Scene empty = lightpath::loadScene(folder / "empty_mat.obj");
    CHECK(empty.triangles.size() >= 256);
    CHECK(empty.labelOf(empty.triangles.back().object) == "unnamed");
    REQUIRE(empty.warnings.size() == 1);
    CHECK(empty.warnings[0].ends_with("empty_mat.obj:233: material \"\" is no label of letters, digits, '_', '-' or '.'; "
                                      "it is labelled \"unnamed\""));

    // tinyobjloader reads `usemtl`'s first word only ("Hard"), its MTL the whole name.
    const Scene spaced = lightpath::loadScene(folder / "space_in_material_name.obj");
    CHECK(!spaced.triangles.empty());
    REQUIRE(spaced.warnings.size() == 1);
    CHECK(spaced.warnings[0].ends_with(":75: usemtl \"Hard\" names no material of its material libraries; its faces are grey"));
}

// Every OBJ of Debian's assimp-testmodels that has a face (a line "f ..."; the UTF-16 box has none
// a byte-wise reader sees) loads as a scene with at most warnings, and has a triangle to show or
// says its faces have no area (number_formats.obj's one face is three points on a line).
TEST_CASE("every OBJ of Debian's assimp-testmodels with faces loads with at most warnings") {
    const fs::path folder = "/usr/share/assimp/models/OBJ";
    if (!fs::is_directory(folder)) {
        MESSAGE("skipped: Debian's assimp-testmodels is not installed (" << folder.string() << " is missing)");
        return;
    }
    int loaded = 0;
    for (const auto& entry : fs::directory_iterator(folder)) {
        if (!lightpath::isObjFile(entry.path())) continue;
        std::ifstream in(entry.path(), std::ios::binary);
        bool hasFace = false;
        for (std::string line; !hasFace && std::getline(in, line);) hasFace = line.starts_with("f ");
        if (!hasFace) continue;
        INFO(entry.path().string());
        Scene scene;
        CHECK_NOTHROW(scene = lightpath::loadScene(entry.path()));
        const auto noArea = [](const std::string& w) { return w.ends_with("faces without area were left out"); };
        CHECK((!scene.triangles.empty() || std::any_of(scene.warnings.begin(), scene.warnings.end(), noArea)));
        ++loaded;
    }
    MESSAGE(loaded << " OBJ files with faces loaded from " << folder.string());
    CHECK(loaded > 0);
}

namespace lightpath {
namespace {

TEST_CASE("area lights become emissive objects labelled by the light's name") {
    const std::string text =
        "[[lights]]\nname = \"panel\"\ntype = \"quad\"\ncorner = [0, 2, 0]\nedge1 = [1, 0, 0]\n"
        "edge2 = [0, 0, 1]\nradiance = [4, 3, 2]\n\n"
        "[[lights]]\ntype = \"sphere\"\ncenter = [0, 5, 0]\nradius = 0.5\nradiance = 10\n";
    const Scene scene = loadSceneFromText(text, "scene.toml");
    REQUIRE(scene.triangles.size() == 2);
    REQUIRE(scene.spheres.size() == 1);
    CHECK(scene.lights.empty());
    CHECK(scene.labelOf(scene.triangles[0].object) == "panel");
    CHECK(scene.materials[scene.objects[scene.triangles[0].object].material]->emission.constant() == Rgb{4, 3, 2});
    // The quad emits on the side of edge1 x edge2 = (0, 0, 1) x ... : here (1,0,0) x (0,0,1) = (0,-1,0).
    const Triangle& t = scene.triangles[0];
    CHECK(glm::cross(t.b - t.a, t.c - t.a).y < 0.0f);
    CHECK(t.a == Vec3{0, 2, 0});
    CHECK(t.c == Vec3{1, 2, 1});
    // An unnamed area light is labelled by its generated material name.
    CHECK(scene.labelOf(scene.spheres[0].object).rfind("area-light-", 0) == 0);
    CHECK(scene.materials[scene.objects[scene.spheres[0].object].material]->emission.constant() == Rgb{10.0f});
}

}  // namespace
}  // namespace lightpath

// [[disks]], a registered shape kind (src/shapes/disk.cpp), read through its schema: the same
// located messages as the hand-read shapes, objects numbered after the planes.
TEST_CASE_FIXTURE(SceneFiles, "disks are read through their schema, with located errors") {
    const std::string materials = "[materials.red]\n[materials.grey]\n";
    const Scene scene = load(materials +
                             "[[triangles]]\nvertices = [[0,0,0], [1,0,0], [0,1,0]]\nmaterial = \"grey\"\n"
                             "[[disks]]\nname = \"coin\"\ncenter = [1, 2, 3]\nnormal = [0, 0, 2]\nradius = 0.5\n"
                             "material = \"red\"\n"
                             "[[planes]]\npoint = [0, 0, 0]\nnormal = [0, 1, 0]\nmaterial = \"grey\"\n");
    REQUIRE(scene.shapes.size() == 1);
    CHECK(scene.shapes[0].ops->name == "disk");
    CHECK(scene.shapes[0].object == 1);  // the plane is object 0, the triangle 2
    CHECK(scene.objects[1].name == "coin");
    CHECK(scene.objects[1].material == 0);
    CHECK(scene.shapes[0].ops->area(scene.shapes[0]) == doctest::Approx(3.14159265358979 * 0.25));
    CHECK(errorOf(materials + "[[disks]]\ncenter = [0, 0, 0]\nnormal = [0, 1, 0]\nradius = 1\nmaterial = \"rde\"\n") ==
          "scene.toml:7:12: disks[0].material: unknown material \"rde\"; did you mean \"red\"? (known: grey, red)");
    CHECK(errorOf(materials + "[[disks]]\ncenter = [0, 0, 0]\nnormal = [0, 1, 0]\nradius = -1\nmaterial = \"red\"\n") ==
          "scene.toml:6:10: disks[0].radius: expected a positive number, got -1");
    CHECK(errorOf(materials + "[[disks]]\ncenter = [0, 0, 0]\nnormal = [0, 0, 0]\nradius = 1\nmaterial = \"red\"\n") ==
          "scene.toml:5:10: disks[0].normal: expected a non-zero vector, got [0, 0, 0]");
    CHECK(errorOf(materials + "[[disks]]\ncenter = [0, 0, 0]\nradius = 1\nmaterial = \"red\"\n") ==
          "scene.toml:3:1: disks[0]: missing required key \"normal\"");
    CHECK(errorOf(materials + "[[disks]]\ncenter = [0, 0, 0]\nnormal = [0, 1, 0]\nradius = 1\nmaterial = \"red\"\n"
                              "type = \"disk\"\n") ==
          "scene.toml:8:1: disks[0].type: unknown key \"type\" (known: name, center, normal, radius, material)");
}

// [[spheres]] and [[planes]] are registered kinds (src/shapes/sphere.cpp, plane.cpp) read through
// their schema; the words and the order of their checks are the hand-written reader's, as the
// loader printed them before (a material is looked up, not refused as a name; a kind's own keys
// are checked before `name`).
TEST_CASE_FIXTURE(SceneFiles, "spheres and planes are read through their schema with the loader's messages") {
    const std::string materials = "[materials.red]\n[materials.grey]\n";
    CHECK(errorOf(materials + "[[spheres]]\ncenter = [0, 0, 0]\nradius = 1\nmaterial = \"re d\"\n") ==
          "scene.toml:6:12: spheres[0].material: unknown material \"re d\"; did you mean \"red\"? (known: grey, red)");
    CHECK(errorOf(materials + "[[planes]]\npoint = [0, 0, 0]\nnormal = [0, 1, 0]\nmaterial = \"gr ey\"\n") ==
          "scene.toml:6:12: planes[0].material: unknown material \"gr ey\"; did you mean \"grey\"? (known: grey, red)");
    CHECK(errorOf(materials + "[[spheres]]\nname = \"bad name\"\nradius = 1\nmaterial = \"red\"\n") ==
          "scene.toml:3:1: spheres[0]: missing required key \"center\"");
    CHECK(errorOf(materials + "[[planes]]\nname = \"bad name\"\npoint = [0, 0, 0]\nmaterial = \"red\"\n") ==
          "scene.toml:3:1: planes[0]: missing required key \"normal\"");
    CHECK(errorOf(materials + "[[spheres]]\ncenter = [0, 0, 0]\nradius = 1\nradius2 = 1\nmaterial = \"red\"\n") ==
          "scene.toml:6:1: spheres[0].radius2: unknown key \"radius2\"; did you mean \"radius\"?");
    const Scene scene = load(materials + "[[planes]]\npoint = [0, 0, 0]\nnormal = [0, 0, 1e-30]\nmaterial = \"grey\"\n"
                                         "[[spheres]]\nname = \"ball\"\ncenter = [1, 2, 3]\nradius = 0.5\nmaterial = \"red\"\n");
    REQUIRE(scene.spheres.size() == 1);
    REQUIRE(scene.planes.size() == 1);
    CHECK(scene.shapes.empty());
    CHECK(scene.spheres[0].object == 0);  // spheres first, whatever the file's order
    CHECK(scene.planes[0].object == 1);
    CHECK(scene.objects[0].name == "ball");
    CHECK(scene.spheres[0].center == Vec3(1, 2, 3));
    CHECK(scene.spheres[0].radius == 0.5f);
    CHECK(scene.planes[0].normal == Vec3(0, 0, 1));  // normalised in double: 1e-30 squared is 0 in float
}

// [[triangles]] and [[meshes]] are registered kinds (src/shapes/triangle.cpp, mesh.cpp) ranked
// after every other: whatever the file's order, objects run spheres, planes, disks, triangles,
// then each mesh's, and the triangle array holds the triangles before the meshes' faces.
TEST_CASE_FIXTURE(SceneFiles, "objects are numbered spheres, planes, disks, triangles, then meshes") {
    write("two.mtl", "newmtl red\nKd 1 0 0\nnewmtl blue\nKd 0 0 1\n");
    write("two.obj", "mtllib two.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
                     "usemtl blue\nf 1 2 3\nusemtl red\nf 1 2 4\nusemtl blue\nf 1 3 4\n");
    const Scene scene = load("[materials.grey]\n"
                             "[[meshes]]\nfile = \"two.obj\"\n"
                             "[[triangles]]\nname = \"tri\"\nvertices = [[0,0,0], [2,0,0], [0,2,0]]\nmaterial = \"grey\"\n"
                             "[[disks]]\ncenter = [0, 0, 0]\nnormal = [0, 1, 0]\nradius = 1\nmaterial = \"grey\"\n"
                             "[[planes]]\npoint = [0, 0, 0]\nnormal = [0, 1, 0]\nmaterial = \"grey\"\n"
                             "[[spheres]]\ncenter = [0, 0, 0]\nradius = 1\nmaterial = \"grey\"\n");
    REQUIRE(scene.objects.size() == 6);
    CHECK(scene.spheres.at(0).object == 0);
    CHECK(scene.planes.at(0).object == 1);
    CHECK(scene.shapes.at(0).object == 2);
    REQUIRE(scene.triangles.size() == 4);
    CHECK(scene.triangles[0].object == 3);
    CHECK(scene.labelOf(3) == "tri");
    CHECK(scene.triangles[0].b == Vec3(2, 0, 0));
    // The mesh's objects in order of first use: blue (faces 1 and 3), then red.
    CHECK(scene.triangles[1].object == 4);
    CHECK(scene.triangles[2].object == 5);
    CHECK(scene.triangles[3].object == 4);
    CHECK(scene.labelOf(4) == "blue");
    CHECK(scene.labelOf(5) == "red");
}

// A mesh's `scale` is one positive number or three (ParameterType::PerAxis).
TEST_CASE_FIXTURE(SceneFiles, "a mesh's scale is a positive number or 3 positive numbers") {
    write("one.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    const std::string mesh = "[[meshes]]\nfile = \"one.obj\"\n";
    const Scene scene = load(mesh + "scale = [2, 3, 4]\n");
    REQUIRE(scene.triangles.size() == 1);
    CHECK(scene.triangles[0].b == Vec3(2, 0, 0));
    CHECK(scene.triangles[0].c == Vec3(0, 3, 0));
    CHECK(load(mesh + "scale = 5\n").triangles.at(0).c == Vec3(0, 5, 0));
    CHECK(errorOf(mesh + "scale = 0\n") == "scene.toml:3:9: meshes[0].scale: expected a positive number, got 0");
    CHECK(errorOf(mesh + "scale = -2\n") == "scene.toml:3:9: meshes[0].scale: expected a positive number, got -2");
    CHECK(errorOf(mesh + "scale = [1, -1, 1]\n") ==
          "scene.toml:3:13: meshes[0].scale[1]: expected a positive number, got -1");
    CHECK(errorOf(mesh + "scale = \"big\"\n") ==
          "scene.toml:3:9: meshes[0].scale: expected a number or an array of 3 numbers, got a string (\"big\")");
    CHECK(errorOf(mesh + "scale = [1, 2]\n") ==
          "scene.toml:3:9: meshes[0].scale: expected an array of 3 numbers, got an array of 2 elements");
    CHECK(errorOf(mesh + "rotate = 90\n") ==
          "scene.toml:3:1: meshes[0].rotate: unknown key \"rotate\"; did you mean \"rotate_y\"?");
    CHECK(errorOf(mesh + "turn = 90\n") ==
          "scene.toml:3:1: meshes[0].turn: unknown key \"turn\" (known: name, file, material, scale, rotate_y, translate, interior)");
}

// Per-vertex normals are kept one per triangle once any triangle has them: the flat triangles
// before and after a smooth mesh (a quad light's, a flat mesh's) hold zero normals.
TEST_CASE_FIXTURE(SceneFiles, "a smooth mesh's normals line up with the triangles around it") {
    write("flat.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    write("smooth.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 2\nf 1//1 2//1 3//1\n");
    const Scene scene = load("[[lights]]\ntype = \"quad\"\ncorner = [0, 2, 0]\nedge1 = [1, 0, 0]\nedge2 = [0, 0, 1]\n"
                             "radiance = 1\n"
                             "[[meshes]]\nfile = \"flat.obj\"\n"
                             "[[meshes]]\nfile = \"smooth.obj\"\nrotate_y = 90\n"
                             "[[meshes]]\nfile = \"flat.obj\"\n");
    REQUIRE(scene.triangles.size() == 5);
    REQUIRE(scene.triangleNormals.size() == 5);
    for (const int flat : {0, 1, 2, 4}) CHECK(scene.triangleNormals[flat].a == Vec3(0.0f));
    // (0, 0, 1) turned by 90 degrees about y (x towards -z): (1, 0, 0), unit length.
    const Vec3 n = scene.triangleNormals[3].b;
    CHECK(n.x == doctest::Approx(1.0));
    CHECK(n.y == doctest::Approx(0.0));
    CHECK(std::fabs(n.z) < 1e-6f);  // cos 90° in float: -4.4e-8
    CHECK(scene.triangles[3].b.z == doctest::Approx(-1.0));
}

TEST_CASE_FIXTURE(SceneFiles, "media are read through their schema and fill the world and closed objects") {
    const Scene scene = load(
        "[media.fog]\nsigma_s = 0.05\n"
        "[media.smoke]\ntype = \"homogeneous\"\nsigma_a = [0.1, 0.2, 0.3]\nsigma_s = 0.5\ng = -0.4\n"
        "[world]\nmedium = \"fog\"\n"
        "[materials.glass]\nkt = 1\n"
        "[[spheres]]\ncenter = [0, 0, 0]\nradius = 1\nmaterial = \"glass\"\ninterior = \"smoke\"\n"
        "[[spheres]]\ncenter = [3, 0, 0]\nradius = 1\nmaterial = \"glass\"\n");
    REQUIRE(scene.media.size() == 2);
    CHECK(scene.media[0]->name == "fog");
    CHECK(scene.media[1]->name == "smoke");
    const auto& fog = dynamic_cast<const lightpath::HomogeneousMedium&>(*scene.media[0]);
    CHECK(fog.sigmaS == Rgb{0.05f});
    CHECK(fog.sigmaA == Rgb{0.0f});
    CHECK(fog.g == 0.0f);
    const auto& smoke = dynamic_cast<const lightpath::HomogeneousMedium&>(*scene.media[1]);
    CHECK(smoke.sigmaA == Rgb{0.1f, 0.2f, 0.3f});
    CHECK(smoke.g == -0.4f);
    CHECK(scene.worldMedium == 0);
    REQUIRE(scene.objects.size() == 2);
    CHECK(scene.objects[0].interior == 1);
    CHECK(scene.objects[1].interior == lightpath::kNoMedium);
    // No [media]: vacuum everywhere.
    CHECK(load("[world]\nbackground = 1\n").worldMedium == lightpath::kNoMedium);
}

TEST_CASE_FIXTURE(SceneFiles, "every part of a mesh is filled by its interior") {
    // Two materials, so two parts (objects).
    write("box.mtl", "newmtl red\nKd 1 0 0\nnewmtl green\nKd 0 1 0\n");
    write("box.obj", "mtllib box.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
                     "usemtl red\nf 1 3 2\nf 1 2 4\nusemtl green\nf 1 4 3\nf 2 3 4\n");
    const Scene scene = load("[media.fog]\nsigma_s = 1\n[[meshes]]\nfile = \"box.obj\"\ninterior = \"fog\"\n");
    REQUIRE(scene.objects.size() == 2);
    for (const lightpath::SceneObject& part : scene.objects) {
        CHECK(part.interior == 0);
        CHECK(part.enclosesVolume);
    }
}

TEST_CASE_FIXTURE(SceneFiles, "a ray through a sphere enters its interior and through a glass pane stays in the fog") {
    const Scene scene = load(
        "[media.fog]\nsigma_s = 0.05\n[media.smoke]\nsigma_s = 0.5\n[world]\nmedium = \"fog\"\n"
        "[materials.glass]\nkt = 1\n"
        "[[spheres]]\ncenter = [0, 0, 0]\nradius = 1\nmaterial = \"glass\"\ninterior = \"smoke\"\n"
        "[[spheres]]\ncenter = [3, 0, 0]\nradius = 1\nmaterial = \"glass\"\n"
        "[[planes]]\npoint = [0, -1, 0]\nnormal = [0, 1, 0]\nmaterial = \"glass\"\n");
    REQUIRE(scene.objects.size() == 3);
    const std::uint32_t fog = 0, smoke = 1;
    CHECK(scene.mediumBeyond(0, true, fog) == smoke);
    CHECK(scene.mediumBeyond(0, false, smoke) == fog);
    // A sphere without `interior` holds vacuum (glass, not fog).
    CHECK(scene.mediumBeyond(1, true, fog) == lightpath::kNoMedium);
    CHECK(scene.mediumBeyond(1, false, lightpath::kNoMedium) == fog);
    // A plane has no inside: crossing it changes nothing.
    CHECK(scene.mediumBeyond(2, true, fog) == fog);
    CHECK(scene.mediumBeyond(2, false, fog) == fog);
}

TEST_CASE_FIXTURE(SceneFiles, "medium errors are located, with a suggestion when one is close") {
    const std::string media = "[media.fog]\n[media.smoke]\n";
    CHECK(errorOf(media + "[world]\nmedium = \"foggy\"\n") ==
          "scene.toml:4:10: world.medium: unknown medium \"foggy\"; did you mean \"fog\"? (known: fog, smoke)");
    CHECK(errorOf("[world]\nmedium = \"fog\"\n") ==
          "scene.toml:2:10: world.medium: unknown medium \"fog\" (known: none)");
    CHECK(errorOf(media + "[materials.glass]\n[[spheres]]\ncenter = [0, 0, 0]\nradius = 1\nmaterial = \"glass\"\n"
                          "interior = \"smoek\"\n") ==
          "scene.toml:8:12: spheres[0].interior: unknown medium \"smoek\"; did you mean \"smoke\"? "
          "(known: fog, smoke)");
    CHECK(errorOf("[media.fog]\ng = 1\n") == "scene.toml:2:5: media.fog.g: expected a number -1 < x < 1, got 1");
    CHECK(errorOf("[media.fog]\ng = -1.5\n") == "scene.toml:2:5: media.fog.g: expected a number -1 < x < 1, got -1.5");
    CHECK(errorOf("[media.fog]\nsigma_s = [0.1, -0.2, 0]\n") ==
          "scene.toml:2:17: media.fog.sigma_s[1]: expected a number >= 0, got -0.2");
    CHECK(errorOf("[media.fog]\nsigma_t = 1\n") ==
          "scene.toml:2:1: media.fog.sigma_t: unknown key \"sigma_t\"; did you mean \"sigma_a\"?");
    CHECK(errorOf("[media.fog]\ntype = \"homogenous\"\n") ==
          "scene.toml:2:8: media.fog.type: unknown medium type \"homogenous\"; did you mean \"homogeneous\"? "
          "(known: homogeneous)");
    // Only a closed shape has an inside.
    CHECK(errorOf(media + "[materials.grey]\n[[planes]]\npoint = [0, 0, 0]\nnormal = [0, 1, 0]\n"
                          "material = \"grey\"\ninterior = \"fog\"\n")
              .starts_with("scene.toml:8:1: planes[0].interior: unknown key \"interior\""));
}
