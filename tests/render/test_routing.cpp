// Each term lands in the AOV its expression names: the events of every contribution to a pixel,
// checked against paths written out by hand, and each AOV against the closed form of the one term
// it should hold. (Sending the diffuse term through the glossy event leaves every sum intact; only
// routing checks like these see it.)
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

#include "film/aov_set.h"
#include "render/renderer.h"
#include "render_world.h"
#include "scene_builder.h"

namespace lightpath {
namespace {

using lpe::EventType;
using lpe::Scatter;

constexpr float kKd = 0.5f, kKs = 0.3f, kN = 10.0f, kKa = 0.2f, kAmbient = 0.1f, kIntensity = 2.0f, kKr = 0.8f;

// A matte, glossy floor under one light named "key", with an ambient term.
Scene floorScene(Vec3 eye, Vec3 lookAt, Vec3 light) {
    Scene scene;
    scene.camera = test::centredCamera(eye, lookAt, {0, 1, 0}, 9);
    scene.ambient = Rgb{kAmbient};
    PhongMaterial floor;
    floor.name = "floor-material";
    floor.kd = Rgb{kKd};
    floor.ks = Rgb{kKs};
    floor.n = kN;
    floor.ka = Rgb{kKa};
    test::addPlane(scene, "floor", test::addMaterial(scene, floor), {0, 0, 0}, {0, 1, 0});
    scene.lights.push_back(PointLight{"key", light, Rgb{kIntensity}, {1, 0, 0}});
    return scene;
}

struct ExpectedEvent {
    EventType type;
    Scatter scatter;
    Subject subject;
    std::uint32_t index;
};

bool sameEvents(const PathRecord& path, const std::vector<ExpectedEvent>& expected) {
    if (path.size() != expected.size()) return false;
    for (std::size_t i = 0; i < expected.size(); ++i) {
        const PathEvent& e = path[i];
        if (e.type != expected[i].type || e.scatter != expected[i].scatter || e.subject != expected[i].subject ||
            e.index != expected[i].index)
            return false;
    }
    return true;
}

// The contribution to the centre pixel whose path is `expected`: exactly one must exist.
Rgb contributionOf(const std::vector<LoggedContribution>& log, const std::vector<ExpectedEvent>& expected) {
    int found = 0;
    Rgb value{0.0f};
    for (const LoggedContribution& c : log) {
        if (!sameEvents(c.path, expected)) continue;
        ++found;
        value = c.value;
    }
    CHECK(found == 1);
    return value;
}

const ExpectedEvent kEye{EventType::Camera, Scatter::None, Subject::None, 0};
const ExpectedEvent kKey{EventType::Emitter, Scatter::None, Subject::SceneLight, 0};
const ExpectedEvent kAmbientLight{EventType::Emitter, Scatter::None, Subject::Ambient, 0};

std::size_t layerIndex(const AovSet& aovs, const std::string& name) {
    const auto names = aovs.layerNames();
    return static_cast<std::size_t>(std::find(names.begin(), names.end(), name) - names.begin());
}

TEST_CASE("routing: ray casting's three terms, each on its own path and in its own AOV") {
    const glm::dvec3 eye{0, 2, 3}, light{1, 3, 1};
    const Scene scene = floorScene(Vec3(eye), {0, 0, 0}, Vec3(light));
    const std::uint32_t floor = 0;
    // The centre pixel sees the origin; N = +y. Szymczak's terms, in double, by hand.
    const glm::dvec3 l = glm::normalize(light), v = glm::normalize(eye), h = glm::normalize(l + v);
    const double diffuse = kKd * kIntensity * l.y;
    const double highlight = kKs * kIntensity * std::pow(h.y, double(kN));
    const double ambient = kKa * kAmbient;

    const AovSet aovs({{"d", "E<RD'floor'><L'key'>"}, {"g", "E<RG'floor'><L'key'>"}, {"amb", "E.*<L'ambient'>"}});
    RenderOptions options;
    options.integrator = "raycast";
    const Renderer renderer(scene, aovs, options);

    const auto log = renderer.explainPixel(4, 4);
    CHECK(log.size() == 3);
    const ExpectedEvent rd{EventType::Reflection, Scatter::Diffuse, Subject::Object, floor};
    const ExpectedEvent rg{EventType::Reflection, Scatter::Glossy, Subject::Object, floor};
    CHECK(contributionOf(log, {kEye, rd, kKey}).g == doctest::Approx(diffuse).epsilon(1e-4).scale(0));
    CHECK(contributionOf(log, {kEye, rg, kKey}).g == doctest::Approx(highlight).epsilon(1e-4).scale(0));
    CHECK(contributionOf(log, {kEye, rd, kAmbientLight}).g == doctest::Approx(ambient).epsilon(1e-5));

    const Film film = renderer.render().film;
    CHECK(film.at(layerIndex(aovs, "d"), 4, 4).g == doctest::Approx(diffuse).epsilon(1e-4).scale(0));
    CHECK(film.at(layerIndex(aovs, "g"), 4, 4).g == doctest::Approx(highlight).epsilon(1e-4).scale(0));
    CHECK(film.at(layerIndex(aovs, "amb"), 4, 4).g == doctest::Approx(ambient).epsilon(1e-5));
    CHECK(film.at(layerIndex(aovs, "rest"), 4, 4).g == 0.0f);
}

TEST_CASE("routing: Whitted's mirror ray adds <RS'mirror'> before the floor's events") {
    // A mirror tilted 45 degrees in front of the camera turns the centre ray down onto the origin.
    const glm::dvec3 light{1, 0.5, 3};
    Scene scene = floorScene({0, 1, 5}, {0, 1, 0}, Vec3(light));
    PhongMaterial mirror;
    mirror.name = "silver";
    mirror.kr = Rgb{kKr};
    test::addPlane(scene, "mirror", test::addMaterial(scene, mirror), {0, 1, 0}, {0, -1, 1});
    const std::uint32_t floor = 0, mirrorObject = 1;
    const glm::dvec3 l = glm::normalize(light), v{0, 1, 0};  // at the origin, towards the mirror
    const glm::dvec3 h = glm::normalize(l + v);
    const double diffuse = kKr * kKd * kIntensity * l.y;
    const double highlight = kKr * kKs * kIntensity * std::pow(h.y, double(kN));

    const AovSet aovs({{"m", "E<RS'mirror'><RD'floor'><L'key'>"}, {"direct", "E(D|G)L"}, {"mg", "ES+GL"}});
    RenderOptions options;
    options.integrator = "whitted";
    const Renderer renderer(scene, aovs, options);
    const auto log = renderer.explainPixel(4, 4);
    const ExpectedEvent rs{EventType::Reflection, Scatter::Specular, Subject::Object, mirrorObject};
    const ExpectedEvent rd{EventType::Reflection, Scatter::Diffuse, Subject::Object, floor};
    const ExpectedEvent rg{EventType::Reflection, Scatter::Glossy, Subject::Object, floor};
    CHECK(contributionOf(log, {kEye, rs, rd, kKey}).g == doctest::Approx(diffuse).epsilon(1e-4).scale(0));
    CHECK(contributionOf(log, {kEye, rs, rg, kKey}).g == doctest::Approx(highlight).epsilon(1e-4).scale(0));
    CHECK(contributionOf(log, {kEye, rs, rd, kAmbientLight}).g == doctest::Approx(kKr * kKa * kAmbient).epsilon(1e-4).scale(0));

    const Film film = renderer.render().film;
    CHECK(film.at(layerIndex(aovs, "m"), 4, 4).g == doctest::Approx(diffuse).epsilon(1e-4).scale(0));
    CHECK(film.at(layerIndex(aovs, "mg"), 4, 4).g == doctest::Approx(highlight).epsilon(1e-4).scale(0));
    CHECK(film.at(layerIndex(aovs, "direct"), 4, 4).g == 0.0f);  // the mirror has no D or G of its own
}

TEST_CASE("explain: Szymczak's factors multiply to the term, and a blocked light says what blocks it") {
    const glm::dvec3 eye{0, 2, 3}, light{1, 3, 1};
    Scene scene = floorScene(Vec3(eye), {0, 0, 0}, Vec3(light));
    // A second light straight above the origin, hidden behind a ball named "blocker" at height 1.
    scene.lights.push_back(PointLight{"top", {0, 4, 0}, Rgb{1.0f}, {1, 0, 0}});
    PhongMaterial grey;
    grey.name = "grey";
    grey.kd = Rgb{0.5f};
    test::addSphere(scene, "blocker", test::addMaterial(scene, grey), {0, 1, 0}, 0.25f);
    const AovSet aovs(std::vector<lpe::NamedExpression>{});
    RenderOptions options;
    options.integrator = "raycast";
    std::vector<Rejection> rejections;
    const auto log = Renderer(scene, aovs, options).explainPixel(4, 4, &rejections);

    const ExpectedEvent rd{EventType::Reflection, Scatter::Diffuse, Subject::Object, 0};
    int checked = 0;
    for (const LoggedContribution& c : log) {
        if (!sameEvents(c.path, {kEye, rd, kKey})) continue;
        REQUIRE(c.factorCount == 4);
        const char* names[] = {"kd", "N.L", "I", "attenuation"};
        Rgb product{1.0f};
        for (std::size_t f = 0; f < 4; ++f) {
            CHECK(std::string(c.factors[f].name) == names[f]);
            product *= c.factors[f].value;
        }
        CHECK(c.factors[1].value.g == doctest::Approx(glm::normalize(light).y).epsilon(1e-5));
        CHECK(c.factors[2].value.g == doctest::Approx(kIntensity).epsilon(1e-5));
        CHECK(product.g == doctest::Approx(c.value.g).epsilon(1e-5));
        ++checked;
    }
    CHECK(checked == 1);
    // The shadow ray from the origin to (0, 4, 0) meets the ball's bottom at t = 0.75.
    bool blocked = false;
    for (const Rejection& r : rejections)
        blocked |= r.reason.find("towards top is blocked by blocker at t = 0.750") != std::string::npos;
    CHECK(blocked);
}


TEST_CASE("the path's event stack refuses the event that would overflow it, in Release too") {
    // An integrator that pushes more events than kMaxPathEvents (a new one, or a longer maxDepth)
    // must stop that branch, as at a dead state, not write past the end of a std::array.
    const test::RenderWorld world(floorScene({0, 1, 3}, {0, 0, 0}, {0, 2, 0}));
    ContributionSink sink({}, nullptr);
    RayCounters counters;
    PathState path(world.context, sink, counters);
    const PathEvent bounce{EventType::Reflection, Scatter::Diffuse, Subject::Object, 0, Vec3{0.0f}};
    REQUIRE(path.push({EventType::Camera, Scatter::None, Subject::None, 0, Vec3{0.0f}}));
    // The camera, kMaxDepth bounces, one more surface: what the longest allowed path pushes.
    for (int i = 0; i <= kMaxDepth; ++i) REQUIRE(path.push(bounce));
    int accepted = 0;
    while (accepted < 100 && path.push(bounce)) ++accepted;
    CHECK(accepted < 100);
    CHECK(path.size() <= kMaxPathEvents - 2);  // room for emit()'s surface and light
    const std::size_t full = path.size();
    CHECK_FALSE(path.push(bounce));
    CHECK(path.size() == full);
    CHECK(counters.eventOverflow == 2);  // counted, for --stats
    path.pop();
    CHECK(path.push(bounce));  // room again after a pop
}

}  // namespace
}  // namespace lightpath
