// One judge of expressions (issue 31): `lpe match --integrator`, `lpe check --integrator`,
// `render`, `explain` and `serve` accept and refuse exactly the same expressions for the same
// integrator. Every expression the documentation shows (README.md and docs/*.md code spans that
// are LPEs) and every string of the LPE engine's tests that is one goes through each command, in
// process, under each integrator; the commands are the ones `lightpath` runs (their add*Command),
// serve through serve::applySettings, which the page's PUT /api/settings reaches.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "cli/bracket_arguments.h"
#include "cli/explain_command.h"
#include "cli/lpe_command.h"
#include "cli/render_command.h"
#include "integrators/registry.h"
#include "lpe/automaton.h"
#include "scene/scene_loader.h"
#include "serve/request_error.h"
#include "serve/settings.h"

using namespace lightpath;
namespace fs = std::filesystem;

namespace {

const std::string kSource = LIGHTPATH_SOURCE_DIR;
// A small scene: the verdict never depends on the scene (what is black only in a scene renders,
// with a warning), and a small one keeps every accepted render short.
const std::string kScene = kSource + "/scenes/mirror-sphere.toml";

std::string readFile(const fs::path& path) {
    std::ifstream file(path);
    std::stringstream text;
    text << file.rdbuf();
    return text.str();
}

bool compiles(const std::string& expression) {
    try {
        lpe::Automaton::compile({{"x", expression}});
        return true;
    } catch (const std::exception&) {
        return false;
    }
}

// Inline code spans outside fenced blocks, with a leading `name=` dropped.
void addDocumentExpressions(const fs::path& file, std::set<std::string>& out) {
    const std::string text = std::regex_replace(readFile(file), std::regex("```[^]*?```"), "");
    const std::regex span("`([^`\n]+)`");
    for (auto it = std::sregex_iterator(text.begin(), text.end(), span); it != std::sregex_iterator(); ++it) {
        std::string e = (*it)[1];
        std::smatch named;
        if (std::regex_match(e, named, std::regex("[A-Za-z_][A-Za-z0-9_-]*=(.+)"))) e = named[1];
        if (compiles(e)) out.insert(e);
    }
}

// String literals without escapes.
void addSourceExpressions(const fs::path& file, std::set<std::string>& out) {
    const std::string text = readFile(file);
    const std::regex literal("\"([^\"\\\\\n]*)\"");
    for (auto it = std::sregex_iterator(text.begin(), text.end(), literal); it != std::sregex_iterator(); ++it)
        if (compiles((*it)[1])) out.insert((*it)[1]);
}

// Issue 31's list, Arnold's built-in AOVs, and what is only black in a scene.
const std::vector<std::string> kNamed = {
    "C.*L<L>", "E(D|G)+", "CV.*", "CDL'key'", "C<RD>.*", "C<RS[^'coat']>.*", "C<TS>.*", "C<TD>.*", "C<V>.*",
    "C<RD>L", "C<RD>[DSVOB].*", "C<RS[^'coat']>L", "C[LO]", "CB", "E.*<L.'floor'>", "E.*<L'kee'>", "E.*L'key'",
    "ES+(D|G)L", "EDDL", "CD|(SD)L", "[SG]", "E[S*](D|G)L",
};

std::vector<std::string> allExpressions() {
    std::set<std::string> found(kNamed.begin(), kNamed.end());
    addDocumentExpressions(kSource + "/README.md", found);
    for (const auto& entry : fs::directory_iterator(kSource + "/docs"))
        if (entry.path().extension() == ".md") addDocumentExpressions(entry.path(), found);
    for (const auto& entry : fs::directory_iterator(kSource + "/tests/lpe"))
        if (entry.path().extension() == ".cpp") addSourceExpressions(entry.path(), found);
    return {found.begin(), found.end()};
}

struct Outcome {
    int code = 0;
    std::string output;  // stdout and stderr
};

// Runs `lightpath ARGS...` as main() does, in process.
Outcome runCommand(const std::vector<std::string>& args) {
    CLI::App app{"lightpath"};
    app.require_subcommand(1);
    addRenderCommand(app);
    addExplainCommand(app);
    addLpeCommand(app);
    unmarkBracketedValues(app);
    std::vector<std::string> argv = {"lightpath"};
    argv.insert(argv.end(), args.begin(), args.end());
    std::vector<const char*> raw;
    for (const std::string& a : argv) raw.push_back(a.c_str());
    const std::vector<std::string> marked = markBracketedArguments(static_cast<int>(raw.size()), raw.data());
    std::vector<const char*> pointers;
    for (const std::string& a : marked) pointers.push_back(a.c_str());

    std::ostringstream captured;
    std::streambuf* out = std::cout.rdbuf(captured.rdbuf());
    std::streambuf* err = std::cerr.rdbuf(captured.rdbuf());
    Outcome outcome;
    try {
        app.parse(static_cast<int>(pointers.size()), pointers.data());
    } catch (const CLI::Error& e) {
        outcome.code = e.get_exit_code();
        captured << withoutMarks(e.what());
    } catch (const std::exception& e) {
        outcome.code = 1;
        captured << "error: " << e.what();
    }
    std::cout.rdbuf(out);
    std::cerr.rdbuf(err);
    outcome.output = captured.str();
    return outcome;
}

bool serveRefuses(const serve::Settings& start, const std::string& integrator, const std::string& expression,
                  std::string& message) {
    const nlohmann::json body = {{"integrator", integrator}, {"spp", 1},
                                 {"lpes", {{{"name", "x"}, {"expression", expression}}}}};
    try {
        serve::applySettings(start, body.dump());
        return false;
    } catch (const serve::RequestError& e) {
        message = e.what();
        return true;
    }
}

}  // namespace

