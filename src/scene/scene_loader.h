#pragma once
#include <filesystem>
#include <stdexcept>
#include <string>

#include "scene/scene.h"

namespace lightpath {

// A scene file that cannot be used. what() reads "FILE:LINE:COLUMN: KEY: what was expected",
// e.g. "scenes/a.toml:12:10: spheres[2].radius: expected a positive number, got -1".
class SceneError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Reads a TOML scene (format: scenes/README.md). Throws SceneError; never returns a partial scene.
Scene loadScene(const std::filesystem::path& path);

}  // namespace lightpath
