#pragma once
#include <filesystem>
#include <string>

namespace lightpath {

// The scenes/ folder of lightpath: beside the working directory when run from a checkout, else
// the source tree this binary was built from.
inline std::filesystem::path shippedScenesDirectory() {
    if (std::filesystem::is_directory("scenes")) return "scenes";
    return std::filesystem::path(LIGHTPATH_SOURCE_DIR) / "scenes";
}

inline std::filesystem::path shippedScene(const std::string& name) { return shippedScenesDirectory() / name; }

}  // namespace lightpath
