// The judge reads what a scene can produce (issue #30): the events its materials' lobes scatter by
// and the emitters its lights and surfaces end paths with. An expression no path of those events
// can match is black in that scene, said with the cause and a fix; a preset's AOV is written black
// and noted, never warned about nor refused. Each rule is checked on a scene that lacks what it
// needs and, as the control, on the same scene with that one thing added. The scenes are written
// here by hand; the expected causes are the lobes and emitters they were written without.
#include <doctest/doctest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "config/lpe_verdict.h"
#include "config/render_config.h"
#include "integrators/registry.h"
#include "scene/scene_loader.h"
#include "serve/request_error.h"
#include "serve/settings.h"

using namespace lightpath;

namespace {

// A matte floor under one point light, a black sky, no ambient light: it scatters only by <RD>,
// and its only emitter is never hit by a ray.
const std::string kMatteRoom = R"(
[camera]
eye = [0, 1, 5]
look_at = [0, 0, 0]
up = [0, 1, 0]
fov = 40
resolution = [8, 6]

[materials.matte]
ka = 0.5
kd = 0.5

[[lights]]
name = "lamp"
position = [0, 3, 0]

[[planes]]
name = "floor"
point = [0, 0, 0]
normal = [0, 1, 0]
material = "matte"
)";

// One sphere of `material` (a TOML inline table's body) in the room.
std::string withBall(const std::string& material) {
    return "[materials.ball]\n" + material + "\n[[spheres]]\nname = \"ball\"\ncenter = [0, 1, 0]\nradius = 1\nmaterial = \"ball\"\n";
}

Scene load(const std::string& text) { return loadSceneFromText(text, "judge-test.toml"); }

Judgement judge(const std::string& expression, const Scene& scene, const char* integrator = "path") {
    return judgeExpression({"x", expression}, findIntegrator(integrator), &scene);
}

struct Rule {
    std::string expression;
    std::string added;  // what the room lacks for it (TOML appended to kMatteRoom)
    std::string cause;  // a part of the reason given without it
};

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST_CASE("the scene's events: an expression needing what no material or light of the scene produces is black there") {
    const std::vector<Rule> rules = {
        {"ES+DL", withBall("kr = 0.9"), "no material has a mirror lobe"},
        {"E.*<TS>.*", withBall("kt = 0.9"), "no material has a refraction lobe"},
        {"E<RG>L", withBall("ks = 0.5"), "no material has a glossy lobe"},
        {"E.*O", withBall("kd = 0.5\nemission = 2"), "no surface emits"},
        {"E.*B", "[world]\nbackground = 0.5\n", "the background is black"},
        {"E<L>", "[[lights]]\ntype = \"quad\"\ncorner = [-1, 2, -1]\nedge1 = [2, 0, 0]\nedge2 = [0, 0, 2]\nradiance = 1\n",
         "no light a ray can hit"},
        {"E.*<L'ambient'>", "[world]\nambient = 0.2\n", "no ambient light"},
    };
    const Scene room = load(kMatteRoom);
    for (const Rule& rule : rules) {
        CAPTURE(rule.expression);
        // Whitted adds the ambient term; the path tracer follows every other path.
        const char* integrator = contains(rule.expression, "ambient") ? "whitted" : "path";
        const Judgement without = judge(rule.expression, room, integrator);
        CHECK(without.verdict == Verdict::BlackHere);
        CHECK_MESSAGE(contains(without.reason, rule.cause), without.reason);
        const Judgement with = judge(rule.expression, load(kMatteRoom + rule.added), integrator);
        CHECK_MESSAGE(with.verdict == Verdict::Fillable, with.reason);
    }
}

TEST_CASE("the scene's events: a volume event needs a medium that scatters, not one that only absorbs") {
    const auto glassBall = [](const std::string& medium) {
        return kMatteRoom + "[media.inside]\ntype = \"homogeneous\"\n" + medium + "\n" + withBall("kt = 0.9") +
               "interior = \"inside\"\n";
    };
    const Judgement tinted = judge("E.*V.*L", load(glassBall("sigma_a = 0.5")));
    CHECK(tinted.verdict == Verdict::BlackHere);
    CHECK_MESSAGE(contains(tinted.reason, "no medium that scatters"), tinted.reason);
    const Judgement milky = judge("E.*V.*L", load(glassBall("sigma_a = 0.5\nsigma_s = 0.1")));
    CHECK_MESSAGE(milky.verdict == Verdict::Fillable, milky.reason);
}

TEST_CASE("the scene's events: a light path needs a light, and a point light is reached only after a diffuse or glossy event") {
    std::string dark = kMatteRoom;
    dark.erase(dark.find("[[lights]]"), std::string("[[lights]]\nname = \"lamp\"\nposition = [0, 3, 0]\n").size());
    const Judgement unlit = judge("ED<L>", load(dark + "[world]\nbackground = 0.5\n"));
    CHECK(unlit.verdict == Verdict::BlackHere);
    CHECK_MESSAGE(contains(unlit.reason, "no light"), unlit.reason);
    CHECK(judge("ED<L>", load(kMatteRoom)).verdict == Verdict::Fillable);
    // Seen through a mirror, a point light is still never hit.
    const Scene mirror = load(kMatteRoom + withBall("kr = 0.9"));
    CHECK(judge("ES<L>", mirror).verdict == Verdict::BlackHere);
    CHECK(judge("ESD<L>", mirror).verdict == Verdict::Fillable);
}

