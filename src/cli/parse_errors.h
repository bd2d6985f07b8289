#pragma once
// How the command line reports its parser's errors: every error carries the `lightpath:` prefix
// and, where a word was misspelt, a did-you-mean (config/messages.h).
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace lightpath {

// A CLI11 check that the value is one of `names`, whose message says what was expected and
// suggests the nearest name (choiceMessage). CLI11 prefixes it with the option's name.
CLI::Validator oneOf(std::vector<std::string> names);

// The text main() prints for an argument parser error, including CLI11's own ("The following
// argument was not expected: --sp"), with the prefix and a suggestion from `app`'s options and
// subcommands (those of the subcommand that was being parsed).
std::string parseErrorMessage(const CLI::App& app, const CLI::ParseError& error);

}  // namespace lightpath
