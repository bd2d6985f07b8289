#include "cli/lpe_command.h"

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "cli/parse_errors.h"
#include "config/messages.h"
#include "config/exit_codes.h"
#include "config/lpe_verdict.h"
#include "config/reach.h"
#include "film/aov_presets.h"
#include "integrators/registry.h"
#include "lpe/analysis.h"
#include "lpe/automaton.h"
#include "lpe/error.h"
#include "lpe/path_string.h"
#include "lpe/reading.h"

namespace lightpath {
namespace {


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

// "E[S*](D|G)L  read as E(S*)?(D|G)L (Heckbert: [ ] = optional)" when lightpath's reading is not
// what was written; the warnings of spellings other dialects read otherwise.
std::string readingNote(const std::string& expression, const Warnings& warn, const std::string& name) {
    const lpe::Reading reading = lpe::readExpression(expression);
    for (const std::string& warning : reading.warnings) warn((name.empty() ? "" : name + ": ") + warning);
    if (reading.notes.empty()) return {};
    std::string notes;
    for (const std::string& note : reading.notes) notes += (notes.empty() ? "" : "; ") + note;
    return "  read as " + reading.text + " (" + notes + ")";
}

// The one judge (config/lpe_verdict.h), as render applies it: refuses (exit 2) an expression no path
// of `integrator` (null: of any integrator) can ever match, warns of one that needs a volume.
void judge(const std::vector<lpe::NamedExpression>& expressions, const IntegratorInfo* integrator,
           const std::string& command, const Warnings& warn) {
    for (const auto& e : expressions) {
        const Judgement judgement = judgeExpression(e, integrator);
        if (judgement.verdict == Verdict::Refused)
            throw CLI::RuntimeError(command + ": " + e.name + ": " + refusalMessage(e, integrator, judgement.reason),
                                    kExitBadInput);
        if (judgement.verdict == Verdict::BlackHere) warn(warningMessage(e, judgement));
    }
}

struct MatchOptions {
    std::vector<std::string> arguments;  // EXPRESSION PATH..., or PATH... with --set
    std::string integrator;              // judge the expression as render does under it
    std::string set;
    bool trace = false;
    bool quiet = false;
};

// The states a path passes through: the start, then the state after each event, numbered as
// `lpe dot` numbers them for the same expressions; "dead" where nothing can accept any more.
std::string stateTrace(const lpe::Automaton& automaton, const lpe::Path& path) {
    lpe::Automaton::State state = automaton.start();
    std::string trace = "states: " + std::to_string(state);
    for (const lpe::Event& event : path) {
        state = automaton.step(state, automaton.symbol(event));
        trace += " " + std::to_string(state);
        if (automaton.isDead(state, automaton.allOutputs())) return trace + " (dead)";
    }
    return trace;
}

// A path argument of `lpe match`. One word of a scattering type and its scattering ("RS", "TD") is
// that one event, as a reader asking whether `[SG]` matches RS means it; lpe::parsePath reads the
// word as compact Heckbert (R with no scattering, then S), a path no renderer records.
lpe::Path readMatchPath(const std::string& text) {
    std::size_t first = text.find_first_not_of(" \t"), last = text.find_last_not_of(" \t");
    if (first != std::string::npos && last == first + 1) {
        const auto type = lpe::eventTypeOf(text[first]);
        const auto scatter = lpe::scatterOf(text[last]);
        if (type && lpe::scatters(*type) && scatter && *scatter != lpe::Scatter::None)
            return lpe::parsePath("<" + text.substr(first, 2) + ">");
    }
    return lpe::parsePath(text);
}

void runMatch(const MatchOptions& options) {
    std::vector<lpe::NamedExpression> expressions;
    std::vector<std::string> pathTexts = options.arguments;
    if (const auto preset = findAovPreset(options.set)) {
        expressions = preset->expressions();
    } else if (!pathTexts.empty()) {
        expressions.push_back({"lpe", pathTexts.front()});
        pathTexts.erase(pathTexts.begin());
    }
    if (pathTexts.empty())
        throw CLI::RuntimeError("lpe match: expected an expression (or --set NAME) and at least one path", kExitBadInput);
    const lpe::Automaton automaton = lpe::Automaton::compile(expressions);
    if (!options.integrator.empty()) judge(expressions, findIntegrator(options.integrator), "lpe match", Warnings(options.quiet));
    // Read every path first: a typo in the last one should not leave half a report.
    std::vector<lpe::Path> paths;
    for (const std::string& text : pathTexts) paths.push_back(readMatchPath(text));
    if (options.set.empty()) {
        const std::string note = readingNote(expressions.front().expression, Warnings(options.quiet), "");
        if (!note.empty()) std::cout << expressions.front().expression << note << '\n';
    }
    std::size_t width = std::string("no match").size();
    for (const auto& e : expressions) width = std::max(width, e.name.size());
    for (std::size_t i = 0; i < paths.size(); ++i) {
        const lpe::OutputMask accepted = automaton.run(paths[i]);
        std::string verdict;
        if (options.set.empty()) {
            verdict = accepted != 0 ? "match" : "no match";
        } else {
            for (std::size_t o = 0; o < automaton.outputCount(); ++o)
                if ((accepted >> o) & 1u) verdict += (verdict.empty() ? "" : ",") + automaton.outputName(o);
            if (verdict.empty()) verdict = "no match";
        }
        std::cout << verdict << std::string(width + 2 - std::min(width + 1, verdict.size()), ' ') << pathTexts[i] << '\n';
        if (options.trace) std::cout << std::string(width + 2, ' ') << stateTrace(automaton, paths[i]) << '\n';
    }
}

struct SetOptions {
    std::vector<std::string> expressions;
    std::string set;
    std::string universe;
    std::string output;
    std::string integrator;
    bool quiet = false;
};

std::vector<lpe::NamedExpression> expressionsOf(const SetOptions& options) {
    std::vector<lpe::NamedExpression> expressions;
    if (const auto preset = findAovPreset(options.set)) expressions = preset->expressions();
    for (std::size_t i = 0; i < options.expressions.size(); ++i) {
        expressions.push_back(namedExpression(options.expressions[i], i));
    }
    if (expressions.empty()) {
        std::string sets;
        for (const std::string& name : aovPresetNames(false)) sets += (sets.empty() ? "" : "|") + name;
        throw CLI::RuntimeError("lpe: give at least one expression or --set " + sets, kExitBadInput);
    }
    return expressions;
}

// The nest: every strict containment as maximal chains (A ⊂ B ⊂ C), then each covering pair with a
// shortest path of the larger that the smaller lacks, and the overlapping pairs neither of which
// contains the other. Nothing when no expression contains another and none overlap.
// Letters of OSL's alphabet that a gap may hold but no lightpath integrator produces (registry.h's
// kRenderedPaths): said, so that a gap such as EsL is not read as light the set loses.
void printUnrenderedEvents(const lpe::Path& path) {
    const bool straight = std::any_of(path.begin(), path.end(), [](const lpe::Event& e) { return e.scatter == lpe::Scatter::Straight; });
    const bool volume = std::any_of(path.begin(), path.end(), [](const lpe::Event& e) { return e.type == lpe::EventType::Volume; });
    if (straight)
        std::cout << "      s is OSL's straight event (a ray passing through a surface unbent): no lightpath integrator "
                     "produces one, so no light falls in this gap\n";
    if (volume)
        std::cout << "      V is a volume event: only scenes with [media] under --integrator path have them\n";
}

void printNest(const std::vector<lpe::NamedExpression>& expressions, const std::string& universe,
               const lpe::SetReport& report) {
    const std::size_t n = expressions.size();
    const lpe::Containment c = lpe::compareLanguages(expressions, universe);
    const auto covers = [&](std::size_t larger, std::size_t smaller) {
        if (!c.strictlyContains(larger, smaller)) return false;
        for (std::size_t k = 0; k < n; ++k)
            if (k != larger && k != smaller && c.strictlyContains(larger, k) && c.strictlyContains(k, smaller)) return false;
        return true;
    };
    std::vector<std::string> lines;
    std::vector<std::string> chains;
    const auto extend = [&](auto&& self, std::vector<std::size_t> chain) -> void {
        bool longer = false;
        for (std::size_t j = 0; j < n; ++j) {
            if (!covers(j, chain.back())) continue;
            longer = true;
            auto next = chain;
            next.push_back(j);
            self(self, next);
        }
        if (!longer && chain.size() > 1) {
            std::string text;
            for (const std::size_t i : chain) text += (text.empty() ? "" : " \u2282 ") + expressions[i].name;
            chains.push_back(text);
        }
    };
    for (std::size_t i = 0; i < n; ++i) {
        bool minimal = true;
        for (std::size_t k = 0; k < n; ++k) minimal = minimal && !c.strictlyContains(i, k);
        if (minimal) extend(extend, {i});
    }
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j) {
            if (i < j && c.contains(i, j) && c.contains(j, i))
                lines.push_back(expressions[i].name + " = " + expressions[j].name + ": they accept the same paths");
            if (covers(j, i))
                lines.push_back(expressions[i].name + " \u2282 " + expressions[j].name + ": " +
                                lpe::toDisplayString(*c.onlyIn[j][i]) + " is only in " + expressions[j].name);
        }
    for (const lpe::Overlap& o : report.overlaps) {
        const std::size_t i = o.first, j = o.second;
        if (c.contains(i, j) || c.contains(j, i)) continue;
        lines.push_back(expressions[i].name + ", " + expressions[j].name + ": neither contains the other (" +
                        lpe::toDisplayString(*c.onlyIn[i][j]) + " only in " + expressions[i].name + ", " +
                        lpe::toDisplayString(*c.onlyIn[j][i]) + " only in " + expressions[j].name + ")");
    }
    if (chains.empty() && lines.empty()) return;
    std::cout << "nest (A \u2282 B: B accepts every path of " << universe << " that A accepts, and more):\n";
    for (const std::string& chain : chains) std::cout << "  " << chain << '\n';
    for (const std::string& line : lines) std::cout << "  " << line << '\n';
}

// Which expressions `integrator` can ever fill, and why not the others.
void printIntegrator(const std::vector<lpe::NamedExpression>& expressions, const std::string& name, std::size_t width) {
    const IntegratorInfo* info = findIntegrator(name);
    std::cout << "--integrator " << info->name << " renders " << info->pathLanguage << ":\n";
    for (const auto& e : expressions) {
        const Judgement judgement = judgeExpression(e, info);
        std::cout << "  " << e.name << std::string(width + 2 - e.name.size(), ' ')
                  << (judgement.verdict == Verdict::Fillable ? std::string("can be filled")
                      : judgement.verdict == Verdict::BlackHere ? "black: " + judgement.reason
                                                                : "never filled: " + judgement.reason)
                  << '\n';
    }
}

void runCheck(const SetOptions& options) {
    const std::vector<lpe::NamedExpression> expressions = expressionsOf(options);
    const auto preset = findAovPreset(options.set);
    const std::string universe =
        !options.universe.empty() ? options.universe : preset ? std::string(preset->schema.events) : "E.*L";
    const Warnings warn(options.quiet);
    // Judged as render judges them, under --integrator or else under any integrator; an expression
    // over a --universe of the user's own is the engine's alone (any event strings).
    const IntegratorInfo* integrator = options.integrator.empty() ? nullptr : findIntegrator(options.integrator);
    if (integrator || options.universe.empty()) judge(expressions, integrator, "lpe check", warn);
    const lpe::SetReport report = lpe::analyse(expressions, universe);

    std::size_t width = 0;
    for (const auto& e : expressions) width = std::max(width, e.name.size());
    for (const auto& e : expressions) {
        std::cout << e.name << std::string(width + 2 - e.name.size(), ' ') << e.expression
                  << readingNote(e.expression, warn, e.name) << '\n';
    }
    if (expressions.size() > 1) printNest(expressions, universe, report);
    for (const lpe::Overlap& o : report.overlaps) {
        std::cout << "overlap: " << expressions[o.first].name << " and " << expressions[o.second].name
                  << " both accept " << lpe::toDisplayString(o.example) << '\n';
    }
    if (report.gap) {
        std::cout << "gap: no expression accepts " << lpe::toDisplayString(*report.gap) << '\n';
        printUnrenderedEvents(*report.gap);
    }
    std::cout << "partition of " << universe << ": " << (report.partition() ? "yes" : "no") << '\n';
    if (!options.integrator.empty()) printIntegrator(expressions, options.integrator, width);
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

// The lecture's table of methods: per path class and integrator, whether it produces some path of
// the class under point lights and under area lights (config/reach.h).
void runReach(const std::vector<std::string>& given) {
    std::vector<std::string> classes = given;
    if (classes.empty()) classes.assign(kReachClasses.begin(), kReachClasses.end());
    std::size_t width = std::string("path class").size();
    for (const std::string& c : classes) width = std::max(width, c.size());
    std::cout << "who reaches what: point lights / area lights (yes: it can produce some path of the class)\n";
    std::cout << "path class" << std::string(width + 2 - 10, ' ');
    for (const IntegratorInfo& info : integrators()) {
        const std::string name = info.name;
        std::cout << name << std::string(std::max<std::size_t>(name.size(), 9) + 2 - name.size(), ' ');
    }
    std::cout << '\n';
    for (const std::string& pathClass : classes) {
        std::cout << pathClass << std::string(width + 2 - pathClass.size(), ' ');
        for (const IntegratorInfo& info : integrators()) {
            const Reach reach = reachOf(info, pathClass);
            const std::string cell = std::string(reach.pointLights ? "yes" : "no") + "/" + (reach.areaLights ? "yes" : "no");
            const std::size_t column = std::max<std::size_t>(std::string(info.name).size(), 9) + 2;
            std::cout << cell << std::string(column - cell.size(), ' ');
        }
        std::cout << '\n';
    }
}

void addSetArguments(CLI::App& command, SetOptions& options) {
    command.add_option("expressions", options.expressions, "[name=]EXPR, e.g. raycast='E(D|G)L'");
    command.add_option("--set", options.set, "start from a predefined set")->check(oneOf(aovPresetNames(false)));
}

}  // namespace

void addLpeCommand(CLI::App& app) {
    CLI::App* lpe = app.add_subcommand("lpe", "Light path expressions: match paths, check AOV sets, draw automata");
    lpe->require_subcommand(1);
    lpe->footer(
        "Examples:\n"
        "  lightpath lpe match 'E(D|G)L' EDL ESDL\n"
        "  lightpath lpe check --set classes\n"
        "  lightpath lpe dot 'E(S*)(D|G)L' -o automaton.dot\n"
        "  lightpath lpe exercise --question mirror-only --answer 'ES+L'\n\n"
        "Syntax: E (or C) camera, L any emitter (light, emitting object O or background B), D G S s\n"
        "scattering, R T V reflection, transmission and volume, . any event, <RS> and <L.'key'> tuples\n"
        "(type, scattering, 'label'), [SG] and [^D] sets, Heckbert's [S*] = (S*)?, 'name' labels, and\n"
        "| ( ) * + ? {n} {n,} {n,m}. docs/lpe.md has the rules and the differences from OSL.");

    auto match = std::make_shared<MatchOptions>();
    CLI::App* matchCommand = lpe->add_subcommand("match", "Does each path match the expression?");
    matchCommand->add_option("expression-and-paths", match->arguments,
                             "the light path expression (unless --set), then paths: compact (ESDL), tuples "
                             "(\"E RS RD'floor' L'key'\", or one event: RS) or as explain prints them (\"E <RS> <RD'floor'> <L.'key'>\")");
    matchCommand->add_option("--set", match->set, "match against a predefined set's expressions (every argument is a path)")
        ->check(oneOf(aovPresetNames(false)));
    matchCommand->add_flag("--trace", match->trace,
                           "also print the automaton states each path passes through, numbered as lpe dot draws them");
    matchCommand->add_option("--integrator", match->integrator,
                             "refuse the expression, as render would, if this integrator can never fill it")
        ->check(oneOf(integratorNames()));
    matchCommand->add_flag("--quiet", match->quiet, "no warnings");
    matchCommand->footer(
        "Prints `match` or `no match` and the path, one line per path; first, when lightpath reads the\n"
        "expression otherwise than it is written (Heckbert's [ ] = optional, <L'key'> = <L.'key'>), the\n"
        "reading it used. With --set, the names of the expressions that accept each path instead.\n"
        "With --trace, a second line per path: `states:` the start state, then the state after each\n"
        "event, as `lpe dot` numbers them for the same expressions (`(dead)`: nothing can accept any more).\n\n"
        "Examples:\n"
        "  lightpath lpe match 'E(D|G)L' EDL ESDL        match EDL, no match ESDL\n"
        "  lightpath lpe match 'ES*<L.'\\''key'\\''>' \"E RS L'key'\" \"E L'fill'\"\n"
        "  lightpath lpe match '<TS>+L' \"TS TS L\" \"RS L\"   refraction only\n"
        "  lightpath lpe match --set classes --trace EDL ESDL   raycast, raytrace, and their states");
    matchCommand->callback([match] { reportingErrors([&] { runMatch(*match); }); });

    auto check = std::make_shared<SetOptions>();
    CLI::App* checkCommand = lpe->add_subcommand("check", "Report overlaps and gaps of a set of expressions");
    addSetArguments(*checkCommand, *check);
    checkCommand->add_option("--universe", check->universe,
                             "the paths the set should split (default E.*L; E(<[RT][DGS]>|<Vx>)*L with --set classes)");
    checkCommand->add_option("--integrator", check->integrator,
                             "refuse, as render does, an expression this integrator can never fill (default: "
                             "one no integrator can fill), and say which of a --set's it fills")
        ->check(oneOf(integratorNames()));
    checkCommand->add_flag("--quiet", check->quiet, "no warnings");
    checkCommand->footer(
        "Decides containment, not only overlap: the nest (A \u2282 B) of the expressions, each strict\n"
        "containment with a shortest path of the larger that the smaller lacks. Every overlapping pair\n"
        "is shown with a shortest path both accept, the gap with a shortest path of the universe none\n"
        "accepts. A set is a partition when there is neither: its AOVs then sum exactly to the beauty.\n"
        "An expression no integrator can ever fill is refused (exit 2) as render refuses it; with\n"
        "--integrator NAME, one that integrator cannot fill (docs/lpe.md, \"No silent black AOVs\"), and\n"
        "a --set's AOVs are listed as filled or not. With only --universe, expressions are plain languages.\n"
        "Unnamed expressions are called lpe1, lpe2, ...\n\n"
        "Examples:\n"
        "  lightpath lpe check --set classes\n"
        "  lightpath lpe check --set taxonomy --integrator whitted\n"
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
        "  lightpath lpe dot key='E.*<L.'\\''key'\\''>' fill='E.*<L.'\\''fill'\\''>'");
    dotCommand->callback([dot] { reportingErrors([&] { runDot(*dot); }); });

    auto reach = std::make_shared<std::vector<std::string>>();
    CLI::App* reachCommand =
        lpe->add_subcommand("reach", "Which integrator can produce which paths, with point lights and with area lights");
    reachCommand->add_option("classes", *reach, "path classes as LPEs (default: the lecture's seven)");
    reachCommand->footer(
        "Prints, for every integrator and path class, whether it can produce some path of the class\n"
        "when every light is a point light and when lights have area: the lecture's table of methods,\n"
        "read off each integrator's declared path languages by automata (src/integrators/registry.h).\n\n"
        "Examples:\n"
        "  lightpath lpe reach\n"
        "  lightpath lpe reach 'ES+(D|G)S+<L.>'");
    reachCommand->callback([reach] { reportingErrors([&] { runReach(*reach); }); });

    addLpeExerciseCommand(*lpe);
}

}  // namespace lightpath
