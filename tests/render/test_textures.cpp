// Textures (materials/texture.h): a checkerboard written by the test (OpenImageIO through the image
// module), lit by the ambient term alone so that a pixel is ka exactly (ka Ia, Ia = 1). Far away
// the filtered texture renders the checks' average like a supersampled render, where point
// sampling aliases; up close each pixel is its texel; an OBJ's map_Kd shows its checks; a file
// that cannot be read is an error located at its key; the AOVs still sum. An 8-bit texel reads
// through sRGB's EOTF unless it is said to be linear; wrap modes pick the texels outside [0, 1].
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "film/aov_presets.h"
#include "film/aov_set.h"
#include "io/image_codec.h"
#include "io/png_file.h"
#include "materials/microfacet_material.h"
#include "render/renderer.h"
#include "scene/scene_loader.h"
#include "../support/film_checks.h"
#include "../support/temp_folder.h"

namespace lightpath {
namespace {

constexpr int kTexels = 64;  // the image's side
constexpr int kCheck = 8;    // texels per check: 8 x 8 checks, black at texel (0, 0)

// The checkerboard's value at texel (i, j): 0 or 1.
float checkAt(int i, int j) { return float(((i / kCheck) + (j / kCheck)) % 2); }

// The checkerboard as an 8-bit PNG (0 and 255: 0 and 1 exactly), written once per test process
// into a folder of its own that goes when the process ends.
class CheckerboardFile {
public:
    CheckerboardFile() {
        std::vector<unsigned char> pixels;
        for (int j = 0; j < kTexels; ++j)
            for (int i = 0; i < kTexels; ++i)
                for (int c = 0; c < 3; ++c) pixels.push_back(checkAt(i, j) > 0.0f ? 255 : 0);
        ImageFileSpec spec;
        spec.width = spec.height = kTexels;
        spec.channelNames = {"R", "G", "B"};
        error_ = writePngFile(path(), spec, pixels.data(), {});
    }

