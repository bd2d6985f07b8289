#pragma once
#include <filesystem>
#include <optional>
#include <string>

namespace lightpath {

// The name a file is written under, beside `target`, before it is renamed to `target`:
// ".NAME.tmp-PID", hidden and unique to the process.
std::filesystem::path temporaryName(const std::filesystem::path& target);

// Writes `contents` under a temporary name beside `path` and renames it into place, so readers
// never see a half-written file. Throws std::runtime_error naming the file.
void writeTextFileAtomically(const std::filesystem::path& path, const std::string& contents);

// Why `target` could not be written, checked before the work that produces it (issue #28):
// "<target>: <reason>", or nothing when it can be. It can be when the folder exists and a file
// can be created in it (tried with temporaryName(target), removed at once), or when the folder is
// missing but can be created (writers create it) below its nearest existing folder; it cannot
// when a folder on the way is a file, the folder refuses new files (permission, a read-only file
// system), or `target` is itself a folder. An existing file of that name is never touched.
std::optional<std::string> whyCannotWrite(const std::filesystem::path& target);

// A JSON string literal for `text` (quotes, backslashes and control characters escaped).
std::string jsonString(const std::string& text);

}  // namespace lightpath
