#pragma once
// The command line's side of a render's configuration: one flag per render option
// (config/render_options.h) and per parameter of every registered integrator, with their --help
// text, read into a RenderConfig and checked by its one validate(). A new option or integrator
// parameter needs nothing here.
#include <CLI/CLI.hpp>

#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "config/render_config.h"

namespace lightpath {

class RenderFlags {
public:
    // Adds the flags to `command`. The object must outlive the parse (the flags write into it).
    void addOptions(CLI::App& command);

    // After the parse: the given flags set into config() and validated (RenderConfig::validate).
    // Throws ConfigError.
    const RenderConfig& apply();
    const RenderConfig& config() const { return config_; }

private:
    RenderConfig config_;
    std::map<std::string, std::string, std::less<>> texts_;  // by option name: the value typed
    std::map<std::string, bool, std::less<>> switches_;      // Boolean options: given or not
    std::vector<std::string> lpes_;
    std::vector<std::pair<std::string, CLI::Option*>> options_;
};

// Runs `action`, reporting a ConfigError as every command-line error is reported: its message
// after "lightpath: ", exit code 2.
void reportingConfigErrors(const std::function<void()>& action);

}  // namespace lightpath
