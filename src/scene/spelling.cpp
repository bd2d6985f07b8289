#include "scene/spelling.h"

#include <algorithm>
#include <numeric>

namespace lightpath {

std::size_t editDistance(std::string_view a, std::string_view b) {
    // One row of the dynamic-programming table at a time: row[j] is the distance between the
    // prefix of `a` read so far and the first j characters of `b`.
    std::vector<std::size_t> row(b.size() + 1);
    std::iota(row.begin(), row.end(), std::size_t{0});
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t substitution = diagonal + (a[i - 1] == b[j - 1] ? 0 : 1);
            diagonal = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, substitution});
        }
    }
    return row[b.size()];
}

std::optional<std::string> closestMatch(std::string_view word,
                                        const std::vector<std::string>& candidates) {
    constexpr std::size_t maxEdits = 2;
    std::optional<std::string> best;
    std::size_t bestDistance = std::min(maxEdits + 1, word.size());
    for (const std::string& candidate : candidates) {
        const std::size_t distance = editDistance(word, candidate);
        if (distance < bestDistance) {
            best = candidate;
            bestDistance = distance;
        }
    }
    return best;
}

namespace {

std::string joinNames(const std::vector<std::string>& names) {
    if (names.empty()) return "none";
    std::string joined = names.front();
    for (std::size_t i = 1; i < names.size(); ++i) joined += ", " + names[i];
    return joined;
}

}  // namespace

std::string unknownNameMessage(std::string_view kind, std::string_view word,
                               const std::vector<std::string>& known, ListKnown list) {
    std::string message = "unknown " + std::string(kind) + " \"" + std::string(word) + "\"";
    const std::optional<std::string> suggestion = closestMatch(word, known);
    if (suggestion) message += "; did you mean \"" + *suggestion + "\"?";
    if (!suggestion || list == ListKnown::always) message += " (known: " + joinNames(known) + ")";
    return message;
}

}  // namespace lightpath
