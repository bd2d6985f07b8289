// How expressions are read and said back: Heckbert's brackets, lightpath's shorthand, warnings
// with both spellings, the spelling fixes the command line suggests, containment and paths printed
// as expressions. Expected texts and witnesses are worked out by hand.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "lpe/analysis.h"
#include "lpe/automaton.h"
#include "lpe/error.h"
#include "lpe/path_string.h"
#include "lpe/reading.h"
#include "test_paths.h"

namespace {

using lpe::EventType;
using lpe::Scatter;
using lpe_test::event;

bool contains(const std::vector<std::string>& lines, const std::string& part) {
    for (const std::string& line : lines)
        if (line.find(part) != std::string::npos) return true;
    return false;
}

// Do two expressions accept exactly the same paths? Decided by containment both ways.
bool sameLanguage(const std::string& a, const std::string& b) {
    const lpe::Containment c = lpe::compareLanguages({{"a", a}, {"b", b}}, ".*");
    return c.contains(0, 1) && c.contains(1, 0);
}

}  // namespace

TEST_CASE("a bracket holding an operator, a group or | is Heckbert's optional group") {
    const lpe::Reading raytracing = lpe::readExpression("E[S*](D|G)L");
    CHECK(raytracing.text == "E(S*)?(D|G)L");
    CHECK(contains(raytracing.notes, "Heckbert: [ ] = optional"));
    CHECK(raytracing.warnings.empty());
    CHECK(sameLanguage("E[S*](D|G)L", "E(S*)?(D|G)L"));
    CHECK(sameLanguage("E[S*](D|G)L", "ES*(D|G)L"));

    const lpe::Reading pathtracing = lpe::readExpression("E[(D|G|S)+(D|G)]L");
    CHECK(pathtracing.text == "E((D|G|S)+(D|G))?L");
    CHECK(sameLanguage("E[(D|G|S)+(D|G)]L", "EL|E(D|G|S)+(D|G)L"));

    // Nested: a set inside an optional group, and an optional group followed by a quantifier.
    CHECK(lpe::readExpression("E[[SG]D]L").text == "E([SG]D)?L");
    CHECK(sameLanguage("E[S*]+DL", "ES*DL"));
}

TEST_CASE("a bracket of single events stays OSL's set, [S] warns with both readings") {
    const lpe::Reading set = lpe::readExpression("C[LO]");
    CHECK(set.text == "C[LO]");
    CHECK(set.notes.empty());
    CHECK(set.warnings.empty());
    const lpe::Reading single = lpe::readExpression("E[S]DL");
    REQUIRE(single.warnings.size() == 1);
    CHECK(single.warnings[0] == "[S] is read as OSL's set (exactly one S); Heckbert's optional S is written (S)?");
    CHECK(sameLanguage("E[S]DL", "ESDL"));
}

TEST_CASE("the slide's E[((D|G|S)+)D|G]L: | splits the bracket, and the warning gives both readings") {
    const lpe::Reading reading = lpe::readExpression("E[((D|G|S)+)D|G]L");
    CHECK(reading.text == "E((D|G|S)+D|G)?L");
    REQUIRE(reading.warnings.size() == 1);
    CHECK(reading.warnings[0] ==
          "| binds loosest, as in regular expressions: read as E((D|G|S)+D|G)?L; OSL binds | tighter and would read "
          "E((D|G|S)+(D|G))?L; add parentheses to say which");
    // Parenthesised, both dialects agree and nothing is said.
    CHECK(lpe::readExpression("E[((D|G|S)+)(D|G)]L").warnings.empty());
    CHECK(lpe::readExpression("(ES*(D|G)L)|(EL)").warnings.empty());
}

TEST_CASE("<L'key'> is read as OSL's <L.'key'>, and says so") {
    const lpe::Reading reading = lpe::readExpression("E.*<L'key'>");
    CHECK(reading.text == "E.*<L.'key'>");
    CHECK(contains(reading.notes, "<X'label'> = OSL's <X.'label'>"));
    CHECK(sameLanguage("E.*<L'key'>", "E.*<L.'key'>"));
    CHECK(lpe::readExpression("E.*<L.'key'>").notes.empty());
}

TEST_CASE("fixes the command line suggests") {
    CHECK(lpe::labelledEventSpelling("E.*L'key'") == "E.*<L.'key'>");
    CHECK(lpe::labelledEventSpelling("ED'floor'L") == "E<.D'floor'>L");
    CHECK_FALSE(lpe::labelledEventSpelling("E.*<L.'key'>").has_value());
    CHECK_FALSE(lpe::labelledEventSpelling("E 'floor' L").has_value());  // a label as its own event
    CHECK(lpe::oslPrecedenceReading("CD|(SD)L") == "C(D|SD)L");
    CHECK_FALSE(lpe::oslPrecedenceReading("E(D|G)L").has_value());
    CHECK_FALSE(lpe::oslPrecedenceReading("(ED)|(EG)").has_value());
}

