// Real-world expressions, as printed in production renderers' manuals and OSL's wiki, on paths
// written by hand as lightpath's renderer produces them: every event labelled (surfaces with their
// object's name, lights with theirs), a [[lights]] quad as L, an emitting mesh as O, the sky as B.
// Each expected set was worked out by hand from OSL's grammar (lpeparse.cpp) and lightpath's
// documented differences (docs/lpe.md); every path not listed must not match.
#include <doctest/doctest.h>

#include <map>
#include <set>
#include <string>
#include <vector>

#include "lpe/analysis.h"
#include "lpe/automaton.h"
#include "lpe/reading.h"
#include "test_paths.h"

namespace {

using lpe::EventType;
using lpe::Scatter;
using lpe_test::event;

const lpe::Event kEye = event(EventType::Camera);
lpe::Event rd(const char* label) { return event(EventType::Reflection, Scatter::Diffuse, label); }
lpe::Event rg(const char* label) { return event(EventType::Reflection, Scatter::Glossy, label); }
lpe::Event rs(const char* label) { return event(EventType::Reflection, Scatter::Specular, label); }
lpe::Event ts(const char* label) { return event(EventType::Transmission, Scatter::Specular, label); }
lpe::Event light(const char* label) { return event(EventType::Emitter, Scatter::None, label); }
lpe::Event object(const char* label) { return event(EventType::ObjectEmission, Scatter::None, label); }
const lpe::Event kSky = event(EventType::Background);

const std::map<std::string, lpe::Path>& paths() {
    static const std::map<std::string, lpe::Path> all = {
        {"dl", {kEye, rd("floor"), light("key")}},                       // E D L, lit by the key light
        {"gl", {kEye, rg("floor"), light("key")}},                       // the highlight
        {"sb", {kEye, rs("mirror-ball"), kSky}},                         // the sky in the mirror
        {"sdl", {kEye, rs("mirror-ball"), rd("floor"), light("key")}},   // the lit floor in the mirror
        {"ddl", {kEye, rd("floor"), rd("back-wall"), light("fill")}},    // indirect diffuse
        {"dsl", {kEye, rd("floor"), rs("mirror-ball"), light("key")}},   // a caustic
        {"quad", {kEye, light("quad-light")}},                           // a [[lights]] quad seen
        {"lamp", {kEye, object("ceiling-lamp")}},                        // an MTL Ke surface seen
        {"sky", {kEye, kSky}},
        {"dO", {kEye, rd("floor"), object("ceiling-lamp")}},             // lit by an emitting object
        {"glass", {kEye, ts("glass-ball"), ts("glass-ball"), rd("floor"), light("key")}},
        {"amb", {kEye, rd("floor"), light("ambient")}},                  // the ambient term
        {"coat", {kEye, rs("coat"), rd("floor"), light("key")}},         // an object named coat
        {"sheen", {kEye, rd("floor"), rg("sheen"), light("key")}},
        {"dB", {kEye, rd("floor"), kSky}},                               // a diffuse bounce to the sky
    };
    return all;
}

struct Case {
    const char* source;
    std::string expression;
    std::set<std::string> matches;
};

void checkCase(const Case& c) {
    CAPTURE(c.source);
    CAPTURE(c.expression);
    const lpe::Automaton automaton = lpe::Automaton::compile({{"x", c.expression}});
    // Not a structured binding: CAPTURE's lambda captures `name`, which clang 14 refuses for bindings.
    for (const auto& entry : paths()) {
        const auto& name = entry.first;
        const auto& path = entry.second;
        CAPTURE(name);
        CHECK(automaton.matches(path, 0) == (c.matches.count(name) == 1));
    }
}

}  // namespace