    std::filesystem::path path() const { return folder_.path() / "checker.png"; }
    const std::string& error() const { return error_; }

private:
    test::TempFolder folder_{"lightpath-texture-tests"};
    std::string error_;
};

std::filesystem::path checkerboard() {
    static const CheckerboardFile file;
    REQUIRE(file.error().empty());
    return file.path();
}

// A plane y = 0 seen from `eye` towards `lookAt`, ka the checkerboard repeated once per
// `repeat` metres, lit by Ia = 1 alone.
std::string floorScene(const std::string& texture, const char* eye, const char* lookAt, const char* up, float repeat,
                       bool filtered) {
    return "[world]\nambient = 1\n[camera]\neye = " + std::string(eye) + "\nlook_at = " + lookAt + "\nup = " + up +
           "\nfov = 40\nresolution = [96, 72]\n[materials.floor]\nka = { texture = \"" + texture +
           "\", uv_scale = " + std::to_string(1.0f / repeat) + ", filter = " + (filtered ? "true" : "false") +
           " }\n[[planes]]\npoint = [0, 0, 0]\nnormal = [0, 1, 0]\nmaterial = \"floor\"\n";
}

Film renderBeauty(const Scene& scene, int samplesPerPixel) {
    const AovSet aovs(classesSet());
    RenderOptions options;
    options.integrator = "raycast";
    options.samplesPerPixel = samplesPerPixel;
    return Renderer(scene, aovs, options).render().film;
}

// The pixels (their centres) whose ray meets the floor farther than `distance` from the eye.
std::vector<std::pair<int, int>> floorPixelsBeyond(const Scene& scene, float distance) {
    const Camera camera(scene.camera);
    std::vector<std::pair<int, int>> pixels;
    for (int y = 0; y < camera.height(); ++y)
        for (int x = 0; x < camera.width(); ++x) {
            const Ray ray = camera.generateRay(float(x) + 0.5f, float(y) + 0.5f);
            const float t = -ray.origin.y / ray.direction.y;
            if (t > distance && std::isfinite(t)) pixels.emplace_back(x, y);
        }
    return pixels;
}

double rmse(const Film& a, const Film& b, const std::vector<std::pair<int, int>>& pixels) {
    double sum = 0.0;
    for (const auto& [x, y] : pixels) {
        const double d = double(a.at(0, x, y).g) - double(b.at(0, x, y).g);
        sum += d * d;
    }
    return std::sqrt(sum / double(pixels.size()));
}

}  // namespace

TEST_CASE("textures: far away a filtered checkerboard renders its average, as a supersampled render does") {
    const std::string texture = checkerboard().string();
    // The eye 1 m above the floor, looking at the horizon: checks 0.5 m wide (4 m per repeat).
    const auto scene = [&](bool filtered) {
        return loadSceneFromText(floorScene(texture, "[0, 1, 0]", "[0, 0.8, -10]", "[0, 1, 0]", 4.0f, filtered),
                                 "far.toml");
    };
    const Scene filteredScene = scene(true), pointScene = scene(false);
    // Beyond 15 m one pixel spans several checks in depth (its footprint there is about 0.15 m
    // across and 2.3 m deep); that is where point sampling aliases.
    const std::vector<std::pair<int, int>> far = floorPixelsBeyond(filteredScene, 15.0f);
    REQUIRE(far.size() > 300);
    // The reference: point sampled, 256 jittered samples in each pixel (the box filter's average).
    const Film reference = renderBeauty(pointScene, 256);
    const Film filtered = renderBeauty(filteredScene, 1);
    const Film pointSampled = renderBeauty(pointScene, 1);
    double mean = 0.0;
    for (const auto& [x, y] : far) mean += filtered.at(0, x, y).g;
    mean /= double(far.size());
    CAPTURE(mean);
    CHECK(mean == doctest::Approx(0.5).epsilon(0.04));  // the checks' analytic average
    const double filteredError = rmse(filtered, reference, far), pointError = rmse(pointSampled, reference, far);
    CAPTURE(filteredError);
    CAPTURE(pointError);
    CHECK(filteredError < 0.06);
    // The control: one point sample per pixel lands on a black or a white check.
    CHECK(pointError > 0.3);
}

TEST_CASE("textures: up close each pixel is its texel's colour") {
    const std::string texture = checkerboard().string();
    // Looking straight down from 0.5 m: a texel (1/64 m for a repeat of 1 m) spans about 3 pixels.
    const Scene scene = loadSceneFromText(
        floorScene(texture, "[0.3, 0.5, 0.2]", "[0.3, 0, 0.2]", "[0, 0, -1]", 1.0f, true), "near.toml");
    const Film film = renderBeauty(scene, 1);
    const Camera camera(scene.camera);
    int checked = 0;
    for (int y = 0; y < camera.height(); ++y)
        for (int x = 0; x < camera.width(); ++x) {
            // The floor point under the pixel centre, its uv (the plane's frame: u = x, v = -z),
            // and the texel: image rows run down from t = 1 - v.
            const Ray ray = camera.generateRay(float(x) + 0.5f, float(y) + 0.5f);
            const Vec3 p = ray.at(-ray.origin.y / ray.direction.y);
            const float s = p.x - std::floor(p.x), t = 1.0f - (-p.z - std::floor(-p.z));
            const float i = s * kTexels, j = t * kTexels;
            // Only points 2 texels or more inside a check: magnification blends neighbours.
            const auto inside = [](float texel) {
                const float within = std::fmod(texel, float(kCheck));
                return within > 2.0f && within < float(kCheck) - 2.0f;
            };
            if (!inside(i) || !inside(j)) continue;
            ++checked;
            CAPTURE(x);
            CAPTURE(y);
            CHECK(film.at(0, x, y).g == doctest::Approx(checkAt(int(i), int(j))).epsilon(1e-4));
        }
    CHECK(checked > 1000);
}

// The pixels of a camera looking straight down at the 2 m square of the OBJ tests (vt (0,0) ..
// (1,1) on x, z in [-1, 1]) that see a point 2 texels or more inside a check: `check(x, y, texel)`
// with that check's value, 0 or 1.
template <class Check>
void forEachCheckPixel(const Scene& scene, Check check) {
    const Camera camera(scene.camera);
    for (int y = 0; y < camera.height(); ++y)
        for (int x = 0; x < camera.width(); ++x) {
            const Ray ray = camera.generateRay(float(x) + 0.5f, float(y) + 0.5f);
            const Vec3 p = ray.at(-ray.origin.y / ray.direction.y);
            if (std::abs(p.x) >= 1.0f || std::abs(p.z) >= 1.0f) continue;
            // vt interpolated: u = (x + 1) / 2, v = (1 - z) / 2; the texel row runs down from t = 1 - v.
            const float i = (p.x + 1.0f) / 2.0f * kTexels, j = (1.0f - (1.0f - p.z) / 2.0f) * kTexels;
            const float wi = std::fmod(i, float(kCheck)), wj = std::fmod(j, float(kCheck));
            if (wi < 2.0f || wi > kCheck - 2.0f || wj < 2.0f || wj > kCheck - 2.0f) continue;
            CAPTURE(x);
            CAPTURE(y);
            check(x, y, checkAt(int(i), int(j)));
        }
}

TEST_CASE("textures: an OBJ's map_Kd is its kd, at its vt") {
    const std::filesystem::path folder = checkerboard().parent_path();
    // A 2 m square on the floor, vt (0,0) .. (1,1), its MTL's map_Kd the checkerboard, lit from
    // straight above by a point light.
    std::ofstream(folder / "square.mtl") << "newmtl checks\nKd 1 1 1\nmap_Kd checker.png\n";
    std::ofstream(folder / "square.obj") << "mtllib square.mtl\nv -1 0 1\nv 1 0 1\nv 1 0 -1\nv -1 0 -1\n"
                                            "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nusemtl checks\nf 1/1 2/2 3/3 4/4\n";
    const std::string text = "[camera]\neye = [0, 3, 0]\nlook_at = [0, 0, 0]\nup = [0, 0, -1]\nfov = 40\n"
                             "resolution = [96, 72]\n[[lights]]\ntype = \"point\"\nposition = [0, 4, 0]\n"
                             "intensity = 16\n[[meshes]]\nfile = \"" + (folder / "square.obj").string() + "\"\n";
    const Scene scene = loadSceneFromText(text, "obj.toml");
    REQUIRE(scene.warnings.empty());
    const Film film = renderBeauty(scene, 1);
    int black = 0, white = 0;
    forEachCheckPixel(scene, [&](int x, int y, float texel) {
        if (texel == 0.0f) {
            ++black;
            CHECK(film.at(0, x, y).g == 0.0f);
        } else {
            ++white;
            CHECK(film.at(0, x, y).g > 0.1f);
        }
    });
    CHECK(black > 200);
    CHECK(white > 200);
}

TEST_CASE("textures: an OBJ's map_Ke is its emission, at its vt (a black Ke counting as white)") {
    const std::filesystem::path folder = checkerboard().parent_path();
    // The square of map_Kd's test, emitting upwards, seen from above with no light: a pixel is Le.
    std::ofstream(folder / "glow.mtl") << "newmtl glow\nKd 0 0 0\nKe 0 0 0\nmap_Ke checker.png\n";
    std::ofstream(folder / "glow.obj") << "mtllib glow.mtl\nv -1 0 1\nv 1 0 1\nv 1 0 -1\nv -1 0 -1\n"
                                          "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nusemtl glow\nf 1/1 2/2 3/3 4/4\n";
    const std::string text = "[camera]\neye = [0, 3, 0]\nlook_at = [0, 0, 0]\nup = [0, 0, -1]\nfov = 40\n"
                             "resolution = [96, 72]\n[[meshes]]\nfile = \"" + (folder / "glow.obj").string() + "\"\n";
    const Scene scene = loadSceneFromText(text, "obj.toml");
    const Film film = renderBeauty(scene, 1);
    int black = 0, white = 0;
    forEachCheckPixel(scene, [&](int x, int y, float expected) {
        (expected == 0.0f ? black : white) += 1;
        CHECK(film.at(0, x, y).g == doctest::Approx(expected).epsilon(1e-4));
    });
    CHECK(black > 200);
    CHECK(white > 200);
}

TEST_CASE("textures: a texture file that cannot be read is an error at its key") {
    const std::string text = "[materials.wood]\nkd = { texture = \"/nonexistent/wood.png\" }\n";
    CHECK_THROWS_WITH_AS(loadSceneFromText(text, "wood.toml"),
                         doctest::Contains("wood.toml:2:6: materials.wood.kd: cannot read the texture \"/nonexistent/wood.png\""),
                         SceneError);
    // A parameter read as a constant refuses one, located too.
    const std::string eta = "[materials.gold]\ntype = \"conductor\"\neta = { texture = \"" + checkerboard().string() + "\" }\n";
    CHECK_THROWS_WITH_AS(loadSceneFromText(eta, "gold.toml"),
                         doctest::Contains("gold.toml:3:7: materials.gold.eta: expected a number or an array of 3 numbers (this parameter takes no texture)"),
                         SceneError);
}

TEST_CASE("textures: microfacet's base_color takes a texture in TOML (its mean is the checks' 0.5 times the tint)") {
    const std::string text = "[materials.tiles]\ntype = \"microfacet\"\nmetallic = 0\nroughness = 0.5\n"
                             "base_color = { texture = \"" + checkerboard().string() + "\", tint = [1, 0.5, 1] }\n";
    const Scene scene = loadSceneFromText(text, "tiles.toml");
    REQUIRE(scene.materials.size() >= 1);
    const Rgb textured = scene.materials.back()->diffuseReflectance();
    const Rgb expected = MicrofacetMaterial(Rgb{0.5f, 0.25f, 0.5f}, 0.0f, 0.5f).diffuseReflectance();
    // 1%: the image module's mean of the checks reads 0.502, not 0.5.
    for (int c = 0; c < 3; ++c) CHECK(textured[c] == doctest::Approx(expected[c]).epsilon(0.01));
}

TEST_CASE("textures: the AOVs of a textured scene sum to the beauty") {
    const std::string texture = checkerboard().string();
    std::string text = floorScene(texture, "[0, 1, 0]", "[0, 0.8, -10]", "[0, 1, 0]", 4.0f, true);
    text += "[materials.ball]\nkd = { texture = \"" + texture + "\", tint = [1, 0.5, 0.25] }\nks = 0.2\n"
            "[[spheres]]\ncenter = [0, 1, -4]\nradius = 0.8\nmaterial = \"ball\"\n"
            "[[lights]]\ntype = \"point\"\nposition = [2, 4, 0]\nintensity = 10\n";
    const Scene scene = loadSceneFromText(text, "sums.toml");
    const AovSet aovs(classesSet());
    RenderOptions options;
    options.integrator = "path";
    options.samplesPerPixel = 4;
    const Film film = Renderer(scene, aovs, options).render().film;
    CHECK(test::worstSumError(film) <= 1.0);
}

namespace {

// An 8-bit RGB PNG of one row of `values` (0..255 each, grey), written into `folder`.
std::string writeRow(const test::TempFolder& folder, const std::string& name, const std::vector<unsigned char>& values) {
    std::vector<unsigned char> pixels;
    for (unsigned char v : values) pixels.insert(pixels.end(), {v, v, v});
    ImageFileSpec spec;
    spec.width = int(values.size());
    spec.height = 1;
    spec.channelNames = {"R", "G", "B"};
    const std::string file = (folder.path() / name).string();
    REQUIRE(writePngFile(file, spec, pixels.data(), {}).empty());
    return file;
}

// The red channel of `file` opened as `colorSpace`, point sampled at (s, 0.5) with `wrap`.
float texelAt(const std::string& file, TextureColorSpace colorSpace, float s, TextureWrap wrap = TextureWrap::repeat) {
    std::string error;
    const std::shared_ptr<const Texture> texture = openTexture({file, nullptr, colorSpace}, error);
    REQUIRE_MESSAGE(texture, error);
    TextureFootprint footprint;
    footprint.uv = {s, 0.5f};
    TextureSampling sampling;
    sampling.filtered = false;
    sampling.wrapS = sampling.wrapT = wrap;
    return texture->lookup(footprint, sampling).r;
}

}  // namespace

TEST_CASE("textures: an 8-bit texel of 128 reads 0.2159 as sRGB (its EOTF) and 0.502 as linear") {
    const test::TempFolder folder("lightpath-srgb-texture");
    const std::string file = writeRow(folder, "grey128.png", {128, 128});
    // IEC 61966-2-1: ((128/255 + 0.055) / 1.055)^2.4, evaluated here in double.
    const double srgb = std::pow((128.0 / 255.0 + 0.055) / 1.055, 2.4);
    CHECK(srgb == doctest::Approx(0.2159).epsilon(1e-3));
    CHECK(texelAt(file, TextureColorSpace::srgb, 0.5f) == doctest::Approx(srgb).epsilon(1e-5));
    CHECK(texelAt(file, TextureColorSpace::automatic, 0.5f) == doctest::Approx(srgb).epsilon(1e-5));  // 8-bit: sRGB
    CHECK(texelAt(file, TextureColorSpace::linear, 0.5f) == doctest::Approx(128.0 / 255.0).epsilon(1e-5));
    // The TOML key says which: `colorspace = "linear"` (and a wrong word is a located error).
    const auto kdOf = [&](const std::string& space) {
        const Scene scene = loadSceneFromText("[materials.grey]\nkd = { texture = \"" + file + "\", colorspace = \"" +
                                                  space + "\" }\n",
                                              "grey.toml");
        return scene.materials.back()->diffuseReflectance();
    };
    CHECK(kdOf("linear").r == doctest::Approx(128.0 / 255.0).epsilon(1e-4));
    CHECK(kdOf("srgb").r == doctest::Approx(srgb).epsilon(1e-4));
    // The value's column follows the temporary file's path, which differs from machine to machine.
    const std::size_t column = std::string("kd = { texture = \"" + file + "\", colorspace = ").size() + 1;
    const std::string expected =
        "grey.toml:2:" + std::to_string(column) + ": materials.grey.kd.colorspace: expected \"srgb\" or \"linear\"";
    CHECK_THROWS_WITH_AS(kdOf("rec709"), doctest::Contains(expected.c_str()), SceneError);
}

TEST_CASE("textures: outside [0, 1] repeat, clamp and mirror read the texels they should") {
    // Four texels 0, 85, 170, 255 (linear): centres at s = 0.125, 0.375, 0.625, 0.875.
    const test::TempFolder folder("lightpath-wrap-texture");
    const std::string file = writeRow(folder, "ramp.png", {0, 85, 170, 255});
    const auto at = [&](float s, TextureWrap wrap) { return texelAt(file, TextureColorSpace::linear, s, wrap) * 255.0f; };
    // s = -0.375: repeat lands on 0.625 (texel 2), clamp on the edge (texel 0), mirror on 0.375 (texel 1).
    CHECK(at(-0.375f, TextureWrap::repeat) == doctest::Approx(170.0f).epsilon(1e-4));
    CHECK(at(-0.375f, TextureWrap::clamp) == doctest::Approx(0.0f));
    CHECK(at(-0.375f, TextureWrap::mirror) == doctest::Approx(85.0f).epsilon(1e-4));
    // s = 1.125: repeat lands on 0.125 (texel 0), clamp and mirror on the last texel.
    CHECK(at(1.125f, TextureWrap::repeat) == doctest::Approx(0.0f));
    CHECK(at(1.125f, TextureWrap::clamp) == doctest::Approx(255.0f).epsilon(1e-4));
    CHECK(at(1.125f, TextureWrap::mirror) == doctest::Approx(255.0f).epsilon(1e-4));
}

}  // namespace lightpath
