#include "cli/bracket_arguments.h"

#include <algorithm>

namespace lightpath {
namespace {

// ASCII unit separator: no shell user types it, and it is not '[' so CLI11 sees no list.
constexpr char kMark = '\x1f';

bool bracketed(const std::string& value) {
    return value.size() >= 2 && value.front() == '[' && value.back() == ']';
}

}  // namespace

std::vector<std::string> markBracketedArguments(int argc, const char* const* argv) {
    std::vector<std::string> arguments(argv, argv + argc);
    for (std::size_t i = 1; i < arguments.size(); ++i) {
        std::string& argument = arguments[i];
        if (bracketed(argument)) {
            argument.insert(argument.begin(), kMark);
            continue;
        }
        // --name=[...]: CLI11 adds the part after '=' as the value.
        const std::size_t equals = argument.find('=');
        if (argument.rfind("--", 0) == 0 && equals != std::string::npos && bracketed(argument.substr(equals + 1))) {
            argument.insert(argument.begin() + static_cast<std::ptrdiff_t>(equals + 1), kMark);
        }
    }
    return arguments;
}

void unmarkBracketedValues(CLI::App& app) {
    for (CLI::Option* option : app.get_options()) {
        if (option->get_items_expected_max() == 0) continue;  // a flag takes no value
        option->transform([](std::string value) { return withoutMarks(std::move(value)); });
    }
    for (CLI::App* subcommand : app.get_subcommands([](CLI::App*) { return true; })) unmarkBracketedValues(*subcommand);
}

std::string withoutMarks(std::string text) {
    text.erase(std::remove(text.begin(), text.end(), kMark), text.end());
    return text;
}

}  // namespace lightpath
