#include "cli/explain_command.h"

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <utility>

#include "cli/render_flags.h"
#include "config/exit_codes.h"
#include "integrators/event_symbols.h"
#include "io/text_file.h"
#include "lpe/path_string.h"

namespace lightpath {
namespace {

struct ExplainCommand {
    RenderFlags flags;
    std::string pixel;
    bool all = false;   // also the paths whose contributions sum to zero
    bool json = false;  // the documented JSON (docs/lpe.md) instead of text
};

// Which of bdpt's strategies made a contribution (Veach 1997 ch. 10): s vertices from the light, t
// from the eye; t = 1 is light tracing, splatted onto the pixel it lands on.
struct BdptStrategy {
    int s = 0, t = 0;
    bool splatted = false;

    std::string text() const {
        return "s=" + std::to_string(s) + " t=" + std::to_string(t) + (splatted ? " (light tracing, splatted here)" : "");
    }
};

// Identical paths (same events, labels and things touched) are one row: their contributions'
// count and sum, each contribution's value and the factors it is the product of.
struct PathGroup {
    lpe::Path path;
    std::string expression;  // toExpressionString: pasted into --lpe, it matches this path
    std::vector<std::string> touched;
    lpe::OutputMask accepted = 0;
    std::vector<Rgb> values;
    std::vector<std::vector<TermFactor>> factors;  // per contribution, per sample
    // Per contribution, each event's world position; none for the ambient term, which comes from
    // nowhere.
    std::vector<std::vector<std::optional<Vec3>>> positions;
    Rgb sum{0.0f};
    // bdpt: per contribution, the strategy (s light vertices, t eye vertices) that made it; none
    // for the other integrators.
    std::vector<std::optional<BdptStrategy>> strategies;
};

// Terms that added nothing, grouped by path and reason.
struct RejectionGroup {
    std::string expression;
    std::string reason;
    std::size_t count = 0;
};

// The recorded path as the LPE engine's Path, labelled as the automaton saw it.
lpe::Path toLpePath(const Scene& scene, const PathRecord& record) {
    lpe::Path path;
    for (std::size_t i = 0; i < record.size(); ++i) path.push_back(lpeEventOf(scene, record[i]));
    return path;
}

std::string formatRgb(const Rgb& v) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.6f %.6f %.6f", v.r, v.g, v.b);
    return buffer;
}

std::string jsonRgb(const Rgb& v) {
    char buffer[96];
    std::snprintf(buffer, sizeof buffer, "[%.9g, %.9g, %.9g]", v.r, v.g, v.b);
    return buffer;
}

// Rows sorted by contribution (Rec. 709 luminance of the sum), largest first; ties keep the
// order in which the renderer first produced the path.
std::vector<PathGroup> groupPaths(const Scene& scene, const std::vector<LoggedContribution>& log) {
    std::vector<PathGroup> groups;
    std::map<std::string, std::size_t> index;
    for (const LoggedContribution& c : log) {
        PathGroup group;
        group.path = toLpePath(scene, c.path);
        group.expression = lpe::toExpressionString(group.path);
        for (std::size_t e = 1; e < c.path.size(); ++e) group.touched.push_back(subjectName(scene, c.path[e]));
        std::string key = group.expression;
        for (const std::string& t : group.touched) key += "\n" + t;
        const auto [at, added] = index.emplace(key, groups.size());
        if (added) {
            group.accepted = c.accepted;
            groups.push_back(std::move(group));
        }
        PathGroup& g = groups[at->second];
        g.values.push_back(c.value);
        g.factors.emplace_back(c.factors.begin(), c.factors.begin() + static_cast<std::ptrdiff_t>(c.factorCount));
        std::vector<std::optional<Vec3>>& positions = g.positions.emplace_back();
        for (std::size_t e = 0; e < c.path.size(); ++e)
            positions.push_back(c.path[e].subject == Subject::Ambient ? std::nullopt
                                                                      : std::optional<Vec3>(c.path[e].position));
        g.sum += c.value;
        g.strategies.push_back(c.lightVertices < 0 ? std::nullopt
                                                   : std::optional<BdptStrategy>({c.lightVertices, c.eyeVertices, c.splatted}));
    }
    const auto luminance = [](const Rgb& v) { return 0.2126 * v.r + 0.7152 * v.g + 0.0722 * v.b; };
    std::stable_sort(groups.begin(), groups.end(),
                     [&](const PathGroup& a, const PathGroup& b) { return luminance(a.sum) > luminance(b.sum); });
    return groups;
}

std::vector<RejectionGroup> groupRejections(const Scene& scene, const std::vector<Rejection>& rejections) {
    std::vector<RejectionGroup> groups;
    std::map<std::string, std::size_t> index;
    for (const Rejection& r : rejections) {
        const std::string expression = lpe::toExpressionString(toLpePath(scene, r.path));
        const auto [at, added] = index.emplace(expression + "\n" + r.reason, groups.size());
        if (added) groups.push_back({expression, r.reason, 0});
        ++groups[at->second].count;
    }
    return groups;
}

std::string formatFactor(const TermFactor& f) {
    char buffer[96];
    if (f.value.r == f.value.g && f.value.g == f.value.b) std::snprintf(buffer, sizeof buffer, "%s %.4g", f.name, f.value.g);
    else std::snprintf(buffer, sizeof buffer, "%s (%.4g %.4g %.4g)", f.name, f.value.r, f.value.g, f.value.b);
    return buffer;
}

std::string jsonFactor(const TermFactor& f) {
    char buffer[128];
    if (f.value.r == f.value.g && f.value.g == f.value.b) std::snprintf(buffer, sizeof buffer, "%.9g", f.value.g);
    else std::snprintf(buffer, sizeof buffer, "[%.9g, %.9g, %.9g]", f.value.r, f.value.g, f.value.b);
    return jsonString(f.name) + ": " + buffer;
}

// At most this many contributions of a row show their factors in the text form.
constexpr std::size_t kFactorRows = 3;

std::vector<std::string> aovNames(const AovSet& aovs, lpe::OutputMask accepted) {
    std::vector<std::string> names;
    for (std::size_t o = 0; o < aovs.expressions().size(); ++o)
        if ((accepted >> o) & 1u) names.push_back(aovs.expressions()[o].name);
    if (names.empty()) names.push_back("rest");
    return names;
}

std::string joined(const std::vector<std::string>& words, const char* separator) {
    std::string text;
    for (const std::string& w : words) text += (text.empty() ? "" : separator) + w;
    return text;
}

// Per layer: the sum of every contribution it takes (beauty all, rest those no AOV accepts).
std::vector<Rgb> layerSums(const AovSet& aovs, const std::vector<PathGroup>& groups) {
    std::vector<Rgb> sums(aovs.layerCount(), Rgb{0.0f});
    for (const PathGroup& g : groups) {
        sums[0] += g.sum;
        if (g.accepted == 0) sums.back() += g.sum;
        for (std::size_t o = 0; o < aovs.expressions().size(); ++o)
            if ((g.accepted >> o) & 1u) sums[1 + o] += g.sum;
    }
    return sums;
}

void printText(const ExplainCommand& command, const RenderOptions& options, const AovSet& aovs, int x, int y,
               std::size_t contributions, const std::vector<PathGroup>& groups,
               const std::vector<RejectionGroup>& rejections) {
    std::size_t shown = 0, zero = 0;
    for (const PathGroup& g : groups) (isBlack(g.sum) ? zero : shown) += 1;
    if (command.all) shown += zero;
    std::printf("pixel %d,%d of %s (%s, %d spp): %zu contribution%s on %zu path%s\n\n", x, y,
                command.flags.config().scenePath.c_str(), options.integrator.c_str(), options.samplesPerPixel, contributions,
                contributions == 1 ? "" : "s", groups.size(), groups.size() == 1 ? "" : "s");
    std::size_t row = 0;
    for (const PathGroup& g : groups) {
        if (isBlack(g.sum) && !command.all) continue;
        std::printf("%3zu  %s\n     compact: %s   count: %zu   touched: %s\n     rgb:     %s%s\n     aovs:    %s\n",
                    ++row, g.expression.c_str(), lpe::toCompactString(g.path).c_str(), g.values.size(),
                    joined(g.touched, ", ").c_str(), formatRgb(g.sum).c_str(), g.values.size() > 1 ? "  (sum)" : "",
                    joined(aovNames(aovs, g.accepted), ", ").c_str());
        for (std::size_t v = 0; v < std::min(g.factors.size(), kFactorRows); ++v) {
            if (g.factors[v].empty()) continue;
            // The product's factors, then the values it depends on but is not multiplied by (pdfs).
            std::vector<std::string> words, values;
            for (const TermFactor& f : g.factors[v]) (f.inProduct ? words : values).push_back(formatFactor(f));
            std::printf("     factors: %s\n", joined(words, " x ").c_str());
            if (!values.empty()) std::printf("     values:  %s\n", joined(values, ", ").c_str());
        }
        if (g.factors.size() > kFactorRows) std::printf("     (factors of the first %zu of %zu samples shown)\n", kFactorRows, g.factors.size());
        std::vector<std::string> strategies;  // the distinct ones, in the order found
        for (const auto& strategy : g.strategies)
            if (strategy && std::find(strategies.begin(), strategies.end(), strategy->text()) == strategies.end())
                strategies.push_back(strategy->text());
        if (!strategies.empty()) std::printf("     strategy: %s\n", joined(strategies, ", ").c_str());
    }
    if (zero > 0 && !command.all)
        std::printf("\n(%zu path%s whose contributions sum to zero hidden; --all shows them)\n", zero, zero == 1 ? "" : "s");
    if (!rejections.empty()) {
        std::printf("\ndid not contribute\n");
        for (const RejectionGroup& r : rejections)
            std::printf("  %s  x%zu: %s\n", r.expression.c_str(), r.count, r.reason.c_str());
    }
    const auto layers = aovs.layerNames();
    const std::vector<Rgb> sums = layerSums(aovs, groups);
    std::printf("\nsums\n");
    for (std::size_t l = 0; l < layers.size(); ++l) {
        const std::string expression = (l == 0 || l + 1 == layers.size()) ? "" : aovs.expressions()[l - 1].expression;
        std::printf("  %-10s %s  %s\n", layers[l].c_str(), formatRgb(sums[l]).c_str(), expression.c_str());
    }
}

// The schema is documented in docs/lpe.md ("explain --json").
// A contribution's path for drawing: each vertex in world space, and each segment between two
// vertices projected onto the image (the part in front of the eye), null where there is none.
std::string jsonGeometry(const Camera& camera, const std::vector<std::optional<Vec3>>& positions) {
    char buffer[160];
    std::string json = "\"vertices\": [";
    for (std::size_t v = 0; v < positions.size(); ++v) {
        const auto& p = positions[v];
        if (p) std::snprintf(buffer, sizeof buffer, "[%.7g, %.7g, %.7g]", p->x, p->y, p->z);
        json += (v ? ", " : "") + std::string(p ? buffer : "null");
    }
    json += "], \"segments\": [";
    for (std::size_t v = 0; v + 1 < positions.size(); ++v) {
        const auto& a = positions[v];
        const auto& b = positions[v + 1];
        const auto ends = a && b ? camera.filmSegment(*a, *b) : std::nullopt;
        if (ends)
            std::snprintf(buffer, sizeof buffer, "[%.7g, %.7g, %.7g, %.7g]", (*ends)[0].x, (*ends)[0].y, (*ends)[1].x,
                          (*ends)[1].y);
        json += (v ? ", " : "") + std::string(ends ? buffer : "null");
    }
    return json + "]";
}

std::string jsonStrategy(const std::optional<BdptStrategy>& strategy) {
    if (!strategy) return "null";
    return "{\"s\": " + std::to_string(strategy->s) + ", \"t\": " + std::to_string(strategy->t) +
           ", \"splatted\": " + (strategy->splatted ? "true" : "false") + "}";
}

void printJson(const ExplainCommand& command, const Scene& scene, const RenderOptions& options, const AovSet& aovs,
               int x, int y, const std::vector<PathGroup>& groups, const std::vector<RejectionGroup>& rejections) {
    const Camera camera(scene.camera);
    std::ostringstream json;
    json << "{\n  \"schema\": \"lightpath-explain-1\",\n  \"scene\": " << jsonString(command.flags.config().scenePath)
         << ",\n  \"integrator\": " << jsonString(options.integrator) << ",\n  \"spp\": " << options.samplesPerPixel
         << ",\n  \"pixel\": [" << x << ", " << y << "],\n  \"layers\": [";
    const auto layers = aovs.layerNames();
    const std::vector<Rgb> sums = layerSums(aovs, groups);
    for (std::size_t l = 0; l < layers.size(); ++l) {
        const bool named = l > 0 && l + 1 < layers.size();
        json << (l ? "," : "") << "\n    {\"name\": " << jsonString(layers[l])
             << ", \"expression\": " << (named ? jsonString(aovs.expressions()[l - 1].expression) : "null")
             << ", \"rgb\": " << jsonRgb(sums[l]) << "}";
    }
    json << "\n  ],\n  \"paths\": [";
    bool first = true;
    std::size_t hidden = 0;
    for (const PathGroup& g : groups) {
        if (isBlack(g.sum) && !command.all) {
            ++hidden;
            continue;
        }
        json << (first ? "" : ",") << "\n    {\"path\": " << jsonString(g.expression)
             << ", \"compact\": " << jsonString(lpe::toCompactString(g.path)) << ", \"count\": " << g.values.size()
             << ", \"rgb\": " << jsonRgb(g.sum) << ",\n     \"events\": [";
        for (std::size_t e = 0; e < g.path.size(); ++e) {
            const lpe::Event& event = g.path[e];
            json << (e ? ", " : "") << "{\"type\": \"" << lpe::letter(event.type) << "\", \"scatter\": \""
                 << lpe::letter(event.scatter) << "\", \"label\": "
                 << (event.label.empty() ? "null" : jsonString(event.label))
                 << ", \"touched\": " << (e == 0 ? "null" : jsonString(g.touched[e - 1])) << "}";
        }
        json << "],\n     \"aovs\": [";
        const auto names = aovNames(aovs, g.accepted);
        for (std::size_t n = 0; n < names.size(); ++n) json << (n ? ", " : "") << jsonString(names[n]);
        json << "],\n     \"contributions\": [";
        for (std::size_t v = 0; v < g.values.size(); ++v) {
            json << (v ? ", " : "") << "{\"rgb\": " << jsonRgb(g.values[v]) << ", \"factors\": {";
            bool firstFactor = true;
            for (const TermFactor& f : g.factors[v])
                if (f.inProduct) json << (std::exchange(firstFactor, false) ? "" : ", ") << jsonFactor(f);
            json << "}, \"values\": {";
            firstFactor = true;
            for (const TermFactor& f : g.factors[v])
                if (!f.inProduct) json << (std::exchange(firstFactor, false) ? "" : ", ") << jsonFactor(f);
            json << "}, \"strategy\": " << jsonStrategy(g.strategies[v]) << ", " << jsonGeometry(camera, g.positions[v])
                 << "}";
        }
        json << "]}";
        first = false;
    }
    json << "\n  ],\n  \"rejected\": [";
    for (std::size_t r = 0; r < rejections.size(); ++r)
        json << (r ? "," : "") << "\n    {\"path\": " << jsonString(rejections[r].expression)
             << ", \"reason\": " << jsonString(rejections[r].reason) << ", \"count\": " << rejections[r].count << "}";
    json << "\n  ],\n  \"hidden_zero_paths\": " << hidden << "\n}\n";
    std::cout << json.str();
}

void run(const ExplainCommand& command) {
    const RenderConfig& config = command.flags.config();
    int x = 0, y = 0;
    char comma = 0, extra = 0;
    if (std::sscanf(command.pixel.c_str(), "%d%c%d%c", &x, &comma, &y, &extra) != 3 || comma != ',')
        throw CLI::RuntimeError("--pixel: expected X,Y such as 320,240, got \"" + command.pixel + "\"", kExitBadInput);
    const Scene scene = config.loadScene();
    const AovSet aovs = config.buildAovSet(scene);
    const RenderOptions options = config.renderOptions();
    std::vector<LoggedContribution> log;
    std::vector<Rejection> rejections;
    try {
        // explain makes no film: only what the integrator keeps per pixel (the z-buffer) must fit.
        PixelMemory memory = Renderer::pixelMemory(scene, aovs, options);
        memory.film = memory.splats = 0;
        config.refuseBeyondMemory(memory);
        log = Renderer(scene, aovs, options).explainPixel(x, y, &rejections);
    } catch (const std::invalid_argument& e) {
        throw CLI::RuntimeError(e.what(), kExitBadInput);
    }
    const std::vector<PathGroup> groups = groupPaths(scene, log);
    const std::vector<RejectionGroup> rejected = groupRejections(scene, rejections);
    if (command.json) {
        printJson(command, scene, options, aovs, x, y, groups, rejected);
    } else {
        printText(command, options, aovs, x, y, log.size(), groups, rejected);
    }
}

}  // namespace

