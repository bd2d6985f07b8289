#pragma once
// How a film's layers are named as EXR channels, for writeFilm and readFilm alike: the beauty as
// R, G, B, every other layer as <layer>.R, <layer>.G, <layer>.B.
#include <array>
#include <string>

namespace lightpath {

inline constexpr const char* kBeautyLayer = "beauty";
inline constexpr std::array<const char*, 3> kRgbChannels{"R", "G", "B"};

inline std::string exrChannelName(const std::string& layer, const char* component) {
    return layer == kBeautyLayer ? std::string(component) : layer + "." + component;
}

// The layer a channel belongs to: "R" is the beauty's, "caustic.R" the layer caustic's.
inline std::string exrLayerOf(const std::string& channel) {
    const std::size_t dot = channel.rfind('.');
    return dot == std::string::npos ? std::string(kBeautyLayer) : channel.substr(0, dot);
}

}  // namespace lightpath
