// The glTF reader (shapes/gltf_loader.h) as the scene loader uses it: a .gltf file as the scene,
// and [[gltf]] in a TOML scene with its placement, label and material overrides. The files are
// tests/render/data/gltf/ (made by make_gltf.py there); the expected values are worked out by hand
// in that folder's TOML scenes.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

#include "lights/point_light.h"
#include "materials/dielectric_material.h"
#include "materials/microfacet_material.h"
#include "materials/phong_material.h"
#include "media/homogeneous_medium.h"
#include "scene/scene_loader.h"

#include "../support/temp_folder.h"

namespace {

namespace fs = std::filesystem;
using namespace lightpath;

const fs::path kData = fs::path(LIGHTPATH_SOURCE_DIR) / "tests/render/data/gltf";

bool hasObject(const Scene& scene, const std::string& label) {
    for (std::uint32_t i = 0; i < scene.objects.size(); ++i)
        if (scene.labelOf(i) == label) return true;
    return false;
}

bool warns(const Scene& scene, const std::string& part) {
    return std::any_of(scene.warnings.begin(), scene.warnings.end(),
                       [&](const std::string& w) { return w.find(part) != std::string::npos; });
}

std::string errorOf(const fs::path& file) {
    try {
        loadScene(file);
    } catch (const SceneError& e) {
        return e.what();
    }
    return "no error";
}

TEST_CASE("a glTF file as the scene: its nodes placed, its camera, its light in W/sr, names as labels") {
    const Scene scene = loadScene(kData / "point.gltf");
    CHECK(scene.cameraGiven);
    CHECK(scene.camera.eye.y == doctest::Approx(2.0));
    CHECK(scene.camera.eye.z == doctest::Approx(5.0));
    // Looking down by 20 degrees: the camera node's -z turned about x.
    const Vec3 forward = glm::normalize(scene.camera.lookAt - scene.camera.eye);
    CHECK(forward.y == doctest::Approx(-0.3420201).epsilon(1e-5));
    CHECK(forward.z == doctest::Approx(-0.9396926).epsilon(1e-5));
    CHECK(scene.camera.verticalFovDegrees == doctest::Approx(40.107046).epsilon(1e-5));
    CHECK(scene.camera.width == 640);

    REQUIRE(scene.lights.size() == 1);
    const PointLight& lamp = pointLightOf(scene.lights[0]);
    CHECK(lamp.name == "Lamp");
    CHECK(lamp.location.x == doctest::Approx(-0.5));
    CHECK(lamp.location.y == doctest::Approx(2.5));
    CHECK(kPi * lamp.intensity.r == doctest::Approx(20.0));  // 13,660 cd read as 13,660 / 683 = 20 W/sr
    CHECK(lamp.attenuationAt(2.0f) == doctest::Approx(0.25));  // physical 1/d^2

    // Material "Floor Paint" is labelled Floor_Paint, and says so.
    CHECK(std::any_of(scene.materials.begin(), scene.materials.end(),
                      [](const MaterialSlot& m) { return m->name == "Floor_Paint"; }));
    CHECK(warns(scene, "materials[0] \"Floor Paint\" is labelled \"Floor_Paint\" in light paths"));
    CHECK(hasObject(scene, "Floor"));
    CHECK(hasObject(scene, "Panel"));

    // The panel (unit quad, halved, turned 90 degrees about y, moved by (1, 0, 0) then (0, 1, -1))
    // lies in the plane x = 1 between y 0.5 and 1.5, z -1.5 and -0.5.
    REQUIRE(scene.triangles.size() == 4);
    for (const Triangle& t : {scene.triangles[2], scene.triangles[3]})
        for (const Vec3& corner : {t.a, t.b, t.c}) {
            CHECK(corner.x == doctest::Approx(1.0));
            CHECK(((corner.y == doctest::Approx(0.5)) || (corner.y == doctest::Approx(1.5))));
            CHECK(((corner.z == doctest::Approx(-0.5)) || (corner.z == doctest::Approx(-1.5))));
        }
    // Vertex normals turned like the node: +z becomes +x.
    REQUIRE(scene.triangleNormals.size() == 4);
    CHECK(scene.triangleNormals[2].a.x == doctest::Approx(1.0));
}

TEST_CASE("a glTF emissive material emits its emissiveFactor times its emissive strength") {
    const Scene scene = loadScene(kData / "emissive.gltf");
    const auto glow = std::find_if(scene.materials.begin(), scene.materials.end(),
                                   [](const MaterialSlot& m) { return m->name == "Glow"; });
    REQUIRE(glow != scene.materials.end());
    CHECK((*glow)->emission.constant().r == doctest::Approx(5.0));
    CHECK((*glow)->emission.constant().g == doctest::Approx(4.5));
    CHECK((*glow)->emission.constant().b == doctest::Approx(4.0));
}

TEST_CASE("a rough glTF transmitting material is the rough dielectric, a smooth one the Fresnel glass") {
    std::ifstream in(kData / "emissive.gltf");
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string panel = "\"metallicFactor\": 1,\n    \"roughnessFactor\": 0.3\n   }";
    REQUIRE(text.find(panel) != std::string::npos);
    const test::TempFolder temp("lightpath-gltf-glass");
    for (const char* roughness : {"0.3", "0"}) {
        std::string glass = text;
        glass.replace(glass.find(panel), panel.size(),
                      std::string("\"metallicFactor\": 0, \"roughnessFactor\": ") + roughness +
                          "}, \"extensions\": {\"KHR_materials_transmission\": {\"transmissionFactor\": 1}, "
                          "\"KHR_materials_ior\": {\"ior\": 1.4}}");
        const fs::path file = temp.path() / (std::string("glass-") + roughness + ".gltf");
        std::ofstream(file) << glass;
        const Scene scene = loadScene(file);
        const auto it = std::find_if(scene.materials.begin(), scene.materials.end(),
                                     [](const MaterialSlot& m) { return m->name == "Panel"; });
        REQUIRE(it != scene.materials.end());
        CAPTURE(roughness);
        if (std::string(roughness) == "0") {
            const auto* smooth = dynamic_cast<const PhongMaterial*>(&**it);
            REQUIRE(smooth != nullptr);
            CHECK(smooth->fresnel);
            CHECK(smooth->ior == doctest::Approx(1.4));
        } else {
            const auto* rough = dynamic_cast<const DielectricMaterial*>(&**it);
            REQUIRE(rough != nullptr);
            CHECK(rough->roughness() == doctest::Approx(0.3));
            CHECK(rough->ior() == doctest::Approx(1.4));
            CHECK(rough->tint().constant().g == doctest::Approx(0.9));
            CHECK(!warns(scene, "roughness"));
        }
    }
}

TEST_CASE("[[gltf]] in a TOML scene: placed, relabelled, in a scene material, its camera yielding to [camera]") {
    const test::TempFolder temp("lightpath-gltf-test");
    const fs::path& folder = temp.path();
    fs::copy_file(kData / "point.gltf", folder / "point.gltf", fs::copy_options::overwrite_existing);
    std::ofstream(folder / "scene.toml") << "[camera]\neye = [0, 0, 9]\n"
                                            "[materials]\nchalk = { kd = 0.5 }\n"
                                            "[[gltf]]\nfile = \"point.gltf\"\nname = \"model\"\nmaterial = \"chalk\"\n"
                                            "translate = [10, 0, 0]\nlights = false\n";
    const Scene scene = loadScene(folder / "scene.toml");
    CHECK(scene.camera.eye.z == doctest::Approx(9.0));
    CHECK(scene.lights.empty());
    REQUIRE(scene.objects.size() == 1);
    CHECK(scene.labelOf(0) == "model");
    CHECK(scene.materials[scene.objects[0].material]->name == "chalk");
    for (const Triangle& t : scene.triangles) CHECK(t.a.x >= 8.0f);
}

// Blender's glTF exporter writes a lamp of P watts as P / (4 pi) * 683 cd ("Standard", its default),
// P / (4 pi) ("Unitless") or P ("Raw"), and a sun of E W/m^2 as 683 E lux, E or E
// (io_scene_gltf2's gather_lights): `lighting` reads each back as W/sr and W/m^2 (the sun's
// modes: tests/render/test_gltf.cpp).
TEST_CASE("[[gltf]] lighting: the file's light intensities read as Blender's glTF exporter writes them") {
    const test::TempFolder temp("lightpath-gltf-lighting");
    const fs::path& folder = temp.path();
    fs::copy_file(kData / "point.gltf", folder / "point.gltf", fs::copy_options::overwrite_existing);
    const auto loaded = [&](const std::string& lighting) {
        std::ofstream(folder / "scene.toml") << "[[gltf]]\nfile = \"point.gltf\"\n"
                                             << (lighting.empty() ? "" : "lighting = \"" + lighting + "\"\n");
        return loadScene(folder / "scene.toml");
    };
    const auto pointWattsPerSr = [&](const std::string& lighting) {
        const Scene scene = loaded(lighting);
        REQUIRE(scene.lights.size() == 1);
        return double(kPi * pointLightOf(scene.lights[0]).intensity.r);
    };
    // point.gltf's lamp: 13,660 in the file.
    CHECK(pointWattsPerSr("") == doctest::Approx(20.0));  // standard, the default
    CHECK(pointWattsPerSr("standard") == doctest::Approx(20.0));
    CHECK(pointWattsPerSr("unitless") == doctest::Approx(13660.0));
    CHECK(pointWattsPerSr("raw") == doctest::Approx(13660.0 / (4.0 * 3.14159265358979)));
    std::string error;
    try {
        loaded("photometric");
    } catch (const SceneError& e) {
        error = e.what();
    }
    CHECK(error.find("lighting") != std::string::npos);
    CHECK(error.find("expected \"standard\", \"unitless\" or \"raw\" (Blender's glTF Lighting Mode), got "
                     "\"photometric\"") != std::string::npos);
}

TEST_CASE("a glTF file requiring an extension lightpath does not read is refused; one merely using it warns") {
    const test::TempFolder temp("lightpath-gltf-extensions");
    const fs::path& folder = temp.path();
    std::ifstream in(kData / "point.gltf");
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string used = "\"extensionsUsed\": [";
    REQUIRE(text.find(used) != std::string::npos);
    const auto variant = [&](const std::string& name, const std::string& extra) {
        std::string changed = text;
        changed.replace(changed.find(used), used.size(), used + "\"KHR_draco_mesh_compression\", ");
        changed.insert(changed.find('{') + 1, extra);
        std::ofstream(folder / name) << changed;
        return folder / name;
    };
    // Required: the meshes may live in the extension, so the file cannot be read as meant.
    const fs::path required = variant("required.gltf", "\"extensionsRequired\": [\"KHR_draco_mesh_compression\"],");
    CHECK(errorOf(required) == required.string() +
                                   ": extensionsRequired[0]: the file requires \"KHR_draco_mesh_compression\", which "
                                   "lightpath does not read (it reads KHR_lights_punctual, KHR_materials_clearcoat, "
                                   "KHR_materials_emissive_strength, KHR_materials_ior, KHR_materials_specular, "
                                   "KHR_materials_transmission, KHR_materials_volume, KHR_mesh_quantization, "
                                   "KHR_texture_transform)");
    // Used only: rendered, the extension named in a warning; the ones it reads are not.
    const Scene scene = loadScene(variant("used.gltf", ""));
    CHECK(warns(scene, "extensionsUsed: KHR_draco_mesh_compression is not read by lightpath: the render leaves it out"));
    CHECK(!warns(scene, "KHR_lights_punctual"));
    CHECK(scene.lights.size() == 1);
}

TEST_CASE("a glTF file's animations, skins and morph targets, which a still render leaves out, are named in warnings") {
    const test::TempFolder temp("lightpath-gltf-unread");
    std::ifstream in(kData / "point.gltf");
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const auto variant = [&](const std::string& file, const std::string& from, const std::string& to) {
        std::string changed = text;
        REQUIRE(changed.find(from) != std::string::npos);
        changed.replace(changed.find(from), from.size(), to);
        std::ofstream(temp.path() / file) << changed;
        return loadScene(temp.path() / file);
    };
    CHECK(warns(variant("skin.gltf", "{", "{ \"skins\": [{\"joints\": [0]}],"),
                "skin.gltf: skins: not applied: a skinned mesh renders as its vertices stand, placed by its node"));
    CHECK(warns(variant("morph.gltf", "\"attributes\": {", "\"targets\": [{\"POSITION\": 0}], \"attributes\": {"),
                "morph.gltf: meshes[0]: morph targets are not applied: the mesh renders without them"));
    CHECK(warns(variant("animated.gltf", "{",
                        "{ \"animations\": [{\"channels\": [{\"sampler\": 0, \"target\": {\"node\": 0, \"path\": "
                        "\"translation\"}}], \"samplers\": [{\"input\": 0, \"output\": 0}]}],"),
                "animated.gltf: animations: 1 animation is not played: the scene renders as its nodes stand"));
    const Scene plain = loadScene(kData / "point.gltf");
    CHECK(!warns(plain, "skins"));
    CHECK(!warns(plain, "morph"));
    CHECK(!warns(plain, "animation"));
}

TEST_CASE("a glTF material's alphaMode and alphaCutoff become its alpha; a bad one is a located error") {
    const test::TempFolder temp("lightpath-gltf-alpha");
    std::ifstream in(kData / "point.gltf");
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string name = "\"name\": \"Floor Paint\"";
    REQUIRE(text.find(name) != std::string::npos);
    const auto variant = [&](const std::string& file, const std::string& extra) {
        std::string changed = text;
        changed.replace(changed.find(name), name.size(), name + ", " + extra);
        std::ofstream(temp.path() / file) << changed;
        return temp.path() / file;
    };
    const auto floorAlpha = [](const Scene& scene) {
        for (const MaterialSlot& m : scene.materials)
            if (m->name == "Floor_Paint") return m->alpha;
        FAIL("no Floor_Paint");
        return std::shared_ptr<const Alpha>();
    };
    // Its baseColorFactor's alpha is 1 (no texture): MASK at the default cutoff 0.5 and BLEND
    // keep every point, so nothing is cut out; a cutoff above 1 cuts out everything.
    CHECK(floorAlpha(loadScene(kData / "point.gltf")) == nullptr);
    CHECK(floorAlpha(loadScene(variant("mask.gltf", "\"alphaMode\": \"MASK\""))) == nullptr);
    CHECK(floorAlpha(loadScene(variant("blend.gltf", "\"alphaMode\": \"BLEND\""))) == nullptr);
    const auto all = floorAlpha(loadScene(variant("high.gltf", "\"alphaMode\": \"MASK\", \"alphaCutoff\": 1.5")));
    REQUIRE(all != nullptr);
    CHECK_FALSE(all->covers({0.3f, 0.6f}, 1.0f, 0.0f));
    CHECK(floorAlpha(loadScene(variant("opaque.gltf", "\"alphaMode\": \"OPAQUE\", \"alphaCutoff\": 1.5"))) == nullptr);
    const fs::path clip = variant("clip.gltf", "\"alphaMode\": \"CLIP\"");
    CHECK(errorOf(clip) == clip.string() + ": materials[0].alphaMode: expected OPAQUE, MASK or BLEND, got \"CLIP\"");
    const fs::path negative = variant("negative.gltf", "\"alphaMode\": \"MASK\", \"alphaCutoff\": -1");
    CHECK(errorOf(negative).find(negative.string() + ": materials[0].alphaCutoff: expected") == 0);
}

// KHR_materials_ior's n gives F0 = ((n - 1)/(n + 1))^2, KHR_materials_specular's specularColorFactor
// tints it; Blender writes F0 = 0.08 * its Principled specular that way (0 in make_blender.py).
TEST_CASE("a glTF dielectric's F0: from KHR_materials_ior and KHR_materials_specular, as Blender writes them") {
    const auto f0Of = [](const Scene& scene, const std::string& name) {
        for (const MaterialSlot& m : scene.materials)
            if (m->name == name) {
                const auto* microfacet = dynamic_cast<const MicrofacetMaterial*>(&*m);
                REQUIRE(microfacet != nullptr);
                return microfacet->dielectricF0();
            }
        FAIL("no material " << name);
        return Rgb{0.0f};
    };
    CHECK(f0Of(loadScene(kData / "point.gltf"), "Floor_Paint") == Rgb{0.04f});  // neither: n = 1.5
    const Scene blender = loadScene(kData / "blender" / "point.glb");
    CHECK(f0Of(blender, "White") == Rgb{0.0f});  // specular 0: specularColorFactor [0, 0, 0], n 1.45
    const test::TempFolder temp("lightpath-gltf-f0");
    std::ifstream in(kData / "point.gltf");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string name = "\"name\": \"Floor Paint\"";
    text.replace(text.find(name), name.size(),
                 name + ", \"extensions\": {\"KHR_materials_ior\": {\"ior\": 2}, \"KHR_materials_specular\": "
                        "{\"specularColorFactor\": [0.5, 1, 20]}}");
    std::ofstream(temp.path() / "f0.gltf") << text;
    const Rgb f0 = f0Of(loadScene(temp.path() / "f0.gltf"), "Floor_Paint");
    CHECK(f0.r == doctest::Approx(0.5 / 9.0));
    CHECK(f0.g == doctest::Approx(1.0 / 9.0));
    CHECK(f0.b == doctest::Approx(1.0));  // 20 / 9, clamped
}

// KHR_materials_clearcoat: clearcoatFactor and clearcoatRoughnessFactor (each 0..1, default 0) make
// the microfacet material's coat; 0 is none. Its normal map and a transmitting material's coat are
// not read, each said in a warning.
TEST_CASE("a glTF material's KHR_materials_clearcoat is its clear coat; a bad factor is a located error") {
    const test::TempFolder temp("lightpath-gltf-clearcoat");
    std::ifstream in(kData / "point.gltf");
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string name = "\"name\": \"Floor Paint\"";
    REQUIRE(text.find(name) != std::string::npos);
    const auto variant = [&](const std::string& file, const std::string& extensions) {
        std::string changed = text;
        changed.replace(changed.find(name), name.size(), name + ", \"extensions\": {" + extensions + "}");
        std::ofstream(temp.path() / file) << changed;
        return temp.path() / file;
    };
    const auto paint = [](const Scene& scene) -> const MicrofacetMaterial& {
        for (const MaterialSlot& m : scene.materials)
            if (m->name == "Floor_Paint") return dynamic_cast<const MicrofacetMaterial&>(*m);
        throw std::runtime_error("no Floor_Paint");
    };
    const Scene coated = loadScene(
        variant("coat.gltf", "\"KHR_materials_clearcoat\": {\"clearcoatFactor\": 0.6, \"clearcoatRoughnessFactor\": 0.3}"));
    const MicrofacetMaterial& coat = paint(coated);
    CHECK(coat.coated());
    CHECK(coat.has(MicrofacetMaterial::kCoatGlossy));
    // The same coat as the TOML keys make it.
    const MicrofacetMaterial expected(Rgb{0.8f, 0.6f, 0.4f}, 0.0f, 0.6f, Rgb{MicrofacetMaterial::kDielectricF0},
                                      {0.6f, 0.3f});
    for (const float c : {0.9f, 0.5f, 0.2f}) CHECK(coat.coatAlbedo(c) == expected.coatAlbedo(c));
    CHECK(!warns(coated, "KHR_materials_clearcoat"));
    CHECK(!paint(loadScene(variant("zero.gltf", "\"KHR_materials_clearcoat\": {\"clearcoatRoughnessFactor\": 0.3}"))).coated());
    CHECK(warns(loadScene(variant("normal.gltf", "\"KHR_materials_clearcoat\": {\"clearcoatFactor\": 1, "
                                                 "\"clearcoatNormalTexture\": {\"index\": 0}}")),
                "materials[0].extensions.KHR_materials_clearcoat.clearcoatNormalTexture is not read"));
    CHECK(warns(loadScene(variant("glass.gltf", "\"KHR_materials_clearcoat\": {\"clearcoatFactor\": 1}, "
                                                "\"KHR_materials_transmission\": {\"transmissionFactor\": 1}")),
                "materials[0].extensions.KHR_materials_clearcoat: a transmitting material is rendered without"));
    const fs::path bad = variant("bad.gltf", "\"KHR_materials_clearcoat\": {\"clearcoatFactor\": 1.5}");
    CHECK(errorOf(bad) == bad.string() + ": materials[0].extensions.KHR_materials_clearcoat.clearcoatFactor: "
                                         "expected a number from 0 to 1, got 1.5");
    const fs::path texture = variant("texture.gltf", "\"KHR_materials_clearcoat\": {\"clearcoatFactor\": 1, "
                                                     "\"clearcoatTexture\": {\"index\": -2}}");
    CHECK(errorOf(texture) == texture.string() + ": materials[0].extensions.KHR_materials_clearcoat.clearcoatTexture"
                                                 ".index: expected a texture index of 0 or more");
}

// KHR_materials_volume (volume.gltf, a glass cube): the object of a transmitting material with a
// thickness and a finite attenuationDistance bounds a medium that absorbs -ln(attenuationColor) /
// attenuationDistance per channel and scatters nothing, named after the material. A thin wall, an
// opaque material or an infinite distance bound none; a TOML `interior` replaces the file's.
TEST_CASE("a glTF material's KHR_materials_volume makes its object bound an absorbing medium; bad values are located errors") {
    const test::TempFolder temp("lightpath-gltf-volume");
    std::ifstream in(kData / "volume.gltf");
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string key = "\"KHR_materials_volume\": {";
    const auto begin = text.find(key);
    REQUIRE(begin != std::string::npos);
    const auto end = text.find('}', begin) + 1;
    // volume.gltf with the material's extension object replaced by {`body`}, and `from` by `to`.
    const auto variant = [&](const std::string& file, const std::string& body, const std::string& from = "",
                             const std::string& to = "") {
        std::string changed = text;
        changed.replace(begin, end - begin, key + body + "}");
        if (!from.empty()) {
            REQUIRE(changed.find(from) != std::string::npos);
            changed.replace(changed.find(from), from.size(), to);
        }
        std::ofstream(temp.path() / file) << changed;
        return temp.path() / file;
    };
    const std::string tinted = "\"thicknessFactor\": 1, \"attenuationDistance\": 0.5, \"attenuationColor\": ";
    const Scene scene = loadScene(kData / "volume.gltf");
    REQUIRE(scene.media.size() == 1);
    REQUIRE(scene.objects.size() == 1);
    CHECK(scene.objects[0].enclosesVolume);
    CHECK(scene.objects[0].interior == 0);
    const auto& medium = dynamic_cast<const HomogeneousMedium&>(*scene.media[0]);
    CHECK(medium.name == "Tinted_Glass");
    CHECK(medium.sigmaA.r == doctest::Approx(-std::log(0.8) / 0.5).scale(0).epsilon(1e-6));
    CHECK(medium.sigmaA.g == doctest::Approx(-std::log(0.5) / 0.5).scale(0).epsilon(1e-6));
    CHECK(medium.sigmaA.b == 0.0f);
    CHECK(!std::signbit(medium.sigmaA.b));
    CHECK(isBlack(medium.sigmaS));
    CHECK(!medium.scatters());
    CHECK(!warns(scene, "KHR_materials_volume"));

    CHECK(loadScene(variant("same.gltf", tinted + "[0.8, 0.5, 1]")).media.size() == 1);
    CHECK(loadScene(variant("thin.gltf", "\"attenuationDistance\": 0.5, \"attenuationColor\": [0.8, 0.5, 1]")).media.empty());
    CHECK(loadScene(variant("infinite.gltf", "\"thicknessFactor\": 1, \"attenuationColor\": [0.8, 0.5, 1]")).media.empty());
    CHECK(loadScene(variant("opaque.gltf", tinted + "[0.8, 0.5, 1]", "\"transmissionFactor\": 1", "\"transmissionFactor\": 0"))
              .media.empty());
    // A channel that keeps nothing absorbs as much as a scene's number may say.
    const Scene black = loadScene(variant("black.gltf", tinted + "[0, 0.5, 1]"));
    REQUIRE(black.media.size() == 1);
    CHECK(dynamic_cast<const HomogeneousMedium&>(*black.media[0]).sigmaA.r == float(kMaxMagnitude));

    // A scene's interior fills the model instead, and the file's medium is not added.
    std::ofstream(temp.path() / "fog.toml") << "[media.fog]\ntype = \"homogeneous\"\nsigma_s = 0.5\n"
                                               "[[gltf]]\nfile = \"" + (kData / "volume.gltf").string() +
                                                   "\"\ninterior = \"fog\"\n";
    const Scene fog = loadScene(temp.path() / "fog.toml");
    REQUIRE(fog.media.size() == 1);
    CHECK(fog.media[0]->name == "fog");
    CHECK(fog.objects[0].interior == 0);

    const fs::path zero = variant("zero.gltf", "\"thicknessFactor\": 1, \"attenuationDistance\": 0");
    CHECK(errorOf(zero) == zero.string() + ": materials[0].extensions.KHR_materials_volume.attenuationDistance: "
                                           "expected a number above 0 and at most 1e6, got 0");
    const fs::path bright = variant("bright.gltf", tinted + "[1.5, 0.5, 1]");
    CHECK(errorOf(bright) == bright.string() + ": materials[0].extensions.KHR_materials_volume.attenuationColor: "
                                               "expected three numbers from 0 to 1");
    const fs::path two = variant("two.gltf", tinted + "[0.8, 0.5]");
    CHECK(errorOf(two) == two.string() + ": materials[0].extensions.KHR_materials_volume.attenuationColor: "
                                         "expected three numbers from 0 to 1");
    const fs::path negative = variant("negative.gltf", "\"thicknessFactor\": -1");
    CHECK(errorOf(negative).find(negative.string() + ": materials[0].extensions.KHR_materials_volume.thicknessFactor: "
                                                     "expected a number from 0") == 0);
}

// glTF 2.0, 3.10.3: an orthographic camera's xmag and ymag are half its view's width and height.
TEST_CASE("a glTF orthographic camera is the scene's orthographic camera: ymag half its height, xmag / ymag its aspect") {
    const test::TempFolder temp("lightpath-gltf-orthographic");
    std::ifstream in(kData / "point.gltf");
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const auto variant = [&](const std::string& file, const std::string& projection) {
        std::string changed = text;
        const std::string from = "\"type\": \"perspective\",";
        REQUIRE(changed.find(from) != std::string::npos);
        changed.replace(changed.find(from), from.size(), "\"type\": \"orthographic\", " + projection + ",");
        std::ofstream(temp.path() / file) << changed;
        return temp.path() / file;
    };
    const Scene scene = loadScene(variant("ortho.gltf", "\"orthographic\": {\"xmag\": 2, \"ymag\": 1.5, \"znear\": 0.1, "
                                                        "\"zfar\": 100}"));
    CHECK(scene.camera.projection == Projection::Orthographic);
    CHECK(scene.camera.orthographicHeight == 3.0f);
    CHECK(scene.camera.height == 480);
    CHECK(scene.camera.width == 640);
    CHECK(!warns(scene, "camera"));
    const fs::path flat = variant("flat.gltf", "\"orthographic\": {\"xmag\": 2, \"ymag\": 0, \"znear\": 0.1, \"zfar\": 100}");
    CHECK(errorOf(flat).find(flat.string() + ": cameras[0].orthographic.ymag: expected a number from") == 0);
}

TEST_CASE("sparse accessors: elements substituted over a bufferView or over zeros; indices out of order refused") {
    const Scene scene = loadScene(kData / "sparse.gltf");
    REQUIRE(scene.triangles.size() == 3);
    // The kite: the quad (-1, -1)..(1, 1) with corner 2 moved to (2, 2); indices 0 1 2, 0 2 3.
    CHECK(scene.triangles[0].c == Vec3(2, 2, 0));
    CHECK(scene.triangles[1].b == Vec3(2, 2, 0));
    CHECK(scene.triangles[1].c == Vec3(-1, 1, 0));
    // The corner from zeros, moved by its node to z = -1.
    CHECK(scene.triangles[2].a == Vec3(0, 0, -1));
    CHECK(scene.triangles[2].b == Vec3(1, 0, -1));
    CHECK(scene.triangles[2].c == Vec3(0, 1, -1));
    CHECK(errorOf(kData / "bad_sparse.gltf") ==
          (kData / "bad_sparse.gltf").string() +
              ": meshes[0].primitives[0].attributes.POSITION: accessor 0: sparse.indices: index 1 is 2; expected "
              "indices increasing strictly, below 4");
}

TEST_CASE("a malformed glTF file is refused naming the file, the element and what was expected") {
    CHECK(errorOf(kData / "bad_index.gltf") ==
          (kData / "bad_index.gltf").string() +
              ": meshes[0].primitives[0].indices: index 5 is 7, but there are 4 vertices");
    const test::TempFolder temp("lightpath-gltf-bad");
    const fs::path& folder = temp.path();
    std::ofstream(folder / "syntax.gltf") << "{\"asset\": {\"version\": \"2.0\"}, \"nodes\": [";
    CHECK(errorOf(folder / "syntax.gltf").rfind((folder / "syntax.gltf").string() + ": cannot read glTF file: ", 0) == 0);
}

TEST_CASE("a glTF texture's texCoord names a TEXCOORD_n every primitive of its material has, as VEC2, one per position") {
    // textured-texcoord1.gltf's baseColorTexture names texCoord 1; its image beside the copies.
    const test::TempFolder temp("lightpath-gltf-texcoord");
    const fs::path& folder = temp.path();
    fs::copy_file(kData / "checker4.png", folder / "checker4.png");
    std::ifstream in(kData / "textured-texcoord1.gltf");
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const auto variant = [&](const std::string& name, const std::string& from, const std::string& to) {
        std::string changed = text;
        const std::size_t at = changed.find(from);
        REQUIRE(at != std::string::npos);
        changed.replace(at, from.size(), to);
        std::ofstream(folder / name) << changed;
        return folder / name;
    };
    const fs::path missing = variant("missing.gltf", "\"TEXCOORD_1\"", "\"TEXCOORD_7\"");
    CHECK(errorOf(missing) == missing.string() + ": meshes[0].primitives[0].attributes: expected a TEXCOORD_1 "
                                                 "accessor: material 0's textures name texCoord 1");
    const fs::path vec3 = variant("vec3.gltf", "\"TEXCOORD_1\": 3", "\"TEXCOORD_1\": 1");
    CHECK(errorOf(vec3) == vec3.string() + ": meshes[0].primitives[0].attributes.TEXCOORD_1: accessor 1: expected type VEC2");
    const fs::path negative = variant("negative.gltf", "\"texCoord\": 1", "\"texCoord\": -1");
    CHECK(errorOf(negative) == negative.string() + ": materials[0].pbrMetallicRoughness.baseColorTexture.texCoord: "
                                                   "expected a set from 0 to 31, got -1");
    const fs::path tangent = variant("tangent.gltf", "\"TEXCOORD_1\": 3", "\"TEXCOORD_1\": 3, \"TANGENT\": 2");
    CHECK(errorOf(tangent) == tangent.string() + ": meshes[0].primitives[0].attributes.TANGENT: accessor 2: expected type VEC4");
}

}  // namespace
