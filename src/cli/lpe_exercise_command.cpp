// `lightpath lpe exercise`: questions whose answer is a light path expression, judged by the LPE
// engine. A student's expression is right when it accepts exactly the paths the answer accepts
// (language equivalence decided on the automata, lpe/analysis.h), however it is written; when it
// is not, the shortest path only one of them accepts is printed, and one render of the scene shows
// what the paths only one of them accepts contribute.
#include <toml++/toml.h>

#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "config/exit_codes.h"
#include "cli/lpe_command.h"
#include "config/render_config.h"
#include "film/aov_set.h"
#include "io/image_writer.h"
#include "lpe/analysis.h"
#include "lpe/error.h"
#include "lpe/path_string.h"
#include "render/renderer.h"

namespace lightpath {
namespace {

struct Exercise {
    std::string id;
    std::string question;
    std::string scene;
    std::string answer;
    std::string universe = "E.*L";
    std::string integrator = "whitted";
    std::vector<std::string> hints;
};

struct ExerciseOptions {
    std::string file = "lectures/exercises.toml";
    std::string question;  // one question's id; empty: all, in order
    std::string answer;    // the student's expression, for scripts; empty: read from stdin
    std::string output = "out/exercise";
    std::string resolution = "80x60";
    int samplesPerPixel = 4;
    bool noRender = false;
};

[[noreturn]] void badInput(const std::string& message) { throw CLI::RuntimeError(message, kExitBadInput); }

std::string where(const std::string& file, const toml::node& node) {
    return file + ":" + std::to_string(node.source().begin.line);
}

std::string requiredString(const std::string& file, const toml::table& table, const char* key) {
    const toml::node* node = table.get(key);
    if (node == nullptr) badInput(where(file, table) + ": exercise lacks \"" + key + "\"");
    const auto* value = node->as_string();
    if (value == nullptr || value->get().empty())
        badInput(where(file, *node) + ": \"" + key + "\": expected a non-empty string");
    return value->get();
}

std::vector<Exercise> loadExercises(const std::string& file) {
    if (!std::ifstream(file)) badInput("cannot open exercise file " + file);
    toml::table document;
    try {
        document = toml::parse_file(file);
    } catch (const toml::parse_error& e) {
        badInput(file + ":" + std::to_string(e.source().begin.line) + ": " + std::string(e.description()));
    }
    const toml::array* list = document["exercise"].as_array();
    if (list == nullptr || list->empty()) badInput(file + ": expected [[exercise]] tables");
    std::vector<Exercise> exercises;
    for (const toml::node& node : *list) {
        const toml::table& table = *node.as_table();
        Exercise e;
        e.id = requiredString(file, table, "id");
        e.question = requiredString(file, table, "question");
        e.scene = requiredString(file, table, "scene");
        e.answer = requiredString(file, table, "answer");
        if (table.contains("universe")) e.universe = requiredString(file, table, "universe");
        if (table.contains("integrator")) e.integrator = requiredString(file, table, "integrator");
        if (const toml::array* hints = table["hints"].as_array()) {
            for (const toml::node& hint : *hints) {
                if (!hint.is_string()) badInput(where(file, hint) + ": \"hints\": expected strings");
                e.hints.push_back(*hint.value<std::string>());
            }
        }
        for (const Exercise& other : exercises)
            if (other.id == e.id) badInput(where(file, table) + ": exercise id \"" + e.id + "\" is used twice");
        exercises.push_back(std::move(e));
    }
    return exercises;
}

// Which paths of the universe only one side accepts: [0] only the student's, [1] only the answer's.
struct Verdict {
    std::optional<lpe::Path> onlyYours, onlyAnswer;
    bool right() const { return !onlyYours && !onlyAnswer; }
};

Verdict judge(const Exercise& exercise, const std::string& yours) {
    const lpe::Containment c =
        lpe::compareLanguages({{"yours", yours}, {"answer", exercise.answer}}, exercise.universe);
    return {c.onlyIn[0][1], c.onlyIn[1][0]};
}

double meanOf(const std::vector<Rgb>& layer) {
    double sum = 0.0;
    for (const Rgb& p : layer) sum += (double(p.r) + double(p.g) + double(p.b)) / 3.0;
    return layer.empty() ? 0.0 : sum / double(layer.size());
}

// A difference of float sums where the two sides carry the same light is rounding, not light:
// below the relative 1e-5 within which the tests hold the AOVs to sum to the beauty, it is zero.
Rgb withoutRounding(Rgb difference, Rgb beauty) {
    for (int c = 0; c < 3; ++c)
        if (difference[c] <= 1e-5f * beauty[c]) difference[c] = 0.0f;
    return difference;
}

// One render with the two expressions as overlapping AOVs. What no AOV accepts is `rest`, so the
// union of the two is beauty - rest, and what only yours accepts is beauty - rest - answer (and
// likewise the other way): exact, with no expression for a difference of languages needed.
void renderDifference(const Exercise& exercise, const std::string& yours, const ExerciseOptions& options) {
    RenderConfig config;
    config.scenePath = exercise.scene;
    config.integrator = exercise.integrator;
    config.resolution = options.resolution;
    config.samplesPerPixel = options.samplesPerPixel;
    config.quiet = true;
    const Scene scene = config.loadScene();
    const AovSet aovs({{"yours", yours}, {"answer", exercise.answer}});
    const RenderResult result = Renderer(scene, aovs, config.renderOptions()).render();
    const Film& film = result.film;
    // Layers: beauty, yours, answer, rest (AovSet::layerNames).
    Film difference(film.width(), film.height(), {"beauty", "yours-only", "answer-only"});
    for (int y = 0; y < film.height(); ++y)
        for (int x = 0; x < film.width(); ++x) {
            const Rgb beauty = film.at(0, x, y), both = beauty - film.at(3, x, y);
            difference.at(0, x, y) = beauty;
            difference.at(1, x, y) = withoutRounding(both - film.at(2, x, y), beauty);
            difference.at(2, x, y) = withoutRounding(both - film.at(1, x, y), beauty);
        }
    const std::string output = options.output + "-" + exercise.id + ".png";
    std::printf("in %s (%s, %s, %d spp): yours-only mean %.4g, answer-only mean %.4g (beauty %.4g)\n",
                exercise.scene.c_str(), exercise.integrator.c_str(), options.resolution.c_str(),
                options.samplesPerPixel, meanOf(difference.layer(1)), meanOf(difference.layer(2)),
                meanOf(difference.layer(0)));
    try {
        for (const auto& file : writeFilm(difference, output, {{"lightpath:exercise", exercise.id}}))
            std::cout << "wrote " << file.string() << '\n';
    } catch (const ImageWriteError& e) {
        throw CLI::RuntimeError(e.what(), kExitFailure);
    }
}

// Prints the verdict; true when right.
bool report(const Exercise& exercise, const std::string& yours, const ExerciseOptions& options) {
    const Verdict verdict = judge(exercise, yours);
    if (verdict.right()) {
        std::cout << "right: " << yours << " accepts the same paths of " << exercise.universe << " as the answer "
                  << exercise.answer << '\n';
        return true;
    }
    std::cout << "not yet: " << yours << " and the answer differ on paths of " << exercise.universe << '\n';
    if (verdict.onlyYours)
        std::cout << "  " << lpe::toDisplayString(*verdict.onlyYours)
                  << " is accepted by yours, not by the answer (yours accepts too much)\n";
    if (verdict.onlyAnswer)
        std::cout << "  " << lpe::toDisplayString(*verdict.onlyAnswer)
                  << " is accepted by the answer, not by yours (yours misses it)\n";
    if (!options.noRender) renderDifference(exercise, yours, options);
    return false;
}

const Exercise& findExercise(const std::vector<Exercise>& exercises, const ExerciseOptions& options) {
    std::string ids;
    for (const Exercise& e : exercises) {
        if (e.id == options.question) return e;
        ids += (ids.empty() ? "" : ", ") + e.id;
    }
    badInput("--question: no exercise \"" + options.question + "\" in " + options.file + " (there are: " + ids + ")");
}

// Asks until the student is right, gives up (an empty line shows the next hint, "skip" moves on)
// or input ends. True when right.
bool ask(const Exercise& exercise, const ExerciseOptions& options, bool& ended) {
    std::cout << "\n[" << exercise.id << "] " << exercise.question << "\n  (scene " << exercise.scene
              << "; Enter for a hint, \"skip\" for the next question)\n";
    std::size_t hintsShown = 0;
    std::string line;
    while (std::cout << "> " << std::flush && std::getline(std::cin, line)) {
        if (line == "skip") {
            std::cout << "the answer: " << exercise.answer << '\n';
            return false;
        }
        if (line.empty()) {
            std::cout << (hintsShown < exercise.hints.size() ? "hint: " + exercise.hints[hintsShown++]
                                                             : "no more hints; \"skip\" shows the answer")
                      << '\n';
            continue;
        }
        try {
            if (report(exercise, line, options)) return true;
        } catch (const lpe::SyntaxError& e) {
            std::cout << e.what() << '\n';
        } catch (const lpe::LimitError& e) {
            std::cout << e.what() << '\n';
        }
    }
    ended = true;
    return false;
}

void run(const ExerciseOptions& options) {
    const std::vector<Exercise> exercises = loadExercises(options.file);
    for (const Exercise& e : exercises) {
        try {
            judge(e, e.answer);  // the file's own answers must be expressions
        } catch (const lpe::SyntaxError& error) {
            badInput(options.file + ": exercise " + e.id + ": answer: " + error.what());
        }
    }
    if (!options.answer.empty()) {
        if (options.question.empty()) badInput("--answer needs --question ID: which question it answers");
        try {
            if (!report(findExercise(exercises, options), options.answer, options))
                throw CLI::RuntimeError("not the answer yet", kExitFailure);
        } catch (const lpe::SyntaxError& e) {
            badInput(std::string("--answer: ") + e.what());
        } catch (const lpe::LimitError& e) {
            badInput(std::string("--answer: ") + e.what());
        }
        return;
    }
    std::vector<const Exercise*> chosen;
    if (options.question.empty()) {
        for (const Exercise& e : exercises) chosen.push_back(&e);
    } else {
        chosen.push_back(&findExercise(exercises, options));
    }
    std::size_t right = 0;
    bool ended = false;
    for (const Exercise* e : chosen) {
        if (ask(*e, options, ended)) ++right;
        if (ended) break;
    }
    std::cout << "\n" << right << " of " << chosen.size() << " right\n";
}

}  // namespace

void addLpeExerciseCommand(CLI::App& lpe) {
    auto options = std::make_shared<ExerciseOptions>();
    CLI::App* command = lpe.add_subcommand("exercise", "Questions answered with a light path expression, checked by the engine");
    command->add_option("file", options->file, "the exercises (TOML, [[exercise]] tables)")
        ->capture_default_str();
    command->add_option("--question", options->question, "ask only this exercise (its id)");
    command->add_option("--answer", options->answer, "judge this expression for --question and exit: 0 right, 1 wrong");
    command->add_option("-o,--output", options->output,
                        "where a wrong answer's difference image goes: PREFIX-ID.png (+ .yours-only, .answer-only)")
        ->capture_default_str();
    command->add_option("--resolution", options->resolution, "of the difference render")->capture_default_str();
    command->add_option("--spp", options->samplesPerPixel, "samples per pixel of the difference render")
        ->capture_default_str()
        ->check(CLI::Range(1, 1024));
    command->add_flag("--no-render", options->noRender, "print the verdict only");
    command->footer(
        "Right means equivalent: your expression accepts exactly the paths (of the exercise's universe,\n"
        "E.*L unless it says) that the answer accepts, however it is written. Otherwise the shortest\n"
        "path only one of them accepts is printed, and the scene is rendered once with both as AOVs:\n"
        "PREFIX-ID.yours-only.png is the light only your expression accepts, PREFIX-ID.answer-only.png\n"
        "the light only the answer accepts, each with its mean. Without --answer the questions are\n"
        "asked on standard input, with hints.\n\n"
        "Examples:\n"
        "  lightpath lpe exercise                                   every question of lectures/exercises.toml\n"
        "  lightpath lpe exercise --question mirror-only --answer 'ES+L'");
    command->callback([options] { run(*options); });
}

}  // namespace lightpath
