// lightpath: a ray tracer for teaching light transport. Every contribution carries its light
// path; light path expressions split the render into AOVs that sum to the beauty.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <new>
#include <string>
#include <iostream>
#include <string>
#include <vector>

#include "cli/bench_command.h"
#include "cli/bracket_arguments.h"
#include "cli/parse_errors.h"
#include "config/config_error.h"
#include "config/messages.h"
#include "config/exit_codes.h"
#include "cli/explain_command.h"
#include "cli/lpe_command.h"
#include "cli/render_command.h"
#include "cli/serve_command.h"
#include "cli/stress_command.h"
#include "cli/types_command.h"
#include "render/memory_limit.h"

namespace {

int run(int argc, char** argv) {
    CLI::App app{"lightpath: a ray tracer that records every contribution's light path (Heckbert's E(S*)(D|G)L)\n"
                 "and splits the image into AOVs by light path expressions."};
    app.require_subcommand(1);
    app.set_version_flag("--version", lightpath::versionText(), "Print the version and the build's options (Embree on or off)");
    app.footer(
        "Examples:\n"
        "  lightpath render scenes/lecture-room.toml -o out/room.png     beauty + one PNG per AOV\n"
        "  lightpath explain scenes/lecture-room.toml --pixel 320,240    why a pixel has its colour\n"
        "  lightpath lpe match 'E(D|G)L' EDL ESDL                        does a path match?\n"
        "  lightpath lpe check --set classes                             is the AOV set a partition?\n"
        "  lightpath lpe check --set taxonomy                            the nest of the four methods\n"
        "  lightpath lpe dot 'E(S*)(D|G)L' > automaton.dot               the automaton, for Graphviz\n"
        "  lightpath lpe exercise                                        the lecture's questions, checked\n"
        "  lightpath serve scenes/lecture-room.toml                      explore it in the browser\n"
        "  lightpath bench skip                                          what skipping saves\n"
        "  lightpath types material phong                                a scene type's keys\n\n"
        "Run `lightpath COMMAND --help` for each command's options.");
    lightpath::setActivity(std::string("running lightpath") + (argc > 1 ? std::string(" ") + argv[1] : std::string()));
    lightpath::addRenderCommand(app);
    lightpath::addExplainCommand(app);
    lightpath::addLpeCommand(app);
    lightpath::addBenchCommand(app);
    lightpath::addStressCommand(app);
    lightpath::addServeCommand(app);
    lightpath::addTypesCommand(app);
    lightpath::unmarkBracketedValues(app);
    const std::vector<std::string> arguments = lightpath::markBracketedArguments(argc, argv);
    std::vector<const char*> marked;
    for (const std::string& argument : arguments) marked.push_back(argument.c_str());
    try {
        app.parse(argc, marked.data());
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::RuntimeError& e) {
        std::cerr << "lightpath: " << lightpath::withoutMarks(e.what()) << "\n";
        return e.get_exit_code();
    } catch (const CLI::ParseError& e) {
        // Wrong arguments are bad input, whatever CLI11's own code for them; CLI11's message gets
        // the prefix and a did-you-mean like every other error.
        std::cerr << lightpath::withoutMarks(lightpath::parseErrorMessage(app, e)) << "\n";
        return lightpath::kExitBadInput;
    } catch (const lightpath::ConfigError& e) {
        // An option a command did not report itself (cli/render_flags.h does): bad input all the same.
        std::cerr << "lightpath: " << lightpath::withoutMarks(e.what()) << "\n";
        return lightpath::kExitBadInput;
    } catch (const lightpath::MemoryLimitError& e) {
        // A render the commands did not check first (bench): refused all the same, as bad input.
        std::cerr << "lightpath: " << e.what() << "\n";
        return lightpath::kExitBadInput;
    } catch (const std::bad_alloc&) {
        // The last resort: renders are refused before they allocate what the machine cannot give
        // (render/memory_limit.h), but anything else may still run out. No allocation here: the
        // activity's text was made before.
        std::fputs("lightpath: out of memory while ", stderr);
        std::fputs(lightpath::activity().c_str(), stderr);
        std::fputs(": the machine or this process's limit (ulimit -v) gave no more; free memory or ask for less "
                   "(fewer pixels, layers or samples)\n",
                   stderr);
        return lightpath::kExitFailure;
    } catch (const std::exception& e) {
        std::cerr << "lightpath: error: " << e.what() << "\n";
        return lightpath::kExitFailure;
    }
    return lightpath::kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
    return run(argc, argv);
}
