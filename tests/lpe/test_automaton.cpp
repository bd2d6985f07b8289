// The compiled automaton on hand-written paths: the lecture's expressions, tuples, labels, sets
// and repetitions; dead states; the complement output; minimality against hand-counted states.
#include <doctest/doctest.h>

#include <random>
#include <regex>
#include <string>
#include <vector>

#include "lpe/automaton.h"
#include "test_paths.h"

using lpe::EventType;
using lpe::Scatter;
using lpe_test::allStrings;
using lpe_test::compactPath;
using lpe_test::event;

namespace {

lpe::Automaton compileOne(const std::string& expression) { return lpe::Automaton::compile({{"x", expression}}); }

bool accepts(const std::string& expression, const lpe::Path& path) {
    return compileOne(expression).matches(path, 0);
}

struct Case {
    std::string expression;
    std::vector<std::string> match;     // compact paths the expression must accept
    std::vector<std::string> noMatch;   // and must reject
};

void checkCases(const std::vector<Case>& cases) {
    for (const Case& c : cases) {
        const lpe::Automaton automaton = compileOne(c.expression);
        for (const std::string& path : c.match) {
            CAPTURE(c.expression);
            CAPTURE(path);
            CHECK(automaton.matches(compactPath(path), 0));
        }
        for (const std::string& path : c.noMatch) {
            CAPTURE(c.expression);
            CAPTURE(path);
            CHECK_FALSE(automaton.matches(compactPath(path), 0));
        }
    }
}

}  // namespace

TEST_CASE("the lecture's taxonomy of tracing on hand-written paths") {
    checkCases({
        {"E(D|G)L", {"EDL", "EGL", "EDB"}, {"EL", "ESL", "ESDL", "EDDL", "EDLL", "DL", "ED", "EsL", ""}},
        {"E(S*)(D|G)L", {"EDL", "EGL", "ESDL", "ESSGL", "ESSSSDB"}, {"EL", "ESL", "EDSL", "EDDL", "ESDSL"}},
        {"ED*L", {"EL", "EDL", "EDDDL", "EB"}, {"EGL", "ESDL", "EDGL", "ED", "DL"}},
        {"E(D|G|S)*L", {"EL", "EDL", "ESGDSL", "EGGGB"}, {"E", "ED", "EsL", "ERL", "ETL", "EDLL", "LDE"}},
    });
    // Refraction is specular scattering too: E <TS> D L is ray tracing through glass.
    CHECK(accepts("E(S*)(D|G)L", {event(EventType::Camera), event(EventType::Transmission, Scatter::Specular),
                                  event(EventType::Reflection, Scatter::Diffuse), event(EventType::Emitter)}));
}

TEST_CASE("compact letters, whitespace, C for E, R and T, s, dot") {
    checkCases({
        {"CDL", {"EDL"}, {"ESL"}},
        {" E ( D | G ) L ", {"EDL", "EGL"}, {"ESL"}},
        {"ERL", {"EDL", "ESL", "EsL", "ERL"}, {"ETL", "EL"}},
        {"ETL", {"ETL"}, {"EDL", "ERL"}},
        {"EsL", {"EsL"}, {"ESL", "EDL"}},
        {"E.L", {"EDL", "ELL", "EBL", "EEL", "ETL"}, {"EL", "EDDL"}},
        {"EBL", {"EBL"}, {"ELL"}},
    });
    const lpe::Path transmittedDiffuse = {event(EventType::Camera),
                                          event(EventType::Transmission, Scatter::Diffuse),
                                          event(EventType::Emitter)};
    CHECK(accepts("EDL", transmittedDiffuse));
    CHECK(accepts("ETL", transmittedDiffuse));
    CHECK_FALSE(accepts("ERL", transmittedDiffuse));
}

