#pragma once
// An option the user gave that cannot be rendered: which option, and why. The command line prints
// what() (exit code 2, config/exit_codes.h); serve answers 400 naming the field, read from
// field(), never parsed out of a message.
#include <stdexcept>
#include <string>

namespace lightpath {

class ConfigError : public std::runtime_error {
public:
    ConfigError(std::string field, std::string message);

    // The option's name in its schema ("spp", "max-depth", an integrator's "patch-size"),
    // "lpe:NAME" for one AOV, "lpe" for the set, "scene" for the scene file, and "" for the render
    // as a whole (its memory).
    const std::string& field() const { return field_; }
    // Why, without the option: "Value 0 not in range 1 to 1048576".
    const std::string& message() const { return message_; }
    // what(): as the command line says it, the option spelt as its flag: "--spp: Value 0 not in
    // range 1 to 1048576", "--lpe NAME: ..."; the message alone for the scene (its errors name
    // their file and line) and the render as a whole.

private:
    std::string field_;
    std::string message_;
};

}  // namespace lightpath