TEST_CASE("the scene's events: the warning names the cause, a preset's black AOV is noted instead") {
    const Scene room = load(kMatteRoom);
    RenderConfig config;
    config.integrator = "path";
    config.lpes = {"s=ES+DL"};
    std::vector<std::string> warnings;
    config.buildAovSet(room, &warnings);
    REQUIRE(warnings.size() == 1);
    CHECK(warnings[0].rfind("AOV s (ES+DL) stays black: in this scene no material has a mirror lobe", 0) == 0);

    // classes' raytrace and mirror need a mirror or glass, emission a light a ray can hit (the
    // point light is not one) or a sky, volume a medium: written black, no warning, noted.
    config.lpes.clear();
    config.aovs = "classes";
    warnings.clear();
    const AovSet set = config.buildAovSet(room, &warnings);
    CHECK(warnings.empty());
    std::vector<std::string> black;
    for (const BlackAov& b : blackPresetAovs(set.expressions(), Judge(findIntegrator("path"), &room))) {
        black.push_back(b.name);
        CHECK(b.inThisScene);
    }
    CHECK(black == std::vector<std::string>{"raytrace", "mirror", "emission", "volume"});
    // The control: a mirror ball, a sky to see in it and fog, and every class can be filled.
    const Scene lit = load(kMatteRoom + withBall("kr = 0.9") +
                           "[world]\nbackground = 0.5\nmedium = \"fog\"\n[media.fog]\nsigma_s = 0.1\n");
    CHECK(blackPresetAovs(config.buildAovSet(lit).expressions(), Judge(findIntegrator("path"), &lit)).empty());
}

TEST_CASE("the ambient term: only raycast, raster and whitted add it, and the lights preset's group stays usable") {
    // The user's own expression is refused under the methods that gather no ambient term ...
    for (const std::string name : {"path", "bdpt", "radiosity"}) {
        CAPTURE(name);
        const Judgement judgement = judgeExpression({"x", "E.*<L'ambient'>"}, findIntegrator(name));
        CHECK(judgement.verdict == Verdict::Refused);
        CHECK_MESSAGE(contains(judgement.reason, "--integrator raycast or --integrator raster or --integrator whitted"),
                      judgement.reason);
    }
    for (const char* name : {"raycast", "raster", "whitted"})
        CHECK(judgeExpression({"x", "E.*<L'ambient'>"}, findIntegrator(name)).verdict == Verdict::Fillable);

    // ... while the lights preset, whose ambient group the scene makes, is written black under them.
    const Scene room = load(kMatteRoom + "[world]\nambient = 0.2\n");
    RenderConfig config;
    config.integrator = "path";
    config.aovs = "lights";
    std::vector<std::string> warnings;
    const AovSet set = config.buildAovSet(room, &warnings);
    CHECK(warnings.empty());
    const auto black = blackPresetAovs(set.expressions(), Judge(findIntegrator("path"), &room));
    REQUIRE(black.size() == 1);
    CHECK(black[0].name == "ambient");
    CHECK_FALSE(black[0].inThisScene);

    // serve, given the scene, accepts the preset's group and refuses the same expression under another name.
    const serve::Settings start = serve::defaultSettings(room);
    const nlohmann::json group = {{"integrator", "path"},
                                  {"lpes", {{{"name", "ambient"}, {"expression", "E.*<L.'ambient'>"}}}}};
    CHECK_NOTHROW(serve::applySettings(start, group.dump(), nullptr, &room));
    const nlohmann::json own = {{"integrator", "path"}, {"lpes", {{{"name", "x"}, {"expression", "E.*<L.'ambient'>"}}}}};
    CHECK_THROWS_AS(serve::applySettings(start, own.dump(), nullptr, &room), serve::RequestError);
}

TEST_CASE("the scene's events on their labels: an object named in an expression scatters by its own material's lobes") {
    const Scene room = load(kMatteRoom + withBall("kr = 0.9"));
    const Judgement floor = judge("E<RS'floor'>.*", room);
    CHECK(floor.verdict == Verdict::BlackHere);
    CHECK(floor.reason == "in this scene floor has no mirror lobe <RS>: its material scatters only by <RD>");
    // The control: the ball is the mirror.
    CHECK(judge("E<RS'ball'>.*", room).verdict == Verdict::Fillable);
    CHECK(judge("E<RD'floor'>.*", room).verdict == Verdict::Fillable);
    const Judgement ball = judge("E<RD'ball'>L", room);
    CHECK(ball.verdict == Verdict::BlackHere);
    CHECK(ball.reason == "in this scene ball has no diffuse lobe <RD>: its material scatters only by <RS>");
}