TEST_CASE("tuples: <RS> mirror, <TS> refraction, <L> emitters only, L emitters and background, B") {
    const lpe::Path mirror = {event(EventType::Camera), event(EventType::Reflection, Scatter::Specular),
                              event(EventType::Emitter)};
    const lpe::Path glass = {event(EventType::Camera), event(EventType::Transmission, Scatter::Specular),
                             event(EventType::Emitter)};
    const lpe::Path diffuse = compactPath("EDL");
    CHECK(accepts("E<RS>L", mirror));
    CHECK_FALSE(accepts("E<RS>L", glass));
    CHECK_FALSE(accepts("E<RS>L", diffuse));
    CHECK(accepts("E<TS>L", glass));
    CHECK_FALSE(accepts("E<TS>L", mirror));
    CHECK(accepts("ESL", mirror));
    CHECK(accepts("ESL", glass));
    CHECK(accepts("E<[RT]S>L", glass));
    CHECK_FALSE(accepts("E<[^T]S>L", glass));
    CHECK(accepts("E<.S>L", glass));
    CHECK(accepts("E<T>L", glass));
    CHECK(accepts("<E_><RS><L_>", mirror));
    CHECK(accepts("<C><R><L>", mirror));

    const lpe::Path toEmitter = compactPath("EL");
    const lpe::Path toBackground = compactPath("EB");
    CHECK(accepts("E<L>", toEmitter));
    CHECK_FALSE(accepts("E<L>", toBackground));  // as in OSL: the tuple <L> is emitters only
    CHECK(accepts("EL", toEmitter));
    CHECK(accepts("EL", toBackground));         // the bare L also matches the background
    CHECK(accepts("EB", toBackground));
    CHECK_FALSE(accepts("EB", toEmitter));
    CHECK(accepts("E<B>", toBackground));
}

TEST_CASE("labels: <L'key'>, labelled events, and class 0 for labels no expression names") {
    const auto path = [](const char* surface, const char* light) {
        return lpe::Path{event(EventType::Camera), event(EventType::Reflection, Scatter::Diffuse, surface),
                         event(EventType::Emitter, Scatter::None, light)};
    };
    CHECK(accepts("E.*<L'key'>", path("", "key")));
    CHECK(accepts("E.*<L'key'>", path("floor", "key")));
    CHECK_FALSE(accepts("E.*<L'key'>", path("", "fill")));
    CHECK_FALSE(accepts("E.*<L'key'>", path("", "")));
    CHECK_FALSE(accepts("E.*<L'key'>", {event(EventType::Camera), event(EventType::Background, Scatter::None, "key")}));
    CHECK(accepts("E'floor'L", path("floor", "")));
    CHECK(accepts("E<RD'floor'>L", path("floor", "")));
    CHECK_FALSE(accepts("E'floor'L", path("wall", "")));
    CHECK(accepts("E<R'floor'>L", path("floor", "")));

    // A label that no expression names behaves exactly like no label.
    const lpe::Automaton automaton = compileOne("E<RD>'key'|ED<L'key'>");
    CHECK(automaton.labels() == std::vector<std::string>{"key"});
    CHECK(automaton.symbolCount() == 2 * 35);  // 7 event types x 5 scatterings per label class
    CHECK(automaton.labelClass("key") == 1);
    CHECK(automaton.labelClass("") == 0);
    CHECK(automaton.labelClass("floor") == 0);
    CHECK(automaton.labelClass("keys") == 0);
    CHECK(automaton.run(path("floor", "key")) == automaton.run(path("", "key")));
    CHECK(automaton.run(path("wall", "key")) == 1);
    CHECK(automaton.run(path("key", "fill")) == 0);

    // Label sets and negation: events not labelled 'key'; two labels at once match nothing.
    CHECK(accepts("E[^'key']L", path("floor", "")));
    CHECK_FALSE(accepts("E[^'key']L", path("key", "")));
    CHECK(accepts("E[^'key']*L", path("floor", "")));
    CHECK_FALSE(accepts("E[^'key']*L", path("key", "")));
    CHECK(accepts("E<RD[^'key']>L", path("floor", "")));
    CHECK_FALSE(accepts("E<RD[^'key']>L", path("key", "")));
    CHECK(accepts("E<RD['a' 'b']>L", path("b", "")));
    CHECK_FALSE(accepts("E<RD['a' 'b']>L", path("c", "")));
    for (const char* surface : {"", "a", "b", "c"}) CHECK_FALSE(accepts("E<RD'a''b'>L", path(surface, "")));
}

