// glTF scenes (issue #26): each file in tests/render/data/gltf/ (made by make_gltf.py there) renders
// as the TOML scene written beside it by hand, with the node transforms, the light's units and the
// emissive strength worked out on paper: the same mean radiance per 4x4 block within 1%, for point,
// spot, directional and emissive lights, and for textures (make_textured.py): a base-colour texture
// from a file and from a data URI against the TOML texture key, a metallic-roughness texture against
// two materials, a constant normal map against the vertex normals it makes (also in the frame of a
// TANGENT the uvs disagree with), a base-colour texture read through TEXCOORD_1. Textured emission:
// a TOML quad light of a four-quadrant texture against four constant quads, and a glTF
// emissiveTexture against the TOML texture key. A scene exported by Blender (blender/) renders as
// Cycles renders it. The AOVs sum to the beauty on a glTF scene as on every other.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>
#include <utility>

#include "film/aov_presets.h"
#include "film/aov_set.h"
#include "render/renderer.h"
#include "scene/camera.h"
#include "scene/scene_loader.h"
#include "../support/film_checks.h"
#include "../support/temp_folder.h"

namespace lightpath {
namespace {

const std::filesystem::path kData = std::filesystem::path(LIGHTPATH_SOURCE_DIR) / "tests/render/data/gltf";

Film renderSmall(const std::filesystem::path& file, const std::string& integrator, int spp, unsigned seed = 0,
                 int width = 48) {
    Scene scene = loadScene(file);
    REQUIRE(scene.cameraGiven);
    scene.camera.width = width;
    scene.camera.height = width * 3 / 4;
    RenderOptions options;
    options.integrator = integrator;
    options.samplesPerPixel = spp;
    options.seed = seed;
    return Renderer(scene, AovSet(classesSet()), options).render().film;
}

// The largest difference of two beauties' 4x4 block means (the sum of the channels), relative to
// the larger of the two, over the blocks holding light: a block darker than 1% of the image's
// brightest is held to 1% of that instead (a relative error of a near-black block is noise).
// Blocks whose column is in [skipFrom, skipTo) are left out (a texture's seam, blurred by its filter).
double worstBlockDifference(const Film& a, const Film& b, int skipFrom = 0, int skipTo = 0) {
    REQUIRE(a.width() == b.width());
    REQUIRE(a.height() == b.height());
    const auto blockMean = [](const Film& film, int bx, int by) {
        double sum = 0.0;
        for (int y = by * 4; y < by * 4 + 4; ++y)
            for (int x = bx * 4; x < bx * 4 + 4; ++x) {
                const Rgb v = film.at(0, x, y);
                sum += double(v.r) + double(v.g) + double(v.b);
            }
        return sum / 16.0;
    };
    double brightest = 0.0;
    for (int by = 0; by < a.height() / 4; ++by)
        for (int bx = 0; bx < a.width() / 4; ++bx) brightest = std::max(brightest, blockMean(a, bx, by));
    REQUIRE(brightest > 0.0);
    double worst = 0.0;
    for (int by = 0; by < a.height() / 4; ++by)
        for (int bx = 0; bx < a.width() / 4; ++bx) {
            if (bx >= skipFrom && bx < skipTo) continue;
            const double p = blockMean(a, bx, by), q = blockMean(b, bx, by);
            worst = std::max(worst, std::fabs(p - q) / std::max({p, q, 0.01 * brightest}));
        }
    return worst;
}

TEST_CASE("a glTF point light, its nodes and camera render as the TOML scene written by hand") {
    for (const char* integrator : {"raycast", "path"}) {
        CAPTURE(integrator);
        const Film gltf = renderSmall(kData / "point.gltf", integrator, 16);
        const Film toml = renderSmall(kData / "point.toml", integrator, 16);
        CHECK(worstBlockDifference(gltf, toml) <= 0.01);
    }
}

TEST_CASE("a glTF spot light (cone angles, candela, its node's -z) renders as the TOML scene written by hand") {
    for (const char* integrator : {"raycast", "path"}) {
        CAPTURE(integrator);
        const Film gltf = renderSmall(kData / "spot.gltf", integrator, 16);
        const Film toml = renderSmall(kData / "spot.toml", integrator, 16);
        CHECK(worstBlockDifference(gltf, toml) <= 0.01);
    }
}

TEST_CASE("a glTF directional light (lux as W/m^2, its node's -z) renders as the TOML scene written by hand") {
    for (const char* integrator : {"raycast", "path"}) {
        CAPTURE(integrator);
        const Film gltf = renderSmall(kData / "directional.gltf", integrator, 16);
        const Film toml = renderSmall(kData / "directional.toml", integrator, 16);
        CHECK(worstBlockDifference(gltf, toml) <= 0.01);
    }
}

// Cycles' 8x8-block means of a render (blender/make_blender.py): rows of numbers, '#' lines skipped.
std::vector<std::vector<double>> readBlockMeans(const std::filesystem::path& file) {
    std::ifstream in(file);
    REQUIRE(in);
    std::vector<std::vector<double>> rows;
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream numbers(line);
        rows.emplace_back(std::istream_iterator<double>(numbers), std::istream_iterator<double>());
    }
    return rows;
}

// lightpath's path-traced render of `scene` (256 spp, Cycles' 8 bounces) at the size of Cycles'
// block means `cycles` (kBlock x kBlock pixels each), compared per block of `merge` x `merge` of
// them: the ratio of the image means and the worst block's difference relative to Cycles' (a
// block darker than a tenth of the brightest is held to a tenth of that).
struct CyclesComparison {
    double meanRatio = 0.0, worstBlock = 0.0;
};
CyclesComparison compareWithCycles(Scene scene, const std::vector<std::vector<double>>& cycles, int merge) {
    constexpr int kBlock = 8;
    scene.camera.width = int(cycles[0].size()) * kBlock;
    scene.camera.height = int(cycles.size()) * kBlock;
    RenderOptions options;
    options.integrator = "path";
    options.samplesPerPixel = 256;
    options.maxDepth = 8;  // Cycles' max bounces
    const Film film = Renderer(scene, AovSet(classesSet()), options).render().film;
    const int side = kBlock * merge;
    const std::size_t columns = cycles[0].size() / std::size_t(merge), rows = cycles.size() / std::size_t(merge);
    std::vector<double> theirs(rows * columns, 0.0), ours(rows * columns, 0.0);
    for (std::size_t by = 0; by < rows * std::size_t(merge); ++by)
        for (std::size_t bx = 0; bx < columns * std::size_t(merge); ++bx)
            theirs[by / std::size_t(merge) * columns + bx / std::size_t(merge)] += cycles[by][bx] / double(merge * merge);
    for (int y = 0; y < int(rows) * side; ++y)
        for (int x = 0; x < int(columns) * side; ++x) {
            const Rgb v = film.at(0, x, y);
            ours[std::size_t(y / side) * columns + std::size_t(x / side)] +=
                (double(v.r) + double(v.g) + double(v.b)) / 3.0 / double(side * side);
        }
    double brightest = 0.0, sumOurs = 0.0, sumTheirs = 0.0;
    for (double v : theirs) brightest = std::max(brightest, v);
    CyclesComparison result;
    for (std::size_t k = 0; k < theirs.size(); ++k) {
        sumOurs += ours[k];
        sumTheirs += theirs[k];
        result.worstBlock = std::max(result.worstBlock, std::fabs(ours[k] - theirs[k]) / std::max(theirs[k], 0.1 * brightest));
    }
    result.meanRatio = sumOurs / sumTheirs;
    return result;
}

// A scene made in Blender and exported by its glTF exporter as a user would (candela and lux at
// 683 lm/W, Blender's default), rendered by Cycles as Blender holds it: an independent renderer's
// converged image, which lightpath's render of the file must match per block, so that what a
// lecturer sees in Blender is what lightpath shows. Reading the file's numbers as W/sr and W/m^2
// (`lighting = "unitless"`) makes every block 683 times too bright; an emissive square emitting
// only on its normal's side leaves its back, which the camera sees, black. A floor painted by a
// colour attribute (its material's base colour) exports it as COLOR_0. An orthographic camera (Blender's
// Orthographic Scale over the image's width) exports xmag and ymag: seen through a pinhole, the same
// view is far off.
TEST_CASE("a Blender scene exported to glTF renders as Cycles renders it in Blender: a point lamp, a sun, an emitter, an orthographic camera" *
          doctest::test_suite("statistical")) {
    for (const std::string light : {"point", "sun", "emissive", "vertex-colors", "orthographic"}) {
        CAPTURE(light);
        const auto cycles = readBlockMeans(kData / "blender" / (light + "-cycles.txt"));
        REQUIRE(cycles.size() == 8);
        REQUIRE(cycles[0].size() == 12);
        // The lamp's edge lies 0.02 pixels apart in the two (the camera passes through the file's floats).
        const Scene scene = loadScene(kData / "blender" / (light + ".toml"));
        const CyclesComparison c = compareWithCycles(scene, cycles, 1);
        CHECK(c.meanRatio == doctest::Approx(1.0).epsilon(0.01));
        CHECK(c.worstBlock <= 0.04);
        if (light == "orthographic") {  // the control: the same view through a pinhole is far off
            Scene pinhole = scene;
            pinhole.camera.projection = Projection::Perspective;
            CHECK(compareWithCycles(pinhole, cycles, 1).worstBlock > 0.3);
        }
    }
}

// Blender's Alpha Clip (an image's alpha, glTF's MASK) and Alpha Blend (a constant alpha of 0.4,
// BLEND) on a black card between a sun and the floor: Cycles renders alpha as transparency, so
// its stripes of light and its 60% are what lightpath must show. Compared per 16 x 16 block: the
// card's and its shadow's horizontal edges lie about 0.06 pixels apart in the two renders (both
// lighter in lightpath's; the file's yfov is Blender's to 1e-7), which the black card against the
// lit floor makes 6% of an 8 x 8 block in its shadow (0.4% of a 16 x 16 one). lightpath's edges
// are where the projection puts them: a black plane's edge 18.5 rows from the centre of a 96 x 64
// render covers its pixel to 0.0002 of the analytic fraction in lightpath, 0.014 more in Cycles
// 3.4. The control: the card without its alpha (opaque) is far off.
TEST_CASE("a Blender scene's cut-outs (Alpha Clip, Alpha Blend) render as Cycles renders them" * doctest::test_suite("statistical")) {
    for (const std::string file : {"cutout-mask", "cutout-blend"}) {
        CAPTURE(file);
        const auto cycles = readBlockMeans(kData / "blender" / (file + "-cycles.txt"));
        REQUIRE(cycles.size() == 8);
        REQUIRE(cycles[0].size() == 12);
        const Scene scene = loadScene(kData / "blender" / (file + ".toml"));
        const CyclesComparison c = compareWithCycles(scene, cycles, 2);
        CHECK(c.meanRatio == doctest::Approx(1.0).epsilon(0.01));
        CHECK(c.worstBlock <= 0.04);
        Scene opaque = scene;
        for (MaterialSlot& m : opaque.materials) m->alpha = nullptr;
        CHECK(compareWithCycles(opaque, cycles, 2).worstBlock > 0.3);
    }
}

// vertex-colors.toml with the glTF `file` of make_vertex_colors.py in it.
Scene vertexColorScene(const std::string& file) {
    std::ifstream in(kData / "vertex-colors.toml");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    text.replace(text.rfind("FILE"), 4, file);
    return loadSceneFromText(text, kData / "vertex-colors.toml");
}

// glTF 2.0, 3.7.2.1: COLOR_0 multiplies the base colour. A floor triangle of base colour 1 and
// F0 0 (a Lambertian base alone) under a light straight down, seen from above by the rasteriser
// (pixel centres): each pixel is the white floor's times the corners' colours interpolated at the
// point that pixel's centre sees, barycentric weights worked here from the corners. The path
// tracer, bdpt and radiosity agree on the coloured floor's mean (each reads the colour).
TEST_CASE("a glTF mesh's COLOR_0 multiplies its base colour: the white floor times the corners' colours, interpolated") {
    const auto sceneOf = vertexColorScene;
    const auto render = [](const Scene& scene, const char* integrator, int spp) {
        RenderOptions options;
        options.integrator = integrator;
        options.samplesPerPixel = spp;
        return Renderer(scene, AovSet(classesSet()), options).render().film;
    };
    const Scene whiteScene = sceneOf("vertex-colors-white.gltf");
    const Film white = render(whiteScene, "raster", 1);
    const Camera camera(whiteScene.camera);
    // The corners (x, z) of make_vertex_colors.py's triangle at y = 0.
    const Vec2 a{-8.0f, 8.0f}, b{8.0f, 8.0f}, c{0.0f, -8.0f};
    const auto weights = [&](Vec2 p) {
        const auto cross = [](Vec2 u, Vec2 v) { return double(u.x) * v.y - double(u.y) * v.x; };
        const double area = cross(b - a, c - a);
        return glm::dvec3(cross(b - p, c - p) / area, cross(c - p, a - p) / area, cross(a - p, b - p) / area);
    };
    struct Case {
        const char* file;
        std::array<Rgb, 3> corners;
    };
    for (const Case& k : {Case{"vertex-colors.gltf", {Rgb(1, 0, 0), Rgb(0, 1, 0), Rgb(0, 0, 1)}},
                          Case{"vertex-colors-u8.gltf", {Rgb(1.0f, 128.0f / 255, 0), Rgb(0, 1, 64.0f / 255),
                                                         Rgb(32.0f / 255, 0, 1)}}}) {
        CAPTURE(k.file);
        const Film colored = render(sceneOf(k.file), "raster", 1);
        int checked = 0;
        double worst = 0.0;
        for (int y = 0; y < white.height(); ++y)
            for (int x = 0; x < white.width(); ++x) {
                const Rgb reference = white.at(0, x, y);
                if (!(reference.r > 0.0f)) continue;  // beyond the triangle
                const Ray ray = camera.generateRay(float(x) + 0.5f, float(y) + 0.5f);
                const Vec3 p = ray.at(-ray.origin.y / ray.direction.y);
                const glm::dvec3 w = weights({p.x, p.z});
                for (int ch = 0; ch < 3; ++ch) {
                    const double expected = w.x * k.corners[0][ch] + w.y * k.corners[1][ch] + w.z * k.corners[2][ch];
                    worst = std::max(worst, std::fabs(double(colored.at(0, x, y)[ch]) / reference[ch] - expected));
                }
                ++checked;
            }
        CHECK(checked > 1000);
        CHECK(worst < 1e-4);
    }
    const Scene coloredScene = sceneOf("vertex-colors.gltf");
    const auto mean = [](const Film& film) {
        double sum = 0.0;
        for (int y = 0; y < film.height(); ++y)
            for (int x = 0; x < film.width(); ++x) sum += double(film.at(0, x, y).g);
        return sum / (film.width() * film.height());
    };
    const double path = mean(render(coloredScene, "path", 16)), bdpt = mean(render(coloredScene, "bdpt", 16));
    CHECK(bdpt / path == doctest::Approx(1.0).epsilon(0.02));
    // Radiosity solves with each patch's mean colour and shows the colour at each point.
    CHECK(mean(render(coloredScene, "radiosity", 1)) / path == doctest::Approx(1.0).epsilon(0.02));
    CHECK(path < 0.9 * mean(render(whiteScene, "path", 16)));  // the control: the colour is there
    try {
        (void)loadScene(kData / "vertex-colors-bad.gltf");
        FAIL("no error");
    } catch (const SceneError& e) {
        CHECK(std::string(e.what()) == (kData / "vertex-colors-bad.gltf").string() +
                                            ": meshes[0].primitives[0].attributes.COLOR_0: accessor 1: element 1 has a "
                                            "component 1.5; expected numbers from 0 to 1");
    }
}

// glTF 2.0, 3.9.4: COLOR_0's alpha multiplies a MASK or BLEND material's. make_vertex_colors.py's
// floor of alpha 1 with corner alphas 0, 0, 1 (a, b, c), seen from above under a light straight
// down, black beyond: alpha is c's barycentric weight, (8 - z) / 16 on the floor, 0.5 along z = 0
// through the image's middle row. MASK: at pixel centres (the rasteriser) the floor is the white
// floor's where alpha is above the cutoff 0.5 and black below. BLEND: each ray meets it with
// probability alpha, so each band of rows, over 16 samples per pixel (ray casting), holds that
// fraction of the white floor's light.
TEST_CASE("glTF's COLOR_0 alpha multiplies a MASK or BLEND material's: cut at the cutoff where it falls below, and blended in proportion") {
    const auto sceneOf = vertexColorScene;
    // The rasteriser at pixel centres; ray casting for 16 samples a pixel.
    const auto render = [](const Scene& scene, int spp) {
        RenderOptions options;
        options.integrator = spp == 1 ? "raster" : "raycast";
        options.samplesPerPixel = spp;
        return Renderer(scene, AovSet(classesSet()), options).render().film;
    };
    const Scene whiteScene = sceneOf("vertex-colors-white.gltf");
    const Camera camera(whiteScene.camera);
    // Alpha at the point a pixel's centre sees: c's weight, c = (0, -8) and the edge ab at z = 8.
    const auto alphaAt = [&](int x, int y) {
        const Ray ray = camera.generateRay(float(x) + 0.5f, float(y) + 0.5f);
        return (8.0 - double(ray.at(-ray.origin.y / ray.direction.y).z)) / 16.0;
    };

    SUBCASE("MASK: the floor where alpha >= 0.5, nothing where it is below") {
        const Film white = render(whiteScene, 1), mask = render(sceneOf("vertex-alpha-mask.gltf"), 1);
        int kept = 0, cut = 0;
        for (int y = 0; y < white.height(); ++y)
            for (int x = 0; x < white.width(); ++x) {
                const double alpha = alphaAt(x, y);
                if (!(white.at(0, x, y).g > 0.0f)) continue;  // beyond the triangle
                if (std::fabs(alpha - 0.5) < 0.01) continue;  // at the cutoff: round-off decides
                CAPTURE(alpha);
                if (alpha > 0.5) {
                    CHECK(mask.at(0, x, y).g == doctest::Approx(white.at(0, x, y).g).epsilon(1e-6));
                    ++kept;
                } else {
                    CHECK(mask.at(0, x, y).g == 0.0f);
                    ++cut;
                }
            }
        CHECK(kept > 500);
        CHECK(cut > 500);
    }
    SUBCASE("BLEND: each band of rows keeps its mean alpha of the light") {
        const Film white = render(whiteScene, 16), blend = render(sceneOf("vertex-alpha-blend.gltf"), 16);
        constexpr int kBand = 8;
        for (int y0 = 0; y0 < white.height(); y0 += kBand) {
            double kept = 0.0, all = 0.0, alpha = 0.0;
            int pixels = 0;
            for (int y = y0; y < std::min(y0 + kBand, white.height()); ++y)
                for (int x = 0; x < white.width(); ++x) {
                    if (!(white.at(0, x, y).g > 0.0f)) continue;  // beyond the triangle
                    kept += blend.at(0, x, y).g;
                    all += white.at(0, x, y).g;
                    alpha += alphaAt(x, y);
                    ++pixels;
                }
            const double expected = alpha / pixels, measured = kept / all;
            CAPTURE(y0);
            CAPTURE(expected);
            CAPTURE(measured);
            // 16 x 384 rays a band, each kept with probability alpha: a standard deviation under 0.007.
            CHECK(std::fabs(measured - expected) < 0.03);
        }
    }
}

TEST_CASE("[[gltf]] lighting: a sun's lux read as W/m^2 by 683 (standard), and unchanged by unitless and raw") {
    const test::TempFolder temp("lightpath-gltf-sun");
    std::filesystem::copy_file(kData / "directional.gltf", temp.path() / "directional.gltf");
    const auto rendered = [&](const std::string& lighting) {
        std::ofstream(temp.path() / "scene.toml")
            << "[[gltf]]\nfile = \"directional.gltf\"\nlighting = \"" << lighting << "\"\n";
        return renderSmall(temp.path() / "scene.toml", "raycast", 1);
    };
    const Film standard = rendered("standard"), unitless = rendered("unitless"), raw = rendered("raw");
    double sumStandard = 0.0, sumUnitless = 0.0, sumRaw = 0.0;
    for (int y = 0; y < standard.height(); ++y)
        for (int x = 0; x < standard.width(); ++x) {
            sumStandard += double(standard.at(0, x, y).g);
            sumUnitless += double(unitless.at(0, x, y).g);
            sumRaw += double(raw.at(0, x, y).g);
        }
    REQUIRE(sumStandard > 0.0);
    CHECK(sumUnitless / sumStandard == doctest::Approx(683.0).epsilon(1e-4));
    CHECK(sumRaw == doctest::Approx(sumUnitless).epsilon(1e-6));
}

// KHR_materials_volume (volume.gltf): a unit cube of index-1 glass, so rays pass straight through
// without reflection, bounding a medium that turns white light into attenuationColor [0.8, 0.5, 1]
// after 0.5. Seen face on through a white sky, each ray inside crosses 1: Beer-Lambert gives
// attenuationColor^(1 / 0.5) = [0.64, 0.25, 1] by hand. The same cube as a thin wall (thickness 0,
// glTF's default) absorbs nothing, the control.
Film renderThroughCube(const std::string& extensionChange, const std::string& integrator) {
    const test::TempFolder temp("lightpath-gltf-volume");
    std::ifstream in(kData / "volume.gltf");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string thickness = "\"thicknessFactor\": 1";
    REQUIRE(text.find(thickness) != std::string::npos);
    if (!extensionChange.empty()) text.replace(text.find(thickness), thickness.size(), extensionChange);
    std::ofstream(temp.path() / "cube.gltf") << text;
    const std::string scene = "[world]\nbackground = 1\n[camera]\neye = [0, 0, 3]\nlook_at = [0, 0, 0]\n"
                              "projection = \"orthographic\"\nheight = 2\nresolution = [16, 16]\n"
                              "[[gltf]]\nfile = \"cube.gltf\"\n";
    RenderOptions options;
    options.integrator = integrator;
    options.samplesPerPixel = 4;
    return Renderer(loadSceneFromText(scene, temp.path() / "cube.toml"), AovSet(classesSet()), options).render().film;
}

// The largest difference, relative per channel, between the middle 4x4 pixels (inside the cube's
// face, which covers the middle 8x8) and `expected`.
double worstInside(const Film& film, const Rgb& expected) {
    double worst = 0.0;
    for (int y = 6; y < 10; ++y)
        for (int x = 6; x < 10; ++x)
            for (int c = 0; c < 3; ++c)
                worst = std::max(worst, std::fabs(double(film.at(0, x, y)[c]) - expected[c]) / expected[c]);
    return worst;
}

TEST_CASE("a glTF volume (KHR_materials_volume) absorbs as Beer-Lambert: attenuationColor^(distance / attenuationDistance)") {
    const Rgb throughCube{0.8f * 0.8f, 0.5f * 0.5f, 1.0f};
    for (const char* integrator : {"whitted", "path"}) {
        CAPTURE(integrator);
        CHECK(worstInside(renderThroughCube("", integrator), throughCube) < 1e-4);
        // A thin wall (thicknessFactor 0) bounds no volume: the sky comes through unchanged.
        const Film thin = renderThroughCube("\"thicknessFactor\": 0", integrator);
        CHECK(worstInside(thin, Rgb{1.0f}) < 1e-4);
        CHECK(worstInside(thin, throughCube) > 0.5);
    }
}

TEST_CASE("a glTF emissive material (emissiveFactor, KHR_materials_emissive_strength) renders as its TOML scene") {
    const Film gltf = renderSmall(kData / "emissive.gltf", "raycast", 256);
    const Film toml = renderSmall(kData / "emissive.toml", "raycast", 256);
    CHECK(worstBlockDifference(gltf, toml) <= 0.01);
}

TEST_CASE("a glTF baseColorTexture (a file beside it, a data URI, a .glb bufferView) renders as the TOML texture key") {
    // Both read the same 8-bit PNG as sRGB, through the same uvs (glTF's v is flipped on reading).
    const Film toml = renderSmall(kData / "textured.toml", "raycast", 4);
    for (const char* file : {"textured.gltf", "textured-embedded.gltf", "textured.glb"}) {
        CAPTURE(file);
        const Film gltf = renderSmall(kData / file, "raycast", 4);
        CHECK(worstBlockDifference(gltf, toml) <= 0.01);
    }
}

TEST_CASE("a glTF metallicRoughnessTexture (B metallic, G roughness) renders as two materials would") {
    // Its left half metal of roughness 0.2, its right half dielectric of roughness 0.8; the two
    // block columns at the seam (x = 0, image columns 20 to 27) are left out: the filter blurs it.
    const Film gltf = renderSmall(kData / "metal-rough.gltf", "raycast", 4);
    const Film toml = renderSmall(kData / "metal-rough.toml", "raycast", 4);
    CHECK(worstBlockDifference(gltf, toml, 5, 7) <= 0.01);
}

TEST_CASE("a glTF clear coat's textures (R weight, G roughness, KHR_materials_clearcoat) render as two materials would") {
    // Its left half a coat of weight 1 and roughness 0.2, its right half 0.4 and 0.8; read as their
    // factors alone (1 and 1), the left half shows the lamp's broad highlight and the right half is
    // dimmed as under a full coat. The seam's block columns are left out, as for metal-rough.
    const Film gltf = renderSmall(kData / "clearcoat.gltf", "raycast", 4);
    const Film toml = renderSmall(kData / "clearcoat.toml", "raycast", 4);
    CHECK(worstBlockDifference(gltf, toml, 5, 7) <= 0.01);
}

TEST_CASE("a glTF normalTexture (constant, tilted, scale 0.5) shades as vertex normals of the tilted normal") {
    // make_textured.py works the map's normal out in double (glTF's +Y up, OpenGL style: the
    // bitangent along v up, which glTF's v down makes -z here) and writes it as NORMAL of the
    // reference; the light's and the camera's directions differ over the floor, so a normal
    // turned the wrong way (x or y flipped, scale not applied) differs by far more than 1%.
    const Film mapped = renderSmall(kData / "normal-map.gltf", "raycast", 4);
    const Film tilted = renderSmall(kData / "normal-tilted.gltf", "raycast", 4);
    CHECK(worstBlockDifference(mapped, tilted) <= 0.01);
}

TEST_CASE("a glTF normalTexture turns the normal in the frame of the mesh's TANGENT, not of its uvs") {
    // normal-map-tangent.gltf turns the uvs a quarter (u along +z) and gives TANGENT (1, 0, 0, 1),
    // the frame normal-tilted.gltf's normal was worked out in; the uvs' frame would lean it elsewhere.
    const Film mapped = renderSmall(kData / "normal-map-tangent.gltf", "raycast", 4);
    const Film tilted = renderSmall(kData / "normal-tilted.gltf", "raycast", 4);
    CHECK(worstBlockDifference(mapped, tilted) <= 0.01);
}

TEST_CASE("a glTF baseColorTexture naming texCoord 1 reads TEXCOORD_1, as the TOML texture key reads the uvs") {
    // TEXCOORD_0 is mirrored in u: read instead, the checker's columns would swap.
    const Film second = renderSmall(kData / "textured-texcoord1.gltf", "raycast", 4);
    const Film toml = renderSmall(kData / "textured.toml", "raycast", 4);
    CHECK(worstBlockDifference(second, toml) <= 0.01);
}

TEST_CASE("KHR_texture_transform (offset, rotation, scale, its texCoord) renders as the uvs transformed by hand") {
    const Film moved = renderSmall(kData / "textured-transform.gltf", "raycast", 4);
    const Film baked = renderSmall(kData / "textured-transform-baked.gltf", "raycast", 4);
    CHECK(worstBlockDifference(moved, baked) <= 0.01);
}

// KHR_mesh_quantization, as gltfpack writes a file: SHORT positions 16384 times the floor's that its
// node scales back, normalized BYTE normals (each element padded to 4 bytes) and normalized SHORT
// uvs. Without the extension in extensionsUsed the integer positions are refused.
TEST_CASE("a KHR_mesh_quantization file (SHORT positions, BYTE normals, SHORT uvs) renders as the float file") {
    const Film toml = renderSmall(kData / "textured.toml", "raycast", 4);
    CHECK(worstBlockDifference(renderSmall(kData / "textured-quantized.gltf", "raycast", 4), toml) <= 0.01);
    // A tilted normal with negative components, as signed bytes (1/127 steps: within 1% per block).
    CHECK(worstBlockDifference(renderSmall(kData / "normal-tilted-quantized.gltf", "raycast", 4),
                               renderSmall(kData / "normal-tilted.gltf", "raycast", 4)) <= 0.01);
    std::ifstream in(kData / "textured-quantized.gltf");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    for (const std::string listed : {",\n  \"KHR_mesh_quantization\"", "\"KHR_mesh_quantization\""}) {
        REQUIRE(text.find(listed) != std::string::npos);
        text.erase(text.find(listed), listed.size());
    }
    const test::TempFolder temp("lightpath-gltf-quantized");
    std::ofstream(temp.path() / "unlisted.gltf") << text;
    std::ofstream(temp.path() / "checker4.png", std::ios::binary)
        << std::ifstream(kData / "checker4.png", std::ios::binary).rdbuf();
    CHECK_THROWS_WITH_AS(loadScene(temp.path() / "unlisted.gltf"),
                         doctest::Contains("meshes[0].primitives[0].attributes.POSITION: expected FLOAT components"),
                         SceneError);
}

TEST_CASE("glTF uvs as normalized UNSIGNED_BYTE and UNSIGNED_SHORT render as float uvs") {
    const Film toml = renderSmall(kData / "textured.toml", "raycast", 4);
    for (const char* file : {"textured-uv8.gltf", "textured-uv16.gltf"}) {
        CAPTURE(file);
        CHECK(worstBlockDifference(renderSmall(kData / file, "raycast", 4), toml) <= 0.01);
    }
}

TEST_CASE("a textured quad light renders as its four quadrants as constant quads: seen, and by the light it casts" *
          doctest::test_suite("statistical")) {
    // Seen directly, a ray's hit reads the texture; on the floor, light sampling reads it at the
    // sampled point's uv, BSDF sampling at the hit's; bdpt's light paths start at a sampled point.
    // 16x12 pixels: the floor's light-sampling noise per 4x4 block is below 0.4% at these counts
    // (the four quads against themselves under another seed: 0.43%, 0.34%, 0.62% at 1600, 4096,
    // 2048 samples).
    for (const auto& run : {std::pair<std::string, int>{"raycast", 1600}, {"path", 8192}, {"bdpt", 8192}}) {
        const std::string& integrator = run.first;
        CAPTURE(integrator);
        const Film textured = renderSmall(kData / "emissive-texture.toml", integrator, run.second, 0, 16);
        const Film quads = renderSmall(kData / "emissive-quads.toml", integrator, run.second, 0, 16);
        CHECK(worstBlockDifference(textured, quads) <= 0.01);
    }
}

TEST_CASE("a glTF emissiveTexture (sRGB, times emissiveFactor and emissive strength) renders as the TOML texture key") {
    // The same emitter as the same triangles: the renders agree sample by sample, few samples do.
    for (const char* integrator : {"raycast", "path"}) {
        CAPTURE(integrator);
        const Film gltf = renderSmall(kData / "emissive-texture-gltf.toml", integrator, 16);
        const Film toml = renderSmall(kData / "emissive-texture-srgb.toml", integrator, 16);
        CHECK(worstBlockDifference(gltf, toml) <= 0.01);
    }
}

TEST_CASE("the AOVs sum to the beauty on glTF scenes") {
    for (const char* file :
         {"point.gltf", "spot.gltf", "directional.gltf", "emissive.gltf", "metal-rough.gltf", "clearcoat.gltf"}) {
        for (const char* integrator : {"raycast", "whitted", "path", "bdpt"}) {
            CAPTURE(file);
            CAPTURE(integrator);
            const Film film = renderSmall(kData / file, integrator, 2);
            CHECK(test::worstSumError(film) <= 1.0);
            CHECK(test::finiteNonNegative(film));
        }
    }
}

}  // namespace
}  // namespace lightpath
