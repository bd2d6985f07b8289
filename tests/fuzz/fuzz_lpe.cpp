// libFuzzer target for the LPE engine: parser, compiler (Thompson, subset construction, Hopcroft),
// analysis, DOT and path strings.
//
// Input, line by line: `name=EXPR` or a bare `EXPR` is one output (at most kMaxExpressions);
// `!` asks for the complement output `rest` of E.*L, `!UNIVERSE` of UNIVERSE; `?PATH` is a path
// string to parse and match. Blank lines are ignored. A hash of the whole input seeds random paths
// and random walks through the automaton.
//
// Refused input (lpe::SyntaxError, lpe::LimitError) is fine. What a compiled set must satisfy,
// checked against references that are not the combined automaton itself:
// - each output accepts exactly what its expression compiled alone accepts; `rest` exactly what
//   the universe accepts and no named output does; the order of the expressions does not matter;
// - run() is stepping event by event; once isDead() says an output is out of reach, it stays so;
// - the table is closed, every state reachable, no two states equivalent (Moore's refinement,
//   written here independently of lpe/minimise.cpp), at most one dead state;
// - each output's shortest path is accepted and as long as the expression alone's shortest path;
// - every DOT edge label, read back as an LPE, matches exactly the events of that edge;
// - analyse(): examples are in both expressions (or none, for the gap) and the universe, and are
//   no longer than any sampled path with that property, which also proves the overlap or gap;
// - toTupleString, toDisplayString and toExpressionString read back through parsePath to the same
//   path (the last up to the scattering non-scattering events claim), and toExpressionString
//   compiled as an LPE accepts the path.
#include <algorithm>
#include <cstdint>
#include <map>
#include <optional>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include "fuzz_support.h"
#include "lpe/analysis.h"
#include "lpe/automaton.h"
#include "lpe/error.h"
#include "lpe/path_string.h"

