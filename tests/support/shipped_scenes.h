#pragma once
// Every scene file under scenes/, sorted: the suites that promise something of every shipped scene.
#include <algorithm>
#include <filesystem>
#include <vector>

namespace lightpath::test {

inline std::vector<std::filesystem::path> shippedScenes() {
    std::vector<std::filesystem::path> scenes;
    for (const auto& entry : std::filesystem::directory_iterator(LIGHTPATH_SOURCE_DIR "/scenes"))
        if (entry.path().extension() == ".toml") scenes.push_back(entry.path());
    std::sort(scenes.begin(), scenes.end());
    return scenes;
}

}  // namespace lightpath::test