void addExplainCommand(CLI::App& app) {
    auto command = std::make_shared<ExplainCommand>();
    CLI::App* sub = app.add_subcommand("explain", "Print every contribution to one pixel with its light path and AOVs");
    command->flags.addOptions(*sub);
    sub->add_option("--pixel", command->pixel, "Pixel X,Y (0,0 is the top-left corner)")->required();
    sub->add_flag("--all", command->all, "Also show the paths whose contributions sum to zero");
    sub->add_flag("--json", command->json, "Print JSON for tools (schema in docs/lpe.md) instead of text");
    sub->footer(
        "Identical paths are grouped, with their count and the sum of their contributions, and sorted\n"
        "by contribution, largest first; zero rows are hidden unless --all. Each path is printed as an\n"
        "expression that, pasted into --lpe, matches it (E <RD'floor'> <L.'key'>), then its compact\n"
        "form (EDL), the objects and lights it touched, its RGB and the AOVs that accept it; the sums\n"
        "per layer follow.\n\n"
        "Examples:\n"
        "  lightpath explain scenes/lecture-room.toml --pixel 320,240\n"
        "  lightpath explain scenes/mirror-sphere.toml --pixel 300,200 --lpe \"mirror=E<RS>+.*\"");
    sub->callback([command] {
        reportingConfigErrors([&] {
            command->flags.apply();
            run(*command);
        });
    });
}

}  // namespace lightpath