TEST_CASE("sets and repetitions: [^D], {n}, {n,}, {n,m}, ?") {
    checkCases({
        {"E[^D]L", {"ESL", "EGL", "EsL", "EEL", "ELL"}, {"EDL", "EL", "ESSL"}},
        {"E[DG]L", {"EDL", "EGL"}, {"ESL"}},
        {"E[^DG]*L", {"EL", "ESSL", "EsSL"}, {"EDL", "ESGL"}},
        {"ED{2}L", {"EDDL"}, {"EL", "EDL", "EDDDL"}},
        {"ED{0}L", {"EL"}, {"EDL"}},
        {"ED{2,}L", {"EDDL", "EDDDL", "EDDDDDDDL"}, {"EL", "EDL"}},
        {"ED{1,2}L", {"EDL", "EDDL"}, {"EL", "EDDDL"}},
        {"ED{0,1}L", {"EL", "EDL"}, {"EDDL"}},
        {"ES?DL", {"EDL", "ESDL"}, {"ESSDL", "ESL"}},
        {"E(SD){2}L", {"ESDSDL"}, {"ESDL", "ESDSDSDL", "ESSDDL"}},
        {"E(S|D)+L", {"ESL", "EDSDL"}, {"EL", "EGL"}},
    });
    const lpe::Path refractedDiffuse = {event(EventType::Camera), event(EventType::Transmission, Scatter::Diffuse),
                                        event(EventType::Emitter)};
    CHECK_FALSE(accepts("E[^D]L", refractedDiffuse));
    CHECK(accepts("E[^<RD>]L", refractedDiffuse));
}

TEST_CASE("dead states: a branch that can no longer contribute stops") {
    const lpe::Automaton raycast = compileOne("E(D|G)L");
    const auto camera = raycast.symbol(EventType::Camera, Scatter::None, 0);
    const auto mirror = raycast.symbol(EventType::Reflection, Scatter::Specular, 0);
    const auto diffuse = raycast.symbol(EventType::Reflection, Scatter::Diffuse, 0);
    const auto light = raycast.symbol(EventType::Emitter, Scatter::None, 0);
    const auto afterE = raycast.step(raycast.start(), camera);
    CHECK_FALSE(raycast.isDead(raycast.start(), raycast.allOutputs()));
    CHECK_FALSE(raycast.isDead(afterE, raycast.allOutputs()));
    CHECK(raycast.isDead(raycast.step(afterE, mirror), raycast.allOutputs()));
    const auto lit = raycast.step(raycast.step(afterE, diffuse), light);
    CHECK(raycast.accepts(lit) == 1);
    CHECK_FALSE(raycast.isDead(lit, 1));
    CHECK(raycast.isDead(raycast.step(lit, light), 1));
    CHECK(raycast.isDead(raycast.start(), 0));  // nothing can accept for no outputs

    // Two outputs: after E S only the mirror output can still accept.
    const lpe::Automaton two = lpe::Automaton::compile({{"radiosity", "ED*L"}, {"mirror", "ES+L"}});
    CHECK(two.allOutputs() == 3);
    const auto e = two.step(two.start(), camera);
    CHECK_FALSE(two.isDead(e, 1));
    CHECK_FALSE(two.isDead(e, 2));
    const auto es = two.step(e, mirror);
    CHECK(two.isDead(es, 1));
    CHECK_FALSE(two.isDead(es, 2));
    CHECK_FALSE(two.isDead(es, 3));
    const auto ed = two.step(e, diffuse);
    CHECK_FALSE(two.isDead(ed, 1));
    CHECK(two.isDead(ed, 2));
}

TEST_CASE("the complement output accepts exactly the universe paths no named output accepts") {
    lpe::CompileOptions options;
    options.complementName = "rest";
    options.universe = "E(D|G|S)*L";
    const lpe::Automaton automaton =
        lpe::Automaton::compile({{"raycast", "E(D|G)L"}, {"mirror", "ES+L"}}, options);
    REQUIRE(automaton.outputCount() == 3);
    CHECK(automaton.outputName(2) == "rest");
    CHECK(automaton.allOutputs() == 7);

    // References by std::regex over compact strings (B never occurs, so L is the only emitter).
    const std::regex universe("E[DGS]*L"), raycast("E[DG]L"), mirror("ES+L");
    for (const std::string& path : allStrings("EDGSsL", 6)) {
        CAPTURE(path);
        const bool inUniverse = std::regex_match(path, universe);
        const bool named = std::regex_match(path, raycast) || std::regex_match(path, mirror);
        CHECK(automaton.matches(compactPath(path), 2) == (inUniverse && !named));
    }
    CHECK(automaton.matches(compactPath("EDDL"), 2));
    CHECK(automaton.matches(compactPath("EL"), 2));
    CHECK_FALSE(automaton.matches(compactPath("EsL"), 2));
    CHECK_FALSE(automaton.matches(compactPath("ESL"), 2));
}

