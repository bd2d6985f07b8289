#include "io/image_reader.h"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/exr_file.h"

namespace lightpath {
namespace {

constexpr const char* kBeautyLayer = "beauty";

// The layer a channel belongs to: "R" is the beauty's, "caustic.R" the layer caustic's.
std::string layerOf(const std::string& channel) {
    const std::size_t dot = channel.rfind('.');
    return dot == std::string::npos ? kBeautyLayer : channel.substr(0, dot);
}

}  // namespace

Film readFilm(const std::filesystem::path& path) {
    ImageData image;
    const std::string error = readExrFile(path, image);
    if (!error.empty()) throw std::runtime_error(path.string() + ": cannot read image (" + error + ")");
    // The beauty first, then the other layers in the file's (alphabetical) order, each R, G, B.
    std::vector<std::string> names;
    for (const std::string& channel : image.channelNames) {
        const std::string layer = layerOf(channel);
        if (std::find(names.begin(), names.end(), layer) == names.end())
            names.insert(layer == kBeautyLayer ? names.begin() : names.end(), layer);
    }
    std::vector<std::array<std::size_t, 3>> sources(names.size());
    for (std::size_t l = 0; l < names.size(); ++l)
        for (std::size_t c = 0; c < 3; ++c) {
            const char* component = c == 0 ? "R" : c == 1 ? "G" : "B";
            const std::string wanted = names[l] == kBeautyLayer ? component : names[l] + "." + component;
            const auto found = std::find(image.channelNames.begin(), image.channelNames.end(), wanted);
            if (found == image.channelNames.end() || image.channelNames.size() != 3 * names.size())
                throw std::runtime_error(path.string() + ": expected R, G, B channels in every layer (as writeFilm writes)");
            sources[l][c] = static_cast<std::size_t>(found - image.channelNames.begin());
        }
    const std::size_t channels = image.channelNames.size();
    Film film(image.width, image.height, names);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const std::size_t base = (static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) +
                                      static_cast<std::size_t>(x)) * channels;
            for (std::size_t l = 0; l < names.size(); ++l)
                film.at(l, x, y) = {image.pixels[base + sources[l][0]], image.pixels[base + sources[l][1]],
                                    image.pixels[base + sources[l][2]]};
        }
    return film;
}

}  // namespace lightpath
