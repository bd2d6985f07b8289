// Alpha cut-outs (materials/alpha.h, geometry/coverage.h): a ray meets a cut-out surface only where
// it is covered. SceneGeometry looks through one on every accelerator; under a light straight down,
// a card whose stripes cover half of it lets half the light reach the floor (the floor's radiance
// kd E / pi, worked by hand), in every integrator, as a TOML alpha texture with a cutoff, an OBJ's
// map_d and glTF's alphaMode MASK give it; a constant alpha of 0.3 stops 30% of the light (BLEND);
// the rasteriser discards the fragments ray casting looks through. Test files: data/cutout/,
// written by make_cutout.py there.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "accel/scene_geometry.h"
#include "film/aov_presets.h"
#include "film/aov_set.h"
#include "materials/texture.h"
#include "math/random.h"
#include "render/renderer.h"
#include "scene/scene_loader.h"

namespace lightpath {
namespace cutout_tests {
namespace {

const std::filesystem::path kData = std::filesystem::path(LIGHTPATH_SOURCE_DIR) / "tests/render/data/cutout";

// The floor's radiance where the light reaches it: kd E / pi, kd 0.5, E 1.
constexpr double kLitFloor = 0.5 / std::numbers::pi;

std::string shadowText() {
    std::ifstream in(kData / "shadow.toml");
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// shadow.toml with the line starting `from` replaced by `to` (whole lines), loaded from its folder.
Scene shadowScene(const std::string& from, const std::string& to) {
    std::string text = shadowText();
    const std::size_t at = text.find(from);
    REQUIRE(at != std::string::npos);
    text.replace(at, text.find('\n', at) - at, to);
    return loadSceneFromText(text, kData / "shadow.toml");
}

Scene withCardAlpha(const std::string& alpha) {
    // The card black: no light comes back from it, so every integrator's floor is its direct light.
    return shadowScene("cut = ", "cut = { kd = 0, alpha = " + alpha + " }");
}

// shadow.toml with `section` in place of its last one, card.obj's [[meshes]].
Scene withCard(const std::string& section) {
    std::string text = shadowText();
    text = text.substr(0, text.find("[[meshes]]")) + section;
    return loadSceneFromText(text, kData / "shadow.toml");
}

// The beauty's mean red over the image, in units of kLitFloor.
double litFraction(Scene scene, const std::string& integrator, int spp = 16, int side = 32) {
    scene.camera.width = side;
    scene.camera.height = side;
    RenderOptions options;
    options.integrator = integrator;
    options.samplesPerPixel = spp;
    const Film film = Renderer(scene, AovSet(classesSet()), options).render().film;
    double sum = 0.0;
    for (int y = 0; y < film.height(); ++y)
        for (int x = 0; x < film.width(); ++x) sum += film.at(0, x, y).r;
    return sum / (double(film.width()) * film.height()) / kLitFloor;
}

// Stripes along u, as stripes-rgba.png makes them at cutoff 0.5: covered where fract(u) < 0.5.
class Stripes final : public SurfaceCoverage {
public:
    bool covers(Vec2 uv, float, float) const override { return uv.x - std::floor(uv.x) < 0.5f; }
};

// Stops the fraction `alpha` of rays, by their own number.
class Fraction final : public SurfaceCoverage {
public:
    explicit Fraction(float alpha) : alpha_(alpha) {}
    bool covers(Vec2, float, float u) const override { return u < alpha_; }

private:
    float alpha_;
};

// A floor (object 0) at y = 0 and card.obj's card (object 1) at y = 1, its u = 4 (x + 4).
SceneGeometry cardOverFloor(Accelerator accelerator, std::shared_ptr<const SurfaceCoverage> card) {
    std::vector<Triangle> triangles{{{-4, 0, -4}, {4, 0, 4}, {4, 0, -4}, 0}, {{-4, 0, -4}, {-4, 0, 4}, {4, 0, 4}, 0},
                                    {{-4, 1, -4}, {4, 1, -4}, {4, 1, 4}, 1}, {{-4, 1, -4}, {4, 1, 4}, {-4, 1, 4}, 1}};
    const auto uv = [](float x, float z) { return Vec2(4.0f * (x + 4.0f), (z + 4.0f) / 8.0f); };
    std::vector<TriangleUvs> uvs{{},
                                 {},
                                 {uv(-4, -4), uv(4, -4), uv(4, 4), true},
                                 {uv(-4, -4), uv(4, 4), uv(-4, 4), true}};
    return SceneGeometry({}, {}, triangles, {}, accelerator, {}, 0, {}, uvs, {}, {nullptr, std::move(card)});
}

std::vector<Accelerator> accelerators() {
    std::vector<Accelerator> all{Accelerator::BruteForce, Accelerator::Bvh};
    if (embreeAvailable()) all.push_back(Accelerator::Embree);
    return all;
}

}  // namespace

TEST_CASE("cut-outs: a ray where the card is cut out meets the floor behind it, elsewhere the card") {
    for (const Accelerator accelerator : accelerators()) {
        CAPTURE(int(accelerator));
        const SceneGeometry geometry = cardOverFloor(accelerator, std::make_shared<Stripes>());
        CHECK(geometry.hasCutouts());
        for (int k = 0; k < 64; ++k) {
            // x in the middle of eighth-stripes: u = 4 (x + 4) has fract 1/16, 3/16, ... 15/16.
            const float x = -2.0f + (float(k) + 0.5f) / 32.0f;
            const float u = 4.0f * (x + 4.0f);
            const bool covered = u - std::floor(u) < 0.5f;
            CAPTURE(x);
            const Ray down{{x, 2.0f, 0.3f}, {0.0f, -1.0f, 0.0f}};
            const std::optional<SurfaceHit> hit = geometry.intersect(down);
            REQUIRE(hit);
            CHECK(hit->object == (covered ? 1u : 0u));
            CHECK(hit->t == doctest::Approx(covered ? 1.0 : 2.0));
            const std::optional<PrimitiveHit> primitive = geometry.closestPrimitive(down);
            REQUIRE(primitive);
            CHECK(primitive->primitive == hit->primitive);
            // A shadow ray from the floor up to a light above the card.
            Ray up{{x, 0.0f, 0.3f}, {0.0f, 1.0f, 0.0f}};
            up.tMin = 1e-4f;
            up.tMax = 3.0f;
            CHECK(geometry.occluded(up) == covered);
            // The card's triangle under (x, 0.3), x < 0.3: the second, z > x.
            CHECK(geometry.covers(down, 1.0f, geometry.triangleId(3)) == covered);
        }
        // Without the cut-out the card stops every ray: the control.
        const SceneGeometry opaque = cardOverFloor(accelerator, nullptr);
        CHECK_FALSE(opaque.hasCutouts());
        CHECK(opaque.intersect(Ray{{0.1f, 2.0f, 0.3f}, {0.0f, -1.0f, 0.0f}})->object == 1u);
    }
}

TEST_CASE("cut-outs: a fractional coverage stops that fraction of rays, the same ray alike each time") {
    const SceneGeometry geometry = cardOverFloor(Accelerator::Bvh, std::make_shared<Fraction>(0.3f));
    Pcg32 rng(7, 1);
    int stopped = 0;
    constexpr int kRays = 20000;
    for (int i = 0; i < kRays; ++i) {
        Ray up{{rng.nextFloat() * 6.0f - 3.0f, 0.0f, rng.nextFloat() * 6.0f - 3.0f}, {0.0f, 1.0f, 0.0f}};
        up.tMin = 1e-4f;
        up.tMax = 3.0f;
        const bool blocked = geometry.occluded(up);
        CHECK(geometry.occluded(up) == blocked);
        stopped += blocked;
    }
    // Binomial: sd sqrt(0.3 0.7 / 20000) = 0.0032; 5 sd.
    CHECK(double(stopped) / kRays == doctest::Approx(0.3).epsilon(0.016 / 0.3));
}

TEST_CASE("cut-outs: a texture's alpha is its own channel, and its colours stay straight (not multiplied by it)") {
    // From the file, and from its bytes in memory as a glTF data URI or bufferView holds them.
    std::ifstream file(kData / "stripes-rgba.png", std::ios::binary);
    const std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    for (const TextureColorSpace space : {TextureColorSpace::srgb, TextureColorSpace::linear})
    for (const bool inMemory : {false, true}) {
        CAPTURE(int(space));
        CAPTURE(inMemory);
        std::string error;
        const auto rgba = openTexture({(kData / "stripes-rgba.png").string(), inMemory ? &bytes : nullptr, space}, error);
        CAPTURE(error);
        REQUIRE(rgba);
        CHECK(rgba->alphaChannel() == 3);
        TextureSampling point;
        point.filtered = false;
        // Texel centres of columns 1 (alpha 1) and 2 (alpha 0), white both.
        for (const float u : {1.5f / 8.0f, 2.5f / 8.0f}) {
            TextureFootprint at;
            at.uv = {u, 0.5f};
            CAPTURE(u);
            CHECK(rgba->lookup(at, point).r == doctest::Approx(1.0));
            CHECK(rgba->lookupChannel(at, point, 3) == doctest::Approx(u < 0.25f ? 1.0 : 0.0));
        }
    }
    std::string error;
    const auto grey = openTexture({(kData / "stripes-grey.png").string(), nullptr, TextureColorSpace::linear}, error);
    REQUIRE(grey);
    CHECK(grey->alphaChannel() == -1);
}

TEST_CASE("cut-outs: a TOML alpha texture with a cutoff lets half the light through striped holes, in every integrator") {
    const Scene striped = withCardAlpha("{ texture = \"stripes-rgba.png\", cutoff = 0.5 }");
    for (const char* integrator : {"raycast", "whitted", "path", "bdpt", "photon", "sppm"}) {
        CAPTURE(integrator);
        CHECK(litFraction(striped, integrator) == doctest::Approx(0.5).epsilon(0.01));
    }
    // The control: alpha 1 (covered everywhere) stops all of it.
    CHECK(litFraction(withCardAlpha("1"), "raycast") == doctest::Approx(0.0));
}

TEST_CASE("cut-outs: a constant alpha of 0.3 stops 30% of the light, and a grey mask's only channel is its alpha") {
    const Scene blend = withCardAlpha("0.3");
    for (const char* integrator : {"raycast", "path", "bdpt"}) {
        CAPTURE(integrator);
        // 32 x 32 x 16 shadow rays, each stopped with probability 0.3: sd 0.0036, 4 sd.
        CHECK(litFraction(blend, integrator) == doctest::Approx(0.7).epsilon(0.015 / 0.7));
    }
    // stripes-grey.png has no alpha channel: its grey is the alpha, read without a cutoff; its
    // mean over a period is 0.5.
    CHECK(litFraction(withCardAlpha("{ texture = \"stripes-grey.png\" }"), "raycast") ==
          doctest::Approx(0.5).epsilon(0.02));
}

TEST_CASE("cut-outs: an OBJ's map_d and glTF's alphaMode cut the card as their files say") {
    // card.obj's own MTL material: map_d stripes-grey.png.
    CHECK(litFraction(withCard("[[meshes]]\nfile = \"card.obj\"\n"), "raycast") == doctest::Approx(0.5).epsilon(0.02));
    const auto gltf = [](const char* file) {
        return withCard("[[gltf]]\nfile = \"" + std::string(file) + "\"\nlights = false\n");
    };
    CHECK(litFraction(gltf("card-mask.gltf"), "raycast") == doctest::Approx(0.5).epsilon(0.01));
    CHECK(litFraction(gltf("card-blend.gltf"), "raycast") == doctest::Approx(0.7).epsilon(0.015 / 0.7));
    // MASK: alpha 0.3 reaches a cutoff of 0.2 (covered), not the default 0.5 (cut out everywhere,
    // the texture having no alpha channel).
    CHECK(litFraction(gltf("card-mask-low.gltf"), "raycast") == doctest::Approx(0.0));
    CHECK(litFraction(gltf("card-mask-rgb.gltf"), "raycast") == doctest::Approx(1.0).epsilon(1e-4));
    CHECK(litFraction(gltf("card-opaque.gltf"), "raycast") == doctest::Approx(0.0));
}

TEST_CASE("cut-outs: the rasteriser discards the fragments ray casting looks through") {
    // Seen from above under ambient light alone: the card (ka 1) over the floor (ka 0.2), half of it
    // cut out, so the image's mean is 0.5 + 0.5 x 0.2 of the ambient radiance.
    std::string text = shadowText();
    text.replace(text.find("[camera]"), text.find("[materials]") - text.find("[camera]"),
                 "[camera]\neye = [0, 3, 0]\nlook_at = [0, 0, 0]\nup = [0, 0, 1]\nfov = 28.0724869\n"
                 "resolution = [32, 32]\n\n[world]\nambient = 1\n\n");
    text.replace(text.find("floor = "), text.find('\n', text.find("floor = ")) - text.find("floor = "),
                 "floor = { ka = 0.2 }");
    text.replace(text.find("cut = "), text.find('\n', text.find("cut = ")) - text.find("cut = "),
                 "cut = { ka = 1, alpha = { texture = \"stripes-rgba.png\", cutoff = 0.5 } }");
    text.replace(text.find("[[lights]]"), text.find("[[triangles]]") - text.find("[[lights]]"), "");
    const Scene scene = loadSceneFromText(text, kData / "shadow.toml");
    for (const char* integrator : {"raster", "raycast"}) {
        CAPTURE(integrator);
        RenderOptions options;
        options.integrator = integrator;
        const Film film = Renderer(scene, AovSet(classesSet()), options).render().film;
        double sum = 0.0;
        for (int y = 0; y < film.height(); ++y)
            for (int x = 0; x < film.width(); ++x) sum += film.at(0, x, y).r;
        CHECK(sum / (film.width() * film.height()) == doctest::Approx(0.6).epsilon(0.02));
    }
}

TEST_CASE("cut-outs: bad alpha values are located errors, and an emitter is never cut out") {
    const auto fails = [](const std::string& line, const std::string& expected) {
        CAPTURE(line);
        try {
            (void)shadowScene("cut = ", line);
            FAIL("no error");
        } catch (const SceneError& e) {
            CHECK(std::string(e.what()).find(expected) != std::string::npos);
            CHECK(std::string(e.what()).find("shadow.toml:") != std::string::npos);
        }
    };
    fails("cut = { alpha = 1.5 }", "alpha");
    fails("cut = { alpha = { texture = \"stripes-rgba.png\", cutoff = 2 } }", "cutoff");
    fails("cut = { alpha = { texture = \"stripes-rgba.png\", tint = [1, 0.5, 1] } }", "tint");
    fails("cut = { kd = { texture = \"stripes-rgba.png\", cutoff = 0.5 } }", "cutoff");
    fails("cut = { alpha = { texture = \"missing.png\" } }", "missing.png");
    const auto warns = [](const Scene& scene, const std::string& part) {
        for (const std::string& warning : scene.warnings)
            if (warning.find(part) != std::string::npos) return true;
        return false;
    };
    const Scene emitter = shadowScene("cut = ", "cut = { emission = 1, alpha = { texture = \"stripes-rgba.png\", cutoff = 0.5 } }");
    CHECK(emitter.objectCoverage().empty());
    CHECK(warns(emitter, "emits, so its alpha is not read: an emitter is never cut out"));
    // Nor is a medium's boundary: the ball holding smoke stays whole, the card is still cut out.
    std::string text = shadowText();
    text.replace(text.find("[materials]"), 11,
                 "[media.smoke]\nsigma_a = 0.1\nsigma_s = 1\n\n[[spheres]]\ncenter = [0, 0.5, 0]\nradius = 0.2\n"
                 "material = \"cut\"\ninterior = \"smoke\"\n\n[materials]");
    const Scene medium = loadSceneFromText(text, kData / "shadow.toml");
    const auto coverage = medium.objectCoverage();
    REQUIRE(coverage.size() == medium.objects.size());
    for (std::uint32_t i = 0; i < medium.objects.size(); ++i) {
        CAPTURE(medium.labelOf(i));
        const bool cut = medium.materials[medium.objects[i].material]->alpha != nullptr;
        CHECK((coverage[i] != nullptr) == (cut && medium.objects[i].interior == kNoMedium));
    }
    CHECK(warns(medium, "bounds a medium (interior), so its alpha is not read"));
    CHECK(!warns(emitter, "bounds a medium"));
}

}  // namespace cutout_tests
}  // namespace lightpath