// The renderer advances one state per event and reads the accepting outputs at every prefix (a
// light at each vertex). Checked at every prefix against std::regex on a token form of the path,
// with regular expressions written by hand for the four LPEs: a reference that shares no code
// with the compiler.
std::string token(const lpe::Event& e) {
    const char type[] = {'E', 'R', 'T', 'L', 'B'};
    const char scatter[] = {'D', 'G', 'S', 's', '_'};
    const bool scatters = e.type == EventType::Reflection || e.type == EventType::Transmission;
    std::string t = "<";
    t += type[static_cast<int>(e.type)];
    t += scatters ? scatter[static_cast<int>(e.scatter)] : '_';
    if (!e.label.empty()) t += "'" + e.label + "'";
    return t + ">";
}

TEST_CASE("stepping event by event accepts at every prefix exactly what std::regex accepts") {
    const lpe::Automaton automaton = lpe::Automaton::compile(
        {{"a", "E(D|G)L"}, {"b", "ES*<L'key'>"}, {"c", "E.*[^D]L"}, {"d", "E<TS>+'glass'L"}});
    // A bare L matches emitters and the background (docs/design.md); any label goes where none is named.
    const std::string light = "(?:<L_(?:'[^']*')?>|<B_>)", any = "<[^>]*>";
    const std::regex expected[] = {
        std::regex("<E_><[RT][DG](?:'[^']*')?>" + light),
        std::regex("<E_>(?:<[RT]S(?:'[^']*')?>)*<L_'key'>"),
        std::regex("<E_>(?:" + any + ")*(?:<[ELB]_[^>]*>|<[RT][GSs][^>]*>)" + light),
        std::regex("<E_>(?:<TS[^>]*>)+<[^>]*'glass'>" + light),
    };
    std::mt19937 rng(7);
    const std::vector<lpe::Event> events = {
        event(EventType::Camera), event(EventType::Reflection, Scatter::Diffuse),
        event(EventType::Reflection, Scatter::Glossy), event(EventType::Reflection, Scatter::Specular),
        event(EventType::Transmission, Scatter::Specular), event(EventType::Transmission, Scatter::Specular, "glass"),
        event(EventType::Emitter), event(EventType::Emitter, Scatter::None, "key"), event(EventType::Background),
        event(EventType::Reflection, Scatter::Straight, "other"), event(EventType::Reflection, Scatter::Diffuse, "glass")};
    int accepted = 0;
    for (int i = 0; i < 3000; ++i) {
        lpe::Automaton::State state = automaton.start();
        std::string text;
        // Most paths start at the camera, as the renderer's do; some do not, and must match nothing.
        const int length = 1 + static_cast<int>(rng() % 7);
        for (int k = 0; k < length; ++k) {
            const lpe::Event& e = k == 0 && rng() % 4 != 0 ? events[0] : events[rng() % events.size()];
            state = automaton.step(state, automaton.symbol(e));
            text += token(e);
            for (std::size_t output = 0; output < 4; ++output) {
                CAPTURE(text);
                CAPTURE(output);
                const bool accepts = (automaton.accepts(state) >> output) & 1u;
                CHECK(accepts == std::regex_match(text, expected[output]));
                accepted += accepts;
            }
        }
    }
    CHECK(accepted > 100);  // the random paths do reach accepting states
}