namespace {

using lpe::Automaton;
using lpe::NamedExpression;
using lpe::OutputMask;
using lpe::Path;
using fuzz::broken;

// Bounds on one execution, so that no input takes seconds: its length, the number of outputs, the
// subset construction (LimitError beyond), and the size up to which the quadratic checks run.
constexpr std::size_t kMaxInput = 4096;
constexpr std::size_t kMaxExpressions = 8;
constexpr std::size_t kMaxStates = 4096;
constexpr std::size_t kMaxCheckedTable = 1 << 12;  // states x symbols
constexpr std::size_t kMaxDotStates = 64;
constexpr std::size_t kMaxDotSymbols = 25 * 9;  // 8 labels
constexpr std::size_t kPathsPerKind = 4;
constexpr std::size_t kMaxPathLength = 12;

struct Request {
    std::vector<NamedExpression> expressions;
    std::optional<std::string> universe;  // set by a `!` line: compile with the complement output
    std::vector<std::string> pathTexts;
};

bool isIdentifier(std::string_view name) {
    const auto identifierChar = [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
    };
    return !name.empty() && std::all_of(name.begin(), name.end(), identifierChar);
}

Request readRequest(std::string_view text) {
    Request request;
    for (const std::string_view line : fuzz::lines(text)) {
        if (line.empty()) continue;
        if (line.front() == '!') {
            request.universe = line.size() > 1 ? std::string(line.substr(1)) : std::string("E.*L");
        } else if (line.front() == '?') {
            request.pathTexts.emplace_back(line.substr(1));
        } else if (request.expressions.size() < kMaxExpressions) {
            NamedExpression e{"lpe" + std::to_string(request.expressions.size()), std::string(line)};
            const std::size_t equals = line.find('=');
            if (equals != std::string_view::npos && isIdentifier(line.substr(0, equals))) {
                e.name = std::string(line.substr(0, equals));
                e.expression = std::string(line.substr(equals + 1));
            }
            request.expressions.push_back(std::move(e));
        }
    }
    return request;
}

// Appended piece by piece: `"\"" + std::string` trips a false -Wrestrict in g++ 12.
std::string show(const Path& path) {
    std::string text = "\"";
    text += lpe::toTupleString(path);
    text += "\"";
    return text;
}

void checkSyntaxError(const lpe::SyntaxError& error, const std::vector<std::string>& texts) {
    if (error.position() > error.text().size())
        broken("SyntaxError position " + std::to_string(error.position()) + " beyond its text \"" + error.text() + "\"");
    if (std::find(texts.begin(), texts.end(), error.text()) == texts.end())
        broken("SyntaxError names \"" + error.text() + "\", which is none of the expressions");
    if (error.message().empty() || std::string_view(error.what()).empty()) broken("SyntaxError without a message");
}

// nullopt when the engine refuses the set as documented.
std::optional<Automaton> compileOrRefuse(const std::vector<NamedExpression>& expressions,
                                         const lpe::CompileOptions& options) {
    std::vector<std::string> texts;
    for (const NamedExpression& e : expressions) texts.push_back(e.expression);
    if (!options.complementName.empty()) texts.push_back(options.universe);
    try {
        return Automaton::compile(expressions, options);
    } catch (const lpe::SyntaxError& error) {
        checkSyntaxError(error, texts);
    } catch (const lpe::LimitError& error) {
        if (std::string_view(error.what()).empty()) broken("LimitError without a message");
    }
    return std::nullopt;
}

// A part of a set compiles whenever the whole set does: its subsets, labels and table are fewer.
Automaton compileAlone(const std::string& expression, const lpe::CompileOptions& options) {
    try {
        return Automaton::compile({{"alone", expression}}, options);
    } catch (const std::exception& error) {
        broken("\"" + expression + "\" compiles within a set but not alone: " + error.what());
    }
}

OutputMask bit(std::size_t output) { return OutputMask{1} << output; }

// The compiled set and the references it is checked against.
struct Subject {
    const Automaton& automaton;
    const std::vector<Automaton>& alone;     // one per named expression
    const std::optional<Automaton>& universe;  // with the complement output only
    std::size_t named = 0;
};

// What every output must say about `path`, from the references.
OutputMask expectedMask(const Subject& s, const Path& path) {
    OutputMask mask = 0;
    for (std::size_t i = 0; i < s.named; ++i)
        if (s.alone[i].run(path) & 1u) mask |= bit(i);
    if (s.universe && mask == 0 && (s.universe->run(path) & 1u)) mask |= bit(s.named);
    return mask;
}

void checkRoundTrips(const Path& path) {
    // Documented for paths of two events or more: one word without spaces or quotes is compact.
    if (path.size() < 2) return;
    const std::string tuple = lpe::toTupleString(path);
    if (lpe::parsePath(tuple) != path) broken("toTupleString " + show(path) + " does not read back");
    const std::string display = lpe::toDisplayString(path);
    if (lpe::parsePath(display) != path) broken("toDisplayString \"" + display + "\" of " + show(path) + " does not read back");
    const std::string compact = lpe::toCompactString(path);
    if (lpe::toCompactString(lpe::parsePath(compact)) != compact) broken("toCompactString \"" + compact + "\" is not stable");
    const std::string expression = lpe::toExpressionString(path);
    // Non-scattering events print no scattering (they match whatever they claim): compare as recorded.
    Path recorded = path;
    for (lpe::Event& e : recorded)
        if (!lpe::scatters(e.type)) e.scatter = lpe::Scatter::None;
    if (lpe::parsePath(expression) != recorded) broken("toExpressionString \"" + expression + "\" does not read back");
    try {
        if (!Automaton::compile({{"path", expression}}).matches(path, 0))
            broken("toExpressionString \"" + expression + "\" does not match its own path");
    } catch (const lpe::LimitError&) {
        // A path too long or with too many labels to compile says nothing about the printer.
    }
}

void checkPath(const Subject& s, const Path& path) {
    const Automaton& a = s.automaton;
    Automaton::State state = a.start();
    OutputMask unreachable = 0;  // outputs isDead() gave up on along the way
    for (const lpe::Event& event : path) {
        state = a.step(state, a.symbol(event));
        if (state >= a.stateCount()) broken("step left the table on " + show(path));
        for (std::size_t o = 0; o < a.outputCount(); ++o)
            if (a.isDead(state, bit(o))) unreachable |= bit(o);
    }
    const OutputMask mask = a.accepts(state);
    if (a.run(path) != mask) broken("run() differs from stepping on " + show(path));
    if (mask & unreachable) broken("an output isDead() gave up on accepts " + show(path));
    if (mask != expectedMask(s, path))
        broken("outputs " + std::to_string(mask) + " accept " + show(path) + ", the expressions alone say " +
               std::to_string(expectedMask(s, path)));
    checkRoundTrips(path);
}

// Table closed; every state reachable; isDead() against reachability computed here; no two
// states equivalent (Moore's partition refinement); at most one dead state.
void checkStructure(const Automaton& a) {
    const std::size_t states = a.stateCount(), symbols = a.symbolCount();
    if (a.start() >= states) broken("start state beyond the table");
    for (Automaton::State s = 0; s < states; ++s)
        for (Automaton::Symbol y = 0; y < symbols; ++y)
            if (a.step(s, y) >= states) broken("table entry beyond the state count");
    if (states * symbols > kMaxCheckedTable) return;

    std::vector<bool> reached(states, false);
    std::vector<Automaton::State> stack{a.start()};
    reached[a.start()] = true;
    while (!stack.empty()) {
        const Automaton::State s = stack.back();
        stack.pop_back();
        for (Automaton::Symbol y = 0; y < symbols; ++y) {
            if (!reached[a.step(s, y)]) {
                reached[a.step(s, y)] = true;
                stack.push_back(a.step(s, y));
            }
        }
    }
    if (std::count(reached.begin(), reached.end(), false) > 0) broken("unreachable state in a minimal automaton");

    std::vector<OutputMask> later(states);
    for (Automaton::State s = 0; s < states; ++s) later[s] = a.accepts(s);
    for (bool grew = true; grew;) {
        grew = false;
        for (Automaton::State s = 0; s < states; ++s) {
            OutputMask all = later[s];
            for (Automaton::Symbol y = 0; y < symbols; ++y) all |= later[a.step(s, y)];
            grew = grew || all != later[s];
            later[s] = all;
        }
    }
    std::size_t dead = 0;
    for (Automaton::State s = 0; s < states; ++s) {
        dead += later[s] == 0;
        for (std::size_t o = 0; o < a.outputCount(); ++o)
            if (a.isDead(s, bit(o)) != !(later[s] & bit(o))) broken("isDead() disagrees with reachability");
    }
    if (dead > 1) broken(std::to_string(dead) + " dead states in a minimal automaton");

    // Moore: states start in classes by accept mask; each round splits them by the classes their
    // symbols lead to, until a round splits nothing. Minimal means every state ends alone.
    std::vector<std::size_t> cls(states);
    std::map<OutputMask, std::size_t> byMask;
    for (Automaton::State s = 0; s < states; ++s) cls[s] = byMask.emplace(a.accepts(s), byMask.size()).first->second;
    std::size_t count = byMask.size();
    for (;;) {
        const std::size_t width = symbols + 1;
        std::vector<std::size_t> signature(states * width);  // own class, then each successor's
        for (Automaton::State s = 0; s < states; ++s) {
            signature[s * width] = cls[s];
            for (Automaton::Symbol y = 0; y < symbols; ++y) signature[s * width + 1 + y] = cls[a.step(s, y)];
        }
        const auto row = [&](Automaton::State s) { return signature.begin() + static_cast<std::ptrdiff_t>(s * width); };
        const auto less = [&](Automaton::State x, Automaton::State y) {
            return std::lexicographical_compare(row(x), row(x) + static_cast<std::ptrdiff_t>(width), row(y),
                                                row(y) + static_cast<std::ptrdiff_t>(width));
        };
        std::vector<Automaton::State> order(states);
        for (Automaton::State s = 0; s < states; ++s) order[s] = s;
        std::sort(order.begin(), order.end(), less);
        std::size_t next = 0;
        for (std::size_t i = 0; i < states; ++i) {
            if (i > 0 && less(order[i - 1], order[i])) ++next;
            cls[order[i]] = next;
        }
        if (next + 1 == count) break;
        count = next + 1;
    }
    if (count != states)
        broken("two equivalent states: " + std::to_string(states) + " states, " + std::to_string(count) + " classes");
}

// Reads back `  S -> T [label="LPE"];` lines and checks that each label matches exactly the events
// (one per symbol) that take S to T. Labels with control bytes are blanked in DOT: skipped.
void checkDot(const Automaton& a) {
    const std::string dot = a.toDot("fuzz \"set\" \\ title");
    if (!dot.starts_with("digraph ") || !dot.ends_with("}\n")) broken("toDot is not a digraph");
    for (const std::string& label : a.labels())
        for (const char c : label)
            if (static_cast<unsigned char>(c) < 0x20) return;

    const auto dead = [&](Automaton::State s) { return s != a.start() && a.isDead(s, a.allOutputs()); };
    struct Edge {
        Automaton::State from, to;
        Automaton matcher;
    };
    std::vector<Edge> edges;
    for (const std::string_view line : fuzz::lines(dot)) {
        const std::size_t arrow = line.find(" -> "), open = line.find(" [label=\"");
        if (arrow == std::string_view::npos || open == std::string_view::npos || !line.ends_with("\"];")) continue;
        std::string text;
        for (std::size_t i = open + 9; i + 3 < line.size(); ++i) {
            if (line[i] == '\\') ++i;
            text += line[i];
        }
        const auto from = static_cast<Automaton::State>(std::stoul(std::string(line.substr(0, arrow))));
        const auto to = static_cast<Automaton::State>(std::stoul(std::string(line.substr(arrow + 4, open - arrow - 4))));
        try {
            edges.push_back({from, to, Automaton::compile({{"edge", text}})});
        } catch (const std::exception& error) {
            broken("DOT edge label \"" + text + "\" is not an LPE: " + error.what());
        }
    }
    for (Automaton::State s = 0; s < a.stateCount(); ++s) {
        if (dead(s)) continue;
        for (Automaton::Symbol y = 0; y < a.symbolCount(); ++y) {
            const Path event{a.eventOf(y)};
            const Automaton::State to = a.step(s, y);
            std::size_t matching = 0;
            for (const Edge& edge : edges) {
                if (edge.from != s || !(edge.matcher.run(event) & 1u)) continue;
                ++matching;
                if (edge.to != to) broken("DOT edge " + std::to_string(s) + " -> " + std::to_string(edge.to) + " matches " + show(event));
            }
            if (matching != (dead(to) ? 0u : 1u))
                broken("event " + show(event) + " from state " + std::to_string(s) + " is on " + std::to_string(matching) + " DOT edges");
        }
    }
}

// Deterministic per input: the fuzzer explores paths by mutating the expressions.
class PathSource {
public:
    PathSource(std::string_view input, const Automaton& a) : automaton_(a) {
        std::uint64_t hash = 1469598103934665603ull;
        for (const char c : input) hash = (hash ^ static_cast<unsigned char>(c)) * 1099511628211ull;
        random_.seed(hash);
        labels_ = a.labels();
        std::string unnamed = "x";  // a label no expression names: label class 0, like no label
        while (std::find(labels_.begin(), labels_.end(), unnamed) != labels_.end()) unnamed += "x";
        labels_.push_back(unnamed);
    }

