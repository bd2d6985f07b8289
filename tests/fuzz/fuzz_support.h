#pragma once
// What the fuzz targets share: how an input is split into lines and sections, and how a broken
// invariant is reported. An expected error (a refused input) is caught by the target and ignored;
// anything else must end the process loudly, so that libFuzzer keeps the input as a crash.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace fuzz {

// Says which invariant broke and aborts: libFuzzer (and the replay runner) report the input.
[[noreturn]] inline void broken(const std::string& what) {
    std::fprintf(stderr, "fuzz invariant broken: %s\n", what.c_str());
    std::fflush(stderr);
    std::abort();
}

inline std::string_view asText(const std::uint8_t* data, std::size_t size) {
    return {reinterpret_cast<const char*>(data), size};
}

// Lines without their '\n' (and a '\r' before it); a last line without '\n' counts too.
inline std::vector<std::string_view> lines(std::string_view text) {
    std::vector<std::string_view> result;
    while (!text.empty()) {
        const std::size_t end = text.find('\n');
        std::string_view line = text.substr(0, end);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        result.push_back(line);
        if (end == std::string_view::npos) break;
        text.remove_prefix(end + 1);
    }
    return result;
}

// The text before and after the first line that is exactly `separator` (the second part empty
// when there is no such line).
inline std::pair<std::string, std::string> splitAtLine(std::string_view text, std::string_view separator) {
    std::size_t lineStart = 0;
    while (lineStart <= text.size()) {
        const std::size_t end = text.find('\n', lineStart);
        const std::size_t lineEnd = end == std::string_view::npos ? text.size() : end;
        std::string_view line = text.substr(lineStart, lineEnd - lineStart);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        if (line == separator) {
            const std::size_t rest = end == std::string_view::npos ? text.size() : end + 1;
            return {std::string(text.substr(0, lineStart)), std::string(text.substr(rest))};
        }
        if (end == std::string_view::npos) break;
        lineStart = end + 1;
    }
    return {std::string(text), std::string()};
}

}  // namespace fuzz
