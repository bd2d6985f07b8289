#pragma once
#include <filesystem>
#include <string>

namespace lightpath {

// The name a file is written under, beside `target`, before it is renamed to `target`:
// ".NAME.tmp-PID", hidden and unique to the process.
std::filesystem::path temporaryName(const std::filesystem::path& target);

// Writes `contents` under a temporary name beside `path` and renames it into place, so readers
// never see a half-written file. Throws std::runtime_error naming the file.
void writeTextFileAtomically(const std::filesystem::path& path, const std::string& contents);

// A JSON string literal for `text` (quotes, backslashes and control characters escaped).
std::string jsonString(const std::string& text);

}  // namespace lightpath