    // Events of any type, scattering and label, mostly from the camera to an emitter.
    Path randomPath() {
        Path path(below(kMaxPathLength + 1));
        for (lpe::Event& e : path) e = randomEvent();
        if (!path.empty() && below(4) != 0) path.front() = {lpe::EventType::Camera, lpe::Scatter::None, {}};
        if (path.size() > 1 && below(4) != 0) path.back().type = lpe::EventType::Emitter;
        return path;
    }

    // A walk along symbols that keep some output reachable, stopping at random in accepting states.
    Path walk() {
        const Automaton& a = automaton_;
        Path path;
        Automaton::State state = a.start();
        while (path.size() < kMaxPathLength) {
            if (a.accepts(state) != 0 && below(3) == 0) break;
            std::vector<Automaton::Symbol> alive;
            for (Automaton::Symbol y = 0; y < a.symbolCount(); ++y)
                if (!a.isDead(a.step(state, y), a.allOutputs())) alive.push_back(y);
            if (alive.empty()) break;
            const Automaton::Symbol y = alive[below(alive.size())];
            lpe::Event e = a.eventOf(y);
            if (e.label.empty() && below(2) == 0) e.label = labels_.back();
            path.push_back(std::move(e));
            state = a.step(state, y);
        }
        return path;
    }

private:
    std::size_t below(std::size_t n) { return static_cast<std::size_t>(random_() % n); }