TEST_CASE("Arnold's built-in AOVs, as its user guide prints them") {
    const std::vector<Case> cases = {
        // [DSVOB] is OSL's set: a D or S event, a volume, an emitting object or the background, not
        // a light; Arnold has no G, so a glossy second bounce (sheen) is not indirect there either.
        {"Arnold diffuse_indirect", "C<RD>[DSVOB].*", {"ddl", "dsl", "dO", "dB"}},
        {"Arnold specular_indirect", "C<RS[^'coat''sheen']>[DSVOB].*", {"sb", "sdl"}},
        {"Arnold emission", "C[LO]", {"quad", "lamp"}},
        {"Arnold background", "CB", {"sky"}},
        {"Arnold diffuse_direct", "C<RD>L", {"dl", "amb", "dO", "dB"}},  // bare L: every emitter
        {"Arnold transmission", "C<TS>.*", {"glass"}},
        {"Arnold coat", "C<RS'coat'>.*", {"coat"}},
        {"Arnold volume", "CV.*", {}},  // lightpath renders no volumes
        // direct C[DSV]L: lightpath's bare L also takes O and B (OSL's would give dl, amb only).
        {"Arnold direct", "C[DSV]L", {"dl", "sb", "amb", "dO", "dB"}},
        {"Arnold direct, OSL's L spelt out", "C[DSV]<L>", {"dl", "amb"}},
        {"Arnold indirect", "C[DSV][DSVOB].*", {"sb", "sdl", "ddl", "dsl", "dO", "glass", "coat", "dB"}},
    };
    for (const Case& c : cases) checkCase(c);
}

TEST_CASE("Arnold's direct and indirect are disjoint once L is spelt as OSL's <L>") {
    const lpe::SetReport asPrinted = lpe::analyse({{"direct", "C[DSV]L"}, {"indirect", "C[DSV][DSVOB].*"}});
    REQUIRE(asPrinted.overlaps.size() == 1);  // e.g. E S B: the sky in a mirror is both
    const lpe::SetReport spelt = lpe::analyse({{"direct", "C[DSV]<L>"}, {"indirect", "C[DSV][DSVOB].*"}});
    CHECK(spelt.overlaps.empty());
}

TEST_CASE("light groups and emission, as OSL's wiki, RenderMan and Karma write them") {
    const std::vector<Case> cases = {
        {"Arnold light group", "C.*[<L.'key'>O]", {"dl", "gl", "sdl", "dsl", "lamp", "dO", "glass", "coat", "sheen"}},
        {"OSL wiki beauty", "C[SGs]*D*<Ts>*[LO]", {"dl", "gl", "sdl", "ddl", "quad", "lamp", "dO", "glass", "amb", "coat"}},
        {"Karma emissive objects", "C.*O", {"lamp", "dO"}},
        {"RenderMan light group", "C.*<L.'key'>", {"dl", "gl", "sdl", "dsl", "glass", "coat", "sheen"}},
        {"RenderMan lpe group", "C<RD'floor'>[LO]", {"dl", "amb", "dO"}},
        {"RenderMan direct reflection", "CR[LO]", {"dl", "gl", "amb", "dO"}},
        {"OSL x: no scattering", "C.*<Lx'key'>", {"dl", "gl", "sdl", "dsl", "glass", "coat", "sheen"}},
        {"lightpath shorthand", "E.*<L'key'>", {"dl", "gl", "sdl", "dsl", "glass", "coat", "sheen"}},
        // From OSL's own accumulator test (accum_test.cpp's rules), on lightpath's paths.
        {"OSL reflections", "C<R[^D]>+D*L", {"sb", "sdl", "gl", "coat"}},
        {"OSL specular", "C<.[SG]>+D*L", {"gl", "sb", "sdl", "glass", "coat"}},
    };
    for (const Case& c : cases) checkCase(c);
}

TEST_CASE("the lecture's taxonomy slide, as printed (Heckbert's [ ] = optional)") {
    const std::vector<Case> cases = {
        {"ray casting", "E(D|G)L", {"dl", "gl", "amb", "dO", "dB"}},
        {"ray tracing", "E[S*](D|G)L", {"dl", "gl", "sdl", "amb", "dO", "dB", "glass", "coat"}},
        {"path tracing (issue)", "E[(D|G|S)+(D|G)]L", {"quad", "lamp", "sky", "sdl", "ddl", "glass", "coat", "sheen"}},
        {"radiosity", "ED*L", {"quad", "lamp", "sky", "dl", "ddl", "amb", "dO", "dB"}},
    };
    for (const Case& c : cases) checkCase(c);
}

TEST_CASE("RenderMan's CD|(SD)L: | binds loosest in lightpath, tighter in OSL") {
    // As regular expressions read it: CD or SDL, neither a whole path.
    checkCase({"RenderMan, lightpath's reading", "CD|(SD)L", {}});
    const auto osl = lpe::oslPrecedenceReading("CD|(SD)L");
    REQUIRE(osl.has_value());
    CHECK(*osl == "C(D|SD)L");
    checkCase({"RenderMan, OSL's reading", *osl, {"dl", "amb", "dO", "dB", "sdl", "coat"}});
}
