#pragma once
// How the command line talks back: every error carries the `lightpath:` prefix and, where a word
// was misspelt, a did-you-mean; warnings go to stderr unless --quiet.
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace lightpath {

// A CLI11 check that the value is one of `names`, whose message says what was expected and
// suggests the nearest name (case ignored): "Whitted is not one of raycast, whitted, path; did
// you mean whitted?". CLI11 prefixes it with the option's name.
CLI::Validator oneOf(std::vector<std::string> names);

// "unknown X; did you mean Y?" without the quotes of scene messages, for command-line words.
std::string choiceMessage(const std::string& word, const std::vector<std::string>& names);

// The text main() prints for an argument parser error, including CLI11's own ("The following
// argument was not expected: --sp"), with the prefix and a suggestion from `app`'s options and
// subcommands (those of the subcommand that was being parsed).
std::string parseErrorMessage(const CLI::App& app, const CLI::ParseError& error);

// What the command is doing, for main's last resort when memory runs out anyway (std::bad_alloc):
// "out of memory while <activity>". Set before each step that allocates much ("rendering a
// 640x480 image of 7 layers (...)"); main sets "running lightpath COMMAND" first.
void setActivity(std::string activity);
const std::string& activity();

// The version and the build's options, for `lightpath --version`.
std::string versionText();

// Warnings: printed to stderr as "warning: ...", unless silenced by --quiet. Errors are never
// silenced and do not come here.
class Warnings {
public:
    explicit Warnings(bool quiet) : quiet_(quiet) {}
    void operator()(const std::string& message) const;

private:
    bool quiet_;
};

}  // namespace lightpath