    lpe::Event randomEvent() {
        lpe::Event e;
        e.type = static_cast<lpe::EventType>(below(lpe::kEventTypeCount));
        e.scatter = static_cast<lpe::Scatter>(below(lpe::kScatterCount));
        if (below(3) == 0) e.label = labels_[below(labels_.size())];
        return e;
    }

    const Automaton& automaton_;
    std::vector<std::string> labels_;
    std::mt19937_64 random_;
};

void checkShortestPaths(const Subject& s, std::vector<Path>& paths) {
    const Automaton& a = s.automaton;
    for (std::size_t o = 0; o < a.outputCount(); ++o) {
        const std::optional<Path> path = a.findShortestPath([o](OutputMask m) { return (m >> o) & 1u; });
        if (!path) {
            if (o < s.named && s.alone[o].findShortestPath([](OutputMask m) { return m != 0; }))
                broken("output " + a.outputName(o) + " accepts nothing, its expression alone accepts something");
            continue;
        }
        if (!((a.run(*path) >> o) & 1u)) broken("shortest path " + show(*path) + " of output " + a.outputName(o) + " is not accepted");
        if (o < s.named) {
            const std::optional<Path> alone = s.alone[o].findShortestPath([](OutputMask m) { return m != 0; });
            if (!alone || alone->size() != path->size())
                broken("output " + a.outputName(o) + "'s shortest path " + show(*path) + " is not as long as its expression's");
        }
        paths.push_back(*path);
    }
}

void checkAnalysis(const Request& request, const Subject& s, const std::vector<Path>& paths) {
    const std::string universeText = request.universe.value_or("E.*L");
    lpe::SetReport report;
    try {
        report = lpe::analyse(request.expressions, universeText);
    } catch (const std::exception& error) {
        broken(std::string("analyse() refuses a set that compiles: ") + error.what());
    }
    const Automaton& universe = s.universe ? *s.universe : compileAlone(universeText, {});
    const auto accepts = [&](std::size_t i, const Path& p) { return (s.alone[i].run(p) & 1u) != 0; };
    const std::size_t n = request.expressions.size();

    std::vector<std::vector<const lpe::Overlap*>> overlap(n, std::vector<const lpe::Overlap*>(n, nullptr));
    for (const lpe::Overlap& o : report.overlaps) {
        if (o.first >= o.second || o.second >= n || overlap[o.first][o.second]) broken("analyse() reports a bad pair");
        overlap[o.first][o.second] = &o;
        if (!accepts(o.first, o.example) || !accepts(o.second, o.example) || !(universe.run(o.example) & 1u))
            broken("overlap example " + show(o.example) + " is not in both expressions and the universe");
    }
    if (report.gap) {
        if (!(universe.run(*report.gap) & 1u)) broken("gap example " + show(*report.gap) + " is outside the universe");
        for (std::size_t i = 0; i < n; ++i)
            if (accepts(i, *report.gap)) broken("gap example " + show(*report.gap) + " is accepted");
    }
    for (const Path& p : paths) {
        if (!(universe.run(p) & 1u)) continue;
        bool any = false;
        for (std::size_t i = 0; i < n; ++i) {
            if (!accepts(i, p)) continue;
            any = true;
            for (std::size_t j = i + 1; j < n; ++j) {
                if (!accepts(j, p)) continue;
                if (!overlap[i][j] || overlap[i][j]->example.size() > p.size())
                    broken("analyse() misses or lengthens the overlap of " + std::to_string(i) + " and " +
                           std::to_string(j) + " shown by " + show(p));
            }
        }
        if (!any && (!report.gap || report.gap->size() > p.size()))
            broken("analyse() misses or lengthens the gap shown by " + show(p));
    }
    if (s.universe) {
        const auto rest = s.automaton.findShortestPath([n](OutputMask m) { return (m >> n) & 1u; });
        if (rest.has_value() != report.gap.has_value() || (rest && rest->size() != report.gap->size()))
            broken("the rest output and analyse()'s gap disagree");
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size > kMaxInput) return 0;
    const std::string_view input = fuzz::asText(data, size);
    const Request request = readRequest(input);

    lpe::CompileOptions options;
    options.maxStates = kMaxStates;
    if (request.universe) {
        options.complementName = "rest";
        options.universe = *request.universe;
    }
    const std::optional<Automaton> automaton = compileOrRefuse(request.expressions, options);
    if (!automaton) return 0;
    const Automaton& a = *automaton;
    if (a.outputCount() != request.expressions.size() + (request.universe ? 1 : 0)) broken("wrong output count");

    lpe::CompileOptions aloneOptions;
    aloneOptions.maxStates = kMaxStates;
    std::vector<Automaton> alone;
    for (const NamedExpression& e : request.expressions) alone.push_back(compileAlone(e.expression, aloneOptions));
    std::optional<Automaton> universe;
    if (request.universe) universe = compileAlone(*request.universe, aloneOptions);
    const Subject subject{a, alone, universe, request.expressions.size()};

    checkStructure(a);
    std::vector<NamedExpression> reversed(request.expressions.rbegin(), request.expressions.rend());
    const std::optional<Automaton> again = compileOrRefuse(reversed, options);
    if (!again || again->stateCount() != a.stateCount()) broken("the order of the expressions changes the automaton");

    std::vector<Path> paths;
    PathSource source(input, a);
    for (std::size_t i = 0; i < kPathsPerKind; ++i) {
        paths.push_back(source.randomPath());
        paths.push_back(source.walk());
    }
    for (const std::string& text : request.pathTexts) {
        try {
            paths.push_back(lpe::parsePath(text));
        } catch (const lpe::SyntaxError& error) {
            checkSyntaxError(error, {text});
        }
    }
    checkShortestPaths(subject, paths);
    for (const Path& path : paths) checkPath(subject, path);

    // Drawing covers every edge's symbols greedily: the costliest step, kept to small automata.
    if (a.stateCount() <= kMaxDotStates && a.symbolCount() <= kMaxDotSymbols) checkDot(a);
    if (a.stateCount() * a.symbolCount() <= kMaxCheckedTable) checkAnalysis(request, subject, paths);
    return 0;
}
