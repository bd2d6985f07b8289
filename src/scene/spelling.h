#pragma once
// "Did you mean ...?" for misspelt keys and names in scene files: students' typos deserve a
// suggestion, not just a refusal.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lightpath {

// Levenshtein distance: the fewest single-character insertions, deletions and substitutions
// that turn `a` into `b`.
std::size_t editDistance(std::string_view a, std::string_view b);

// The candidate nearest to `word` when it is close enough to be a likely typo (at most two edits,
// and fewer edits than `word` has characters), else nothing. Ties go to the earlier candidate.
std::optional<std::string> closestMatch(std::string_view word,
                                        const std::vector<std::string>& candidates);

// Whether an "unknown ..." message lists every known name or only when it has no suggestion.
enum class ListKnown { always, withoutSuggestion };

// `unknown key "raduis"; did you mean "radius"?` or `unknown material "x" (known: grey, red)`.
std::string unknownNameMessage(std::string_view kind, std::string_view word,
                               const std::vector<std::string>& known, ListKnown list);

}  // namespace lightpath