TEST_CASE("containment: the lecture's nest, with hand-checked shortest witnesses") {
    const std::vector<lpe::NamedExpression> taxonomy = {
        {"raycasting", "E(D|G)L"}, {"raytracing", "E[S*](D|G)L"}, {"radiosity", "ED*L"}, {"pathtracing", "E(D|G|S)*L"}};
    const lpe::Containment c = lpe::compareLanguages(taxonomy);
    const auto witness = [&](std::size_t in, std::size_t notIn) { return lpe::toCompactString(*c.onlyIn[in][notIn]); };
    CHECK(c.strictlyContains(1, 0));  // ray casting in ray tracing
    CHECK(witness(1, 0) == "ESDL");
    CHECK(c.strictlyContains(3, 1));  // ray tracing in path tracing
    CHECK(witness(3, 1) == "EL");
    CHECK(c.strictlyContains(3, 2));  // radiosity in path tracing
    CHECK(witness(3, 2) == "EGL");
    CHECK(c.strictlyContains(3, 0));
    CHECK_FALSE(c.contains(2, 0));    // ray casting has EGL, radiosity does not
    CHECK(witness(0, 2) == "EGL");
    CHECK_FALSE(c.contains(0, 2));
    CHECK(witness(2, 0) == "EL");
}

TEST_CASE("commonPath honours where labels can be") {
    const lpe::LabelPlacement placement = {{"floor", {EventType::Reflection, EventType::Transmission}},
                                           {"key", {EventType::Emitter}}};
    CHECK(lpe::commonPath({"E.*<L.'floor'>"}).has_value());
    CHECK_FALSE(lpe::commonPath({"E.*<L.'floor'>"}, placement).has_value());
    const auto lit = lpe::commonPath({"E<RD'floor'>.*", "E.*<L.'key'>"}, placement);
    REQUIRE(lit.has_value());
    CHECK(lpe::toTupleString(*lit) == "E RD'floor' L'key'");
    CHECK_FALSE(lpe::commonPath({"E(D|G)+", ".*[LOB]"}).has_value());
    CHECK_FALSE(lpe::commonPath({"CV.*", "E<[RT][DGSs]>*[LOB]"}).has_value());
}

TEST_CASE("a path printed as an expression matches that path and, when labelled, no other") {
    const std::vector<lpe::Path> paths = {
        {event(EventType::Camera), event(EventType::Reflection, Scatter::Diffuse, "floor"),
         event(EventType::Emitter, Scatter::None, "key")},
        {event(EventType::Camera), event(EventType::Reflection, Scatter::Diffuse, "floor"),
         event(EventType::Emitter, Scatter::None, "fill")},
        {event(EventType::Camera), event(EventType::Reflection, Scatter::Glossy, "floor"),
         event(EventType::Emitter, Scatter::None, "key")},
        {event(EventType::Camera), event(EventType::Transmission, Scatter::Specular, "glass"),
         event(EventType::Background)},
        {event(EventType::Camera), event(EventType::Reflection, Scatter::Specular, "glass"),
         event(EventType::Background)},
        {event(EventType::Camera), event(EventType::Reflection, Scatter::Diffuse), event(EventType::Emitter)},
        {event(EventType::Camera), event(EventType::Reflection, Scatter::Diffuse), event(EventType::Background)},
        {event(EventType::Camera), event(EventType::ObjectEmission, Scatter::None, "lamp")},
        {event(EventType::Camera), event(EventType::Emitter, Scatter::None, "lamp")},
    };
    CHECK(lpe::toExpressionString(paths[0]) == "E <RD'floor'> <L.'key'>");
    CHECK(lpe::toExpressionString(paths[5]) == "E <RD> <L>");
    CHECK(lpe::toExpressionString(paths[7]) == "E <O.'lamp'>");
    for (std::size_t i = 0; i < paths.size(); ++i) {
        const std::string text = lpe::toExpressionString(paths[i]);
        CAPTURE(text);
        CHECK(lpe::parsePath(text) == paths[i]);
        const lpe::Automaton automaton = lpe::Automaton::compile({{"x", text}});
        CHECK(automaton.matches(paths[i], 0));
        // An unlabelled event also matches labelled ones; the renderer labels every surface and light.
        const bool labelled = paths[i][1].label.size() > 0;
        for (std::size_t j = 0; j < paths.size(); ++j)
            if (labelled) CHECK(automaton.matches(paths[j], 0) == (i == j));
    }
}

TEST_CASE("V, O and x: OSL's letters are read, and x only where OSL allows it") {
    const lpe::Path volume = {event(EventType::Camera), event(EventType::Volume, Scatter::Diffuse), event(EventType::Emitter)};
    const lpe::Path emitting = {event(EventType::Camera), event(EventType::ObjectEmission)};
    const lpe::Automaton automaton =
        lpe::Automaton::compile({{"v", "CV.*"}, {"o", "CO"}, {"bareL", "EL"}, {"oslL", "E<L>"}, {"noScatter", "E<Ox>"}});
    CHECK(automaton.matches(volume, 0));
    CHECK(automaton.matches(emitting, 1));
    CHECK(automaton.matches(emitting, 2));       // Heckbert's bare L: every emitter
    CHECK_FALSE(automaton.matches(emitting, 3)); // OSL's <L>: lights only
    CHECK(automaton.matches(emitting, 4));
    CHECK_THROWS_AS(lpe::Automaton::compile({{"x", "ExL"}}), lpe::SyntaxError);
}
