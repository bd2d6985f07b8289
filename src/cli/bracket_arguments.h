#pragma once
// CLI11 2.1.2 reads an argument that starts with '[' and ends with ']' as a list ("[a,b]") for
// every vector option and positional (Option::_add_result), so `lpe match '[SG]' RS` saw "SG".
// Such arguments are marked before parsing, so CLI11 does not take them for lists, and every
// option unmarks its values again before its validators and callbacks see them.
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace lightpath {

// The arguments with each bracketed value ("[SG]", or "--lpe=[SG]"'s value) marked.
std::vector<std::string> markBracketedArguments(int argc, const char* const* argv);

// Has every option of `app` and its subcommands, present and added so far, unmark its values.
void unmarkBracketedValues(CLI::App& app);

// `text` without marks: for messages that quote an argument (a parse error names a value).
std::string withoutMarks(std::string text);

}  // namespace lightpath
