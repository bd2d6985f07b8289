#include "cli/parse_errors.h"

#include <algorithm>
#include <cctype>
#include <sstream>

#include "config/messages.h"

namespace lightpath {
namespace {

std::string lowered(std::string word) {
    std::transform(word.begin(), word.end(), word.begin(), [](unsigned char c) { return std::tolower(c); });
    return word;
}

// What users of other renderers type for lightpath's options (pbrt, Mitsuba, Cycles, POV-Ray,
// make): one table for every command, consulted before the spelling distance, which would
// answer --samples with --sampler. A synonym is offered only where its option exists.
struct Synonym {
    const char* typed;
    const char* option;
    const char* usage;  // how to say it, when the option takes another form ("" for the option alone)
};
constexpr Synonym kSynonyms[] = {
    {"--samples", "--spp", ""},
    {"--spp-count", "--spp", ""},
    {"--samples-per-pixel", "--spp", ""},
    {"--pixel-samples", "--spp", ""},
    {"-s", "--spp", ""},
    {"--width", "--resolution", "--resolution WIDTHxHEIGHT"},
    {"--height", "--resolution", "--resolution WIDTHxHEIGHT"},
    {"--size", "--resolution", "--resolution WIDTHxHEIGHT"},
    {"--res", "--resolution", "--resolution WIDTHxHEIGHT"},
    {"-w", "--resolution", "--resolution WIDTHxHEIGHT"},
    {"--outfile", "--output", ""},
    {"--out", "--output", ""},
    {"--threads-count", "--threads", ""},
    {"--nthreads", "--threads", ""},
    {"--jobs", "--threads", ""},
    {"-j", "--threads", ""},
    {"-t", "--threads", ""},
    {"--depth", "--max-depth", ""},
    {"--maxdepth", "--max-depth", ""},
    {"--bounces", "--max-depth", ""},
    {"--max-bounces", "--max-depth", ""},
    {"--method", "--integrator", ""},
    {"--aov", "--lpe", ""},
    {"--pass", "--lpe", ""},
    {"--passes", "--aovs", ""},
    {"--pixel-filter", "--filter", ""},
    {"--accelerator", "--accel", ""},
    {"--adaptive-threshold", "--target-error", ""},
    {"--noise-threshold", "--target-error", ""},
    {"--silent", "--quiet", ""},
    {"-q", "--quiet", ""},
};

// The option `word` stands for in `candidates`, by the table of synonyms.
std::optional<std::string> synonym(const std::string& word, const std::vector<std::string>& candidates) {
    for (const Synonym& s : kSynonyms) {
        if (lowered(word) != s.typed || std::find(candidates.begin(), candidates.end(), s.option) == candidates.end())
            continue;
        return *s.usage ? std::string(s.usage) : std::string(s.option);
    }
    return std::nullopt;
}

// The subcommand being parsed when the error struck: the deepest one that was given.
const CLI::App& deepest(const CLI::App& app) {
    for (const CLI::App* sub : app.get_subcommands())
        if (sub->parsed()) return deepest(*sub);
    return app;
}

// What a misspelt word could have been: the long options and subcommands of `app`.
std::vector<std::string> candidatesOf(const CLI::App& app) {
    std::vector<std::string> names;
    for (const CLI::Option* option : app.get_options()) {
        for (const std::string& name : option->get_lnames()) names.push_back("--" + name);
    }
    for (const CLI::App* sub : app.get_subcommands({})) names.push_back(sub->get_name());
    return names;
}

}  // namespace

CLI::Validator oneOf(std::vector<std::string> names) {
    std::string description = "{";
    for (const std::string& name : names) description += (description.size() > 1 ? "," : "") + name;
    description += "}";
    return CLI::Validator(
        [names](std::string& value) {
            return std::find(names.begin(), names.end(), value) != names.end() ? std::string()
                                                                                 : choiceMessage(value, names);
        },
        description);
}

std::string parseErrorMessage(const CLI::App& app, const CLI::ParseError& error) {
    std::string message = "lightpath: ";
    message += error.what();
    const CLI::App& where = deepest(app);
    // The words the parser could not place: those ExtrasError names ("The following argument(s)
    // was/were not expected: a b"), else what was left over ("lightpath rendr": a subcommand is
    // required, and rendr was not one).
    std::vector<std::string> words;
    if (dynamic_cast<const CLI::ExtrasError*>(&error)) {
        const std::string text = error.what();
        const std::size_t colon = text.find(": ");
        std::istringstream list(colon == std::string::npos ? "" : text.substr(colon + 2));
        for (std::string word; list >> word;) words.push_back(word);
    } else {
        words = where.remaining();
        if (!words.empty()) message += " (got " + words.front() + ")";
    }
    // A synonym of any word first (--samples means --spp), then the nearest spelling.
    const std::vector<std::string> candidates = candidatesOf(where);
    std::optional<std::string> suggestion;
    for (const std::string& word : words)
        if (!suggestion) suggestion = synonym(word.substr(0, word.find('=')), candidates);
    for (const std::string& word : words)
        if (!suggestion) suggestion = nearestName(word.substr(0, word.find('=')), candidates);
    if (suggestion) message += "; did you mean " + *suggestion + "?";
    return message + "\nRun with --help for more information.";
}

}  // namespace lightpath