TEST_CASE("the automaton is minimal: state counts worked out by hand") {
    // start, after E, after E D|G, accepting after L, dead.
    CHECK(compileOne("E(D|G)L").stateCount() == 5);
    CHECK(compileOne("E[DG]L").stateCount() == 5);
    CHECK(compileOne("E(D|G)L|EDL|EGL").stateCount() == 5);
    // start, after E (loops on D|G|S), accepting, dead.
    CHECK(compileOne("E(D|G|S)*L").stateCount() == 4);
    // (D|G)*: the start accepts and loops; anything else is dead.
    CHECK(compileOne("(D|G)*").stateCount() == 2);
    CHECK(compileOne("(D*G*)*").stateCount() == 2);
    // Even (accepting) and odd count of D, plus dead.
    CHECK(compileOne("(DD)*").stateCount() == 3);
    // 0, 1, 2 (accepts), 3 (accepts), dead.
    CHECK(compileOne("D{2,3}").stateCount() == 5);
    // Every path matches: one state and no dead state.
    CHECK(compileOne(".*").stateCount() == 1);
    CHECK(compileOne("(D|[^D])*").stateCount() == 1);
    // E(S*)(D|G)L: start, after E S* (loops on S), after D|G, accepting, dead.
    CHECK(compileOne("E(S*)(D|G)L").stateCount() == 5);
    // The same expression twice: one accepting state accepts both outputs.
    const lpe::Automaton twice = lpe::Automaton::compile({{"a", "EDL"}, {"b", "EDL"}});
    CHECK(twice.stateCount() == 5);
    CHECK(twice.run(compactPath("EDL")) == 3);
    // Labels only add states where they matter: start, after E, accepting for 'key', dead.
    CHECK(compileOne("E<L'key'>").stateCount() == 4);
}

TEST_CASE("outputs, symbols and representative events") {
    const lpe::Automaton automaton = lpe::Automaton::compile({{"direct", "E(D|G)L"}, {"keyed", "E.*<L'key'>"}});
    CHECK(automaton.outputCount() == 2);
    CHECK(automaton.outputName(0) == "direct");
    CHECK(automaton.outputName(1) == "keyed");
    CHECK(automaton.start() == 0);
    for (lpe::Automaton::Symbol s = 0; s < automaton.symbolCount(); ++s) {
        const lpe::Event e = automaton.eventOf(s);
        CHECK(automaton.symbol(e) == s);
    }
    CHECK(automaton.eventOf(automaton.symbol(EventType::Emitter, Scatter::None, 1)) ==
          event(EventType::Emitter, Scatter::None, "key"));
    CHECK(automaton.eventOf(automaton.symbol(EventType::Reflection, Scatter::Glossy, 0)) ==
          event(EventType::Reflection, Scatter::Glossy));
}

TEST_CASE("shortestPath finds a shortest accepted path, preferring natural events") {
    const lpe::Automaton automaton =
        lpe::Automaton::compile({{"whitted", "E(S*)(D|G)L"}, {"mirror", "ES+L"}, {"keyed", "E.*<L'key'>"},
                                 {"none", "E<L'a''b'>"}, {"empty", "D*"}});
    CHECK(automaton.shortestPath([](lpe::OutputMask m) { return m & 1; }) == compactPath("EDL"));
    CHECK(automaton.shortestPath([](lpe::OutputMask m) { return m & 2; }) == compactPath("ESL"));
    CHECK(automaton.shortestPath([](lpe::OutputMask m) { return m & 4; }) ==
          lpe::Path{event(EventType::Camera), event(EventType::Emitter, Scatter::None, "key")});
    CHECK(automaton.shortestPath([](lpe::OutputMask m) { return m & 8; }).empty());
    CHECK_FALSE(automaton.findShortestPath([](lpe::OutputMask m) { return m & 8; }).has_value());
    // The empty path is accepted by D*: found, and empty.
    const auto empty = automaton.findShortestPath([](lpe::OutputMask m) { return m & 16; });
    REQUIRE(empty.has_value());
    CHECK(empty->empty());
    // Every path of ES+(D|G)L has at least four events; ESDL is the first in the preferred order.
    CHECK(compileOne("ES+(D|G)L").shortestPath([](lpe::OutputMask m) { return m != 0; }) == compactPath("ESDL"));
}