TEST_CASE("one judge: lpe match, lpe check, render, explain and serve agree on every documented expression") {
    const std::vector<std::string> expressions = allExpressions();
    // Hundreds: the docs' code spans and the engine tests' strings, not only the named ones.
    REQUIRE(expressions.size() > 100);
    const fs::path out = fs::path(LIGHTPATH_TEST_OUTPUT_DIR);
    fs::create_directories(out);
    const Scene scene = loadScene(kScene);
    serve::Settings start = serve::defaultSettings(scene);
    start.width = 4;
    start.height = 3;

    std::size_t refusals = 0, acceptances = 0;
    for (const IntegratorInfo& integrator : integrators()) {
        const std::string name = integrator.name;
        for (const std::string& e : expressions) {
            CAPTURE(name);
            CAPTURE(e);
            const Outcome check = runCommand({"lpe", "check", "--quiet", "--integrator", name, "x=" + e});
            const Outcome match = runCommand({"lpe", "match", "--quiet", "--integrator", name, e, "EDL"});
            // Small integrator budgets: the verdict is the integrator's and the expression's, never
            // the budget's, and radiosity's solve at its default rays and refinement was most of
            // this test's CPU (perf) with its 64 patches.
            const std::vector<std::string> common = {kScene, "--integrator", name, "--quiet", "--resolution", "4x3",
                                                     "--patches", "64", "--refine", "0", "--form-factor-rays", "16",
                                                     "--light-samples", "4", "--photons", "1000", "--lpe", "x=" + e};
            std::vector<std::string> render = {"render"};
            render.insert(render.end(), common.begin(), common.end());
            render.insert(render.end(), {"-o", (out / "judge.exr").string()});
            std::vector<std::string> explain = {"explain"};
            explain.insert(explain.end(), common.begin(), common.end());
            explain.insert(explain.end(), {"--pixel", "1,1", "--json"});
            const Outcome rendered = runCommand(render);
            const Outcome explained = runCommand(explain);
            std::string served;
            const bool serveRefused = serveRefuses(start, name, e, served);

            const bool refused = check.code == 2;
            CAPTURE(check.output);
            CAPTURE(match.output);
            CAPTURE(rendered.output);
            CAPTURE(explained.output);
            CAPTURE(served);
            CHECK(check.code == (refused ? 2 : 0));
            CHECK(match.code == check.code);
            CHECK(rendered.code == check.code);
            CHECK(explained.code == check.code);
            CHECK(serveRefused == refused);
            if (refused) {
                // The same reason, said by each command.
                const std::string reason = check.output.substr(check.output.find("can never match"));
                CHECK(match.output.find(reason) != std::string::npos);
                CHECK(rendered.output.find(reason) != std::string::npos);
                CHECK(explained.output.find(reason) != std::string::npos);
                CHECK(served.find(reason) != std::string::npos);
                ++refusals;
            } else {
                ++acceptances;
            }
        }
    }
    // Both verdicts occur (a judge that refuses nothing, or everything, agrees with itself).
    CHECK(refusals > 100);
    CHECK(acceptances > 100);
}

TEST_CASE("one judge: issue 31's expressions get the verdicts the issue asks for, under every integrator") {
    for (const IntegratorInfo& integrator : integrators()) {
        const std::string name = integrator.name;
        CAPTURE(name);
        for (const std::string never : {"C.*L<L>", "E(D|G)+", "CDL'key'", "E.*L'key'"})
            CHECK(runCommand({"lpe", "check", "--quiet", "--integrator", name, never}).code == 2);
        // Empty only in a scene: never refused.
        for (const std::string black : {"E.*<L.'floor'>", "E.*<L'kee'>", "C[LO]", "CB"})
            CHECK(runCommand({"lpe", "check", "--quiet", "--integrator", name, black}).code == 0);
        // Volume light: empty in a scene without media under an integrator that renders media;
        // refused under one that never does (it refuses scenes with media).
        for (const std::string volume : {"CV.*", "C<V>.*"}) {
            CAPTURE(volume);
            CHECK(runCommand({"lpe", "check", "--quiet", "--integrator", name, volume}).code == (integrator.rendersMedia ? 0 : 2));
        }
        // A mirror in a scene without a coat: every integrator that follows mirrors renders it.
        const bool mirrors = name == "whitted" || name == "path" || name == "bdpt" || name == "photon" || name == "sppm";
        for (const std::string specular : {"C<RS[^'coat']>.*", "C<RS'coat'>.*"}) {
            CAPTURE(specular);
            CHECK(runCommand({"lpe", "check", "--quiet", "--integrator", name, specular}).code == (mirrors ? 0 : 2));
        }
    }
}
