#include "cli/explain_command.h"

#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>

#include "cli/exit_codes.h"
#include "cli/render_setup.h"
#include "lpe/path_string.h"

namespace lightpath {
namespace {

struct ExplainCommand {
    RenderSetup setup;
    std::string pixel;
};

// What an event touched, as a student reads it: the object's or light's name.
std::string subjectName(const Scene& scene, const PathEvent& event) {
    switch (event.subject) {
        case Subject::None:
            if (event.type == lpe::EventType::Background) return "background";
            // Radiosity's intermediate bounces: a sum over every patch, so no one object.
            if (event.type != lpe::EventType::Camera) return "every patch (unlabelled bounce)";
            return "camera";
        case Subject::Ambient: return "ambient";
        case Subject::PointLight: {
            const std::string& name = scene.lights[event.index].name;
            return name.empty() ? "light #" + std::to_string(event.index) : name;
        }
        case Subject::Object: {
            const std::string& name = scene.objects[event.index].name;
            return name.empty() ? "object #" + std::to_string(event.index) + " (" + scene.labelOf(event.index) + ")" : name;
        }
    }
    return {};
}

// The recorded path as the LPE engine's Path, labelled as the automaton saw it.
lpe::Path toLpePath(const Scene& scene, const PathRecord& record) {
    lpe::Path path;
    for (std::size_t i = 0; i < record.size(); ++i) {
        const PathEvent& e = record[i];
        lpe::Event event{e.type, e.scatter, {}};
        if (e.subject == Subject::Ambient) event.label = kAmbientLabel;
        else if (e.subject == Subject::PointLight) event.label = scene.lights[e.index].name;
        else if (e.subject == Subject::Object) event.label = scene.labelOf(e.index);
        path.push_back(event);
    }
    return path;
}

std::string formatRgb(const Rgb& v) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.6f %.6f %.6f", v.r, v.g, v.b);
    return buffer;
}

void run(const ExplainCommand& command) {
    int x = 0, y = 0;
    char comma = 0, extra = 0;
    if (std::sscanf(command.pixel.c_str(), "%d%c%d%c", &x, &comma, &y, &extra) != 3 || comma != ',')
        throw CLI::RuntimeError("--pixel: expected X,Y such as 320,240, got \"" + command.pixel + "\"", kExitBadInput);
    const Scene scene = command.setup.loadScene();
    const AovSet aovs = command.setup.buildAovSet(scene);
    const RenderOptions options = command.setup.renderOptions();
    std::vector<LoggedContribution> log;
    try {
        log = Renderer(scene, aovs, options).explainPixel(x, y);
    } catch (const std::invalid_argument& e) {
        throw CLI::RuntimeError(e.what(), kExitBadInput);
    }

    const auto layers = aovs.layerNames();
    std::vector<Rgb> sums(layers.size(), Rgb{0.0f});
    std::printf("pixel %d,%d of %s (%s, %d spp): %zu contribution%s\n\n", x, y, command.setup.scenePath.c_str(),
                options.integrator.c_str(), options.samplesPerPixel, log.size(), log.size() == 1 ? "" : "s");
    for (std::size_t i = 0; i < log.size(); ++i) {
        const LoggedContribution& c = log[i];
        const lpe::Path path = toLpePath(scene, c.path);
        std::ostringstream touched, accepted;
        for (std::size_t e = 1; e < c.path.size(); ++e) touched << (e > 1 ? ", " : "") << subjectName(scene, c.path[e]);
        sums[0] += c.value;
        if (c.accepted == 0) {
            accepted << "rest";
            sums.back() += c.value;
        }
        for (std::size_t o = 0; o < aovs.expressions().size(); ++o) {
            if (((c.accepted >> o) & 1u) == 0) continue;
            accepted << (accepted.tellp() > 0 ? ", " : "") << aovs.expressions()[o].name;
            sums[1 + o] += c.value;
        }
        std::printf("%3zu  %-8s %s\n     touched: %s\n     rgb:     %s\n     aovs:    %s\n", i + 1,
                    lpe::toCompactString(path).c_str(), lpe::toTupleString(path).c_str(), touched.str().c_str(),
                    formatRgb(c.value).c_str(), accepted.str().c_str());
    }
    std::printf("\nsums\n");
    for (std::size_t l = 0; l < layers.size(); ++l) {
        const std::string expression = (l == 0 || l + 1 == layers.size()) ? "" : aovs.expressions()[l - 1].expression;
        std::printf("  %-10s %s  %s\n", layers[l].c_str(), formatRgb(sums[l]).c_str(), expression.c_str());
    }
}

}  // namespace

void addExplainCommand(CLI::App& app) {
    auto command = std::make_shared<ExplainCommand>();
    CLI::App* sub = app.add_subcommand("explain", "Print every contribution to one pixel with its light path and AOVs");
    command->setup.addOptions(*sub);
    sub->add_option("--pixel", command->pixel, "Pixel X,Y (0,0 is the top-left corner)")->required();
    sub->footer(
        "Each contribution is shown as a compact path (EDL), as event tuples with the labels the\n"
        "automaton saw (E RD'floor' L'key'), the objects and lights it touched, its RGB value and\n"
        "the AOVs whose expressions accept it; the sums per layer follow.\n\n"
        "Examples:\n"
        "  lightpath explain scenes/lecture-room.toml --pixel 320,240\n"
        "  lightpath explain scenes/mirror-sphere.toml --pixel 300,200 --lpe \"mirror=E<RS>+.*\"");
    sub->callback([command] { run(*command); });
}

}  // namespace lightpath