TEST_CASE("toDot draws states, accepting outputs and edges in LPE syntax") {
    const std::string dot = lpe::Automaton::compile({{"raycast", "E(D|G)L"}}).toDot("raycast");
    CHECK(dot.find("digraph") == 0);
    CHECK(dot.find("rankdir=LR") != std::string::npos);
    CHECK(dot.find("start [shape=point, style=invis];") != std::string::npos);
    CHECK(dot.find("start -> 0;") != std::string::npos);
    CHECK(dot.find("0 -> 1 [label=\"E\"]") != std::string::npos);
    CHECK(dot.find("1 -> 2 [label=\"D|G\"]") != std::string::npos);
    CHECK(dot.find("2 -> 3 [label=\"L\"]") != std::string::npos);
    CHECK(dot.find("3 [shape=doublecircle, label=\"3\\nraycast\"]") != std::string::npos);
    CHECK(dot.find("4") == std::string::npos);  // the dead state and edges into it are left out

    const auto edge = [](const std::string& expression) {
        const std::string text = lpe::Automaton::compile({{"x", "E" + expression}}).toDot();
        const std::string from = "1 -> 2 [label=\"";
        const std::size_t at = text.find(from);
        REQUIRE(at != std::string::npos);
        return text.substr(at + from.size(), text.find('"', at + from.size()) - at - from.size());
    };
    CHECK(edge("<RS>") == "<RS>");
    CHECK(edge("<TS>") == "<TS>");
    CHECK(edge("S") == "S");
    CHECK(edge("(G|S)") == "G|S");
    CHECK(edge("<L>") == "<L>");
    CHECK(edge("L") == "L");
    CHECK(edge("B") == "B");
    CHECK(edge("<L'key'>") == "<L.'key'>");
    CHECK(edge("<L.'key'>") == "<L.'key'>");
    CHECK(edge("O") == "O");
    CHECK(edge("[LO]") == "<L>|O");
    CHECK(edge("[^D]") == "[^D]");
    CHECK(edge(".") == ".");
    CHECK(edge("'floor'") == "'floor'");
    CHECK(edge("<R[DG]>") == "<R[DG]>");
    CHECK(edge("[^'floor']") == "[^'floor']");
    CHECK(edge("(R|T)") == "R|T");
    // Inside a set L is OSL's, lights only: [^L] also takes emitting objects and the background.
    CHECK(edge("[^L]") == "<[^L]>");
    CHECK(edge("(R|T|E|B|V|O)") == "<[^L]>");
    CHECK(edge("[^<L>]") == "<[^L]>");
    CHECK(edge("(R|T|E|V)") == "R|T|V|E");  // [^L] would read as "not a light"
}

TEST_CASE("toDot edge labels, read back as LPEs, match exactly the events of their edge") {
    const lpe::Automaton automaton = lpe::Automaton::compile(
        {{"key", "E.*<L'key'>"}, {"fill", "E[^'key']*<L'fill'>"}, {"raycast", "E(D|G)L"},
         {"glass", "E<RS>+<TS>'glass'L"}, {"sky", "E[^D]*B"}, {"floor", "E<[RT][DG]'floor'>L"}});
    const std::string dot = automaton.toDot();

    // Every event a renderer produces, with each label the expressions name and one they do not.
    std::vector<lpe::Event> events;
    for (const char* label : {"", "key", "fill", "glass", "floor", "unnamed"}) {
        events.push_back(event(EventType::Camera, Scatter::None, label));
        events.push_back(event(EventType::Emitter, Scatter::None, label));
        events.push_back(event(EventType::Background, Scatter::None, label));
        for (const EventType type : {EventType::Reflection, EventType::Transmission}) {
            for (const Scatter scatter :
                 {Scatter::Diffuse, Scatter::Glossy, Scatter::Specular, Scatter::Straight, Scatter::None}) {
                events.push_back(event(type, scatter, label));
            }
        }
    }

    struct Edge {
        lpe::Automaton::State from, to;
        std::string label;
    };
    std::vector<Edge> edges;
    const std::regex line(R"re(  (\d+) -> (\d+) \[label="([^"]*)"\];)re");
    for (std::sregex_iterator it(dot.begin(), dot.end(), line), end; it != end; ++it) {
        edges.push_back({static_cast<lpe::Automaton::State>(std::stoul((*it)[1])),
                         static_cast<lpe::Automaton::State>(std::stoul((*it)[2])), (*it)[3]});
    }
    REQUIRE(edges.size() > 10);
    for (const Edge& e : edges) {
        CAPTURE(e.label);
        const lpe::Automaton label = compileOne(e.label);
        for (const lpe::Event& ev : events) {
            CAPTURE(lpe_test::describe(ev));
            CHECK(label.matches({ev}, 0) == (automaton.step(e.from, automaton.symbol(ev)) == e.to));
        }
    }
}
