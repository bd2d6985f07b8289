#pragma once
// How lightpath talks back, below the command line: a did-you-mean for a misspelt word, warnings
// on stderr unless --quiet, the activity named when memory runs out, the version text.
#include <optional>
#include <string>
#include <vector>

namespace lightpath {

// "unknown X; did you mean Y?" without the quotes of scene messages, for command-line words:
// "Whitted is not one of raycast, whitted, path; did you mean whitted?".
std::string choiceMessage(const std::string& word, const std::vector<std::string>& names);

// The nearest of `names` to `word`, case ignored; nothing when none is a likely typo.
std::optional<std::string> nearestName(const std::string& word, const std::vector<std::string>& names);

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
