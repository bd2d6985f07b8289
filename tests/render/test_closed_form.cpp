// Pixels whose visible point, normal, light vector and half vector are worked out by hand, checked
// against Szymczak's illumination formula evaluated here in double precision, term by term through
// the light path expressions that select each term.
#include <doctest/doctest.h>

#include <cmath>

#include "film/aov_set.h"
#include "render/renderer.h"
#include "scene_builder.h"
#include "film/aov_presets.h"

namespace lightpath {
namespace {

using test::addMaterial;
using test::addPlane;
using test::addSphere;
using test::centredCamera;

// One light path expression per term of the formula, plus the whole beauty.
const std::vector<lpe::NamedExpression> kTerms = {
    {"ambient", "E D <L'ambient'>"},
    {"diffuse", "E D <L'key'>"},
    {"highlight", "E G <L'key'>"},
};

Rgb centrePixel(const Scene& scene, std::size_t layer, const std::string& integrator = "whitted") {
    const AovSet aovs(kTerms);
    RenderOptions options;
    options.integrator = integrator;
    options.threads = 1;
    const RenderResult result = Renderer(scene, aovs, options).render();
    return result.film.at(layer, scene.camera.width / 2, scene.camera.height / 2);
}

constexpr std::size_t kBeauty = 0, kAmbient = 1, kDiffuse = 2, kHighlight = 3;

// A floor y = 0 seen from straight above; the centre pixel sees the origin, N = (0,1,0), V = N.
Scene floorUnderLight(Vec3 attenuation) {
    Scene scene;
    scene.camera = centredCamera({0, 5, 0}, {0, 0, 0}, {0, 0, -1});
    scene.ambient = Rgb{0.5f, 0.25f, 1.0f};
    PhongMaterial m;
    m.name = "floor";
    m.ka = {0.2f, 0.4f, 0.1f};
    m.kd = {0.7f, 0.5f, 0.3f};
    m.ks = {0.3f, 0.3f, 0.6f};
    m.n = 8.0f;
    addPlane(scene, "floor", addMaterial(scene, m), {0, 0, 0}, {0, 1, 0});
    scene.lights.push_back(PointLight{"key", {3, 4, 0}, Rgb{2.0f, 1.0f, 0.5f}, attenuation});
    return scene;
}

TEST_CASE("floor under a point light: ambient, diffuse and highlight terms by their LPEs") {
    for (const Vec3 attenuation : {Vec3{1, 0, 0}, Vec3{0, 0, 1}, Vec3{0.5f, 0.2f, 0.04f}}) {
        CAPTURE(attenuation.y);
        const Scene scene = floorUnderLight(attenuation);
        // By hand: p = 0, b - p = (3,4,0), d = 5, L = (0.6,0.8,0), N.L = 0.8,
        // H = (L + V)/|L + V| = (0.6,1.8,0)/sqrt(3.6), H.N = 1.8/sqrt(3.6).
        const double d = 5.0, nDotL = 0.8, hDotN = 1.8 / std::sqrt(3.6);
        const double att = 1.0 / (attenuation.x + attenuation.y * d + attenuation.z * d * d);
        const double intensity[3] = {2.0, 1.0, 0.5};
        const Rgb ambient = centrePixel(scene, kAmbient);
        const Rgb diffuse = centrePixel(scene, kDiffuse);
        const Rgb highlight = centrePixel(scene, kHighlight);
        const Rgb beauty = centrePixel(scene, kBeauty);
        const auto& m = phongOf(scene.materials[0]);
        for (int c = 0; c < 3; ++c) {
            const double expectAmbient = double(m.ka.constant()[c]) * double(scene.ambient[c]);
            const double expectDiffuse = intensity[c] * att * double(m.kd.constant()[c]) * nDotL;
            const double expectHighlight = intensity[c] * att * double(m.ks.constant()[c]) * std::pow(hDotN, 8.0);
            CHECK(ambient[c] == doctest::Approx(expectAmbient).epsilon(1e-5));
            CHECK(diffuse[c] == doctest::Approx(expectDiffuse).epsilon(1e-5));
            CHECK(highlight[c] == doctest::Approx(expectHighlight).epsilon(1e-5));
            CHECK(beauty[c] == doctest::Approx(expectAmbient + expectDiffuse + expectHighlight).epsilon(1e-5));
        }
    }
}

TEST_CASE("nearest point of a sphere: N = V, the formula with the light off-axis") {
    Scene scene;
    scene.camera = centredCamera({0, 0, 10}, {0, 0, 0}, {0, 1, 0});
    PhongMaterial m;
    m.name = "ball";
    m.kd = Rgb{0.6f};
    m.ks = Rgb{0.4f};
    m.n = 20.0f;
    addSphere(scene, "ball", addMaterial(scene, m), {0, 0, 0}, 2.0f);
    // p = (0,0,2), N = (0,0,1); light at (0,3,6): b - p = (0,3,4), d = 5, N.L = 0.8,
    // H = ((0,0.6,0.8) + (0,0,1)) normalised, H.N = 1.8/sqrt(3.6).
    scene.lights.push_back(PointLight{"key", {0, 3, 6}, Rgb{1.0f}, {0, 0, 1}});
    const double att = 1.0 / 25.0;
    const double hDotN = 1.8 / std::sqrt(3.6);
    for (const char* integrator : {"raycast", "whitted"}) {
        CAPTURE(integrator);
        CHECK(centrePixel(scene, kDiffuse, integrator).g == doctest::Approx(att * 0.6 * 0.8).epsilon(1e-5));
        CHECK(centrePixel(scene, kHighlight, integrator).g ==
              doctest::Approx(att * 0.4 * std::pow(hDotN, 20.0)).epsilon(1e-5));
    }
}

TEST_CASE("a light behind the surface adds nothing: the own-primitive test N.(b - p) < 0") {
    Scene scene = floorUnderLight({1, 0, 0});
    pointLightOf(scene.lights[0]).location = {3, -4, 0};
    CHECK(centrePixel(scene, kDiffuse).r == 0.0f);
    CHECK(centrePixel(scene, kHighlight).r == 0.0f);
    CHECK(centrePixel(scene, kAmbient).r == doctest::Approx(0.2 * 0.5));
}

TEST_CASE("a point in shadow gets only the ambient term") {
    Scene scene = floorUnderLight({1, 0, 0});
    PhongMaterial blocker;
    blocker.name = "blocker";
    blocker.kd = Rgb{1.0f};
    // A small sphere on the segment from the origin to the light at (3,4,0).
    addSphere(scene, "blocker", addMaterial(scene, blocker), {1.5f, 2.0f, 0.0f}, 0.5f);
    const Rgb beauty = centrePixel(scene, kBeauty);
    const auto& m = phongOf(scene.materials[0]);
    for (int c = 0; c < 3; ++c) CHECK(beauty[c] == doctest::Approx(double(m.ka.constant()[c]) * double(scene.ambient[c])));
}

TEST_CASE("a mirror seen straight on returns kr times what it reflects") {
    Scene scene;
    scene.camera = centredCamera({0, 0, 5}, {0, 0, 0}, {0, 1, 0});
    scene.background = Rgb{0.2f, 0.4f, 0.8f};
    scene.ambient = Rgb{1.0f};
    PhongMaterial mirror;
    mirror.name = "mirror";
    mirror.kr = {0.9f, 0.5f, 0.25f};
    addPlane(scene, "mirror", addMaterial(scene, mirror), {0, 0, 0}, {0, 0, 1});

    const std::vector<lpe::NamedExpression> set = {{"mirror", "E<RS>L"}, {"raytrace", "ES+DL"}};
    const AovSet aovs(set);
    RenderOptions options;
    SUBCASE("the background, through the mirror") {
        const Film film = Renderer(scene, aovs, options).render().film;
        const Rgb seen = film.at(1, 4, 4);
        for (int c = 0; c < 3; ++c) CHECK(seen[c] == doctest::Approx(double(mirror.kr.constant()[c]) * scene.background[c]));
    }
    SUBCASE("an ambient-lit wall behind the camera, through the mirror") {
        PhongMaterial wall;
        wall.name = "wall";
        wall.ka = {0.3f, 0.6f, 0.9f};
        addPlane(scene, "wall", addMaterial(scene, wall), {0, 0, 20}, {0, 0, -1});
        const Film film = Renderer(scene, aovs, options).render().film;
        const Rgb seen = film.at(2, 4, 4);
        for (int c = 0; c < 3; ++c) CHECK(seen[c] == doctest::Approx(double(mirror.kr.constant()[c]) * wall.ka.constant()[c]));
        CHECK(film.at(1, 4, 4) == Rgb{0.0f});
    }
}

TEST_CASE("a pixel that misses everything gets the background, in the emission AOV") {
    Scene scene;
    scene.camera = centredCamera({0, 0, 5}, {0, 0, 0}, {0, 1, 0});
    scene.background = Rgb{0.1f, 0.2f, 0.3f};
    const AovSet aovs(classesSet());
    const Film film = Renderer(scene, aovs, RenderOptions{}).render().film;
    const auto names = aovs.layerNames();
    for (std::size_t l = 0; l < names.size(); ++l) {
        CAPTURE(names[l]);
        const bool lit = names[l] == "beauty" || names[l] == "emission";
        CHECK(film.at(l, 3, 5) == (lit ? scene.background : Rgb{0.0f}));
    }
}

}  // namespace
}  // namespace lightpath
