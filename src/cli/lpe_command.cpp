#include "cli/lpe_command.h"

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "lpe/analysis.h"
#include "lpe/automaton.h"
#include "lpe/error.h"
#include "lpe/path_string.h"

namespace lightpath {
namespace {

// The README's exit codes (cli/exit_codes.h); this file depends on CLI11 and lpe only.
constexpr int kExitFailure = 1;
constexpr int kExitBadInput = 2;

// Runs a subcommand, turning the engine's errors into CLI11's, which main() reports.
template <class Body>
void reportingErrors(Body body) {
    try {
        body();
    } catch (const lpe::SyntaxError& e) {
        throw CLI::RuntimeError(e.what(), kExitBadInput);
    } catch (const lpe::LimitError& e) {
        throw CLI::RuntimeError(e.what(), kExitBadInput);
    }
}

// "name=EXPR" or a bare "EXPR" (named lpe1, lpe2, ...). The name must look like an identifier, so
// an `=` inside a quoted label ('a=b') is not taken for one.
lpe::NamedExpression namedExpression(const std::string& argument, std::size_t index) {
    const std::size_t equals = argument.find('=');
    const auto identifier = [](const std::string& name) {
        if (name.empty() || std::isdigit(static_cast<unsigned char>(name.front()))) return false;
        for (const char c : name) {
            if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-') return false;
        }
        return true;
    };
    if (equals != std::string::npos && identifier(argument.substr(0, equals))) {
        return {argument.substr(0, equals), argument.substr(equals + 1)};
    }
    return {"lpe" + std::to_string(index + 1), argument};
}

struct MatchOptions {
    std::string expression;
    std::vector<std::string> paths;
};

void runMatch(const MatchOptions& options) {
    const lpe::Automaton automaton = lpe::Automaton::compile({{"lpe", options.expression}});
    // Read every path first: a typo in the last one should not leave half a report.
    std::vector<lpe::Path> paths;
    for (const std::string& text : options.paths) paths.push_back(lpe::parsePath(text));
    for (std::size_t i = 0; i < paths.size(); ++i) {
        std::cout << (automaton.matches(paths[i], 0) ? "match     " : "no match  ") << options.paths[i] << '\n';
    }
}

struct SetOptions {
    std::vector<std::string> expressions;
    std::string set;
    std::string universe;
    std::string output;
};

std::vector<lpe::NamedExpression> expressionsOf(const SetOptions& options) {
    std::vector<lpe::NamedExpression> expressions;
    if (options.set == "classes") expressions = lpe::classesSet();
    if (options.set == "taxonomy") expressions = lpe::taxonomySet();
    for (std::size_t i = 0; i < options.expressions.size(); ++i) {
        expressions.push_back(namedExpression(options.expressions[i], i));
    }
    if (expressions.empty()) {
        throw CLI::RuntimeError("lpe: give at least one expression or --set classes|taxonomy", kExitBadInput);
    }
    return expressions;
}

void runCheck(const SetOptions& options) {
    const std::vector<lpe::NamedExpression> expressions = expressionsOf(options);
    const std::string universe =
        !options.universe.empty() ? options.universe : options.set == "classes" ? "E(D|G|S)*L" : "E.*L";
    const lpe::SetReport report = lpe::analyse(expressions, universe);

    std::size_t width = 0;
    for (const auto& e : expressions) width = std::max(width, e.name.size());
    for (const auto& e : expressions) {
        std::cout << e.name << std::string(width + 2 - e.name.size(), ' ') << e.expression << '\n';
    }
    for (const lpe::Overlap& o : report.overlaps) {
        std::cout << "overlap: " << expressions[o.first].name << " and " << expressions[o.second].name
                  << " both accept " << lpe::toDisplayString(o.example) << '\n';
    }
    if (report.gap) std::cout << "gap: no expression accepts " << lpe::toDisplayString(*report.gap) << '\n';
    std::cout << "partition of " << universe << ": " << (report.partition() ? "yes" : "no") << '\n';
}

void runDot(const SetOptions& options) {
    const std::vector<lpe::NamedExpression> expressions = expressionsOf(options);
    std::string title;
    for (const auto& e : expressions) title += (title.empty() ? "" : ", ") + e.name + " = " + e.expression;
    const std::string dot = lpe::Automaton::compile(expressions).toDot(title);
    if (options.output.empty()) {
        std::cout << dot;
        return;
    }
    std::ofstream file(options.output);
    if (!(file << dot) || !file.flush()) {
        throw CLI::RuntimeError("lpe dot: cannot write " + options.output, kExitFailure);
    }
}

void addSetArguments(CLI::App& command, SetOptions& options) {
    command.add_option("expressions", options.expressions, "[name=]EXPR, e.g. raycast='E(D|G)L'");
    command.add_option("--set", options.set, "start from a predefined set")
        ->check(CLI::IsMember({"classes", "taxonomy"}));
}

}  // namespace

void addLpeCommand(CLI::App& app) {
    CLI::App* lpe = app.add_subcommand("lpe", "Light path expressions: match paths, check AOV sets, draw automata");
    lpe->require_subcommand(1);
    lpe->footer(
        "Examples:\n"
        "  lightpath lpe match 'E(D|G)L' EDL ESDL\n"
        "  lightpath lpe check --set classes\n"
        "  lightpath lpe dot 'E(S*)(D|G)L' -o automaton.dot\n\n"
        "Syntax: E camera, L emitter or background, B background, D G S s scattering, R T reflection\n"
        "and transmission, . any event, <RS> tuples (type, scattering, 'label'), [^D] sets,\n"
        "'name' labels, and | ( ) * + ? {n} {n,} {n,m}.");

    auto match = std::make_shared<MatchOptions>();
    CLI::App* matchCommand = lpe->add_subcommand("match", "Does each path match the expression?");
    matchCommand->add_option("expression", match->expression, "the light path expression")->required();
    matchCommand->add_option("paths", match->paths, "paths, compact (ESDL) or tuples (\"E RS RD'floor' L'key'\")")
        ->required();
    matchCommand->footer(
        "Prints `match` or `no match` and the path, one line per path.\n\n"
        "Examples:\n"
        "  lightpath lpe match 'E(D|G)L' EDL ESDL        match EDL, no match ESDL\n"
        "  lightpath lpe match 'ES*<L'\\''key'\\''>' \"E RS L'key'\" \"E L'fill'\"\n"
        "  lightpath lpe match '<TS>+L' \"TS TS L\" \"RS L\"   refraction only");
    matchCommand->callback([match] { reportingErrors([&] { runMatch(*match); }); });

    auto check = std::make_shared<SetOptions>();
    CLI::App* checkCommand = lpe->add_subcommand("check", "Report overlaps and gaps of a set of expressions");
    addSetArguments(*checkCommand, *check);
    checkCommand->add_option("--universe", check->universe,
                             "the paths the set should split (default E.*L; E(D|G|S)*L with --set classes)");
    checkCommand->footer(
        "Every overlapping pair is shown with a shortest path both accept, the gap with a shortest\n"
        "path of the universe none accepts. A set is a partition when there is neither: its AOVs\n"
        "then sum exactly to the beauty. Unnamed expressions are called lpe1, lpe2, ...\n\n"
        "Examples:\n"
        "  lightpath lpe check --set classes\n"
        "  lightpath lpe check --set taxonomy\n"
        "  lightpath lpe check direct='E(D|G)L' indirect='E.+(D|G)L' --universe 'E.*(D|G)L'");
    checkCommand->callback([check] { reportingErrors([&] { runCheck(*check); }); });

    auto dot = std::make_shared<SetOptions>();
    CLI::App* dotCommand = lpe->add_subcommand("dot", "Draw the compiled automaton for Graphviz");
    addSetArguments(*dotCommand, *dot);
    dotCommand->add_option("-o,--output", dot->output, "write to FILE instead of standard output");
    dotCommand->footer(
        "States are numbered from the start (0); double circles accept, labelled with their\n"
        "outputs. Edges read in LPE syntax. The dead state, from which nothing can accept, is left out.\n\n"
        "Examples:\n"
        "  lightpath lpe dot 'E(S*)(D|G)L' | dot -Tsvg > whitted.svg\n"
        "  lightpath lpe dot --set classes -o classes.dot\n"
        "  lightpath lpe dot key='E.*<L'\\''key'\\''>' fill='E.*<L'\\''fill'\\''>'");
    dotCommand->callback([dot] { reportingErrors([&] { runDot(*dot); }); });
}

}  // namespace lightpath
