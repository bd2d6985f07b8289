#include "io/image_reader.h"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/exr_file.h"
#include "io/exr_layers.h"

namespace lightpath {
Film readFilm(const std::filesystem::path& path) {
    ImageData image;
    const std::string error = readExrFile(path, image);
    if (!error.empty()) throw std::runtime_error(path.string() + ": cannot read image (" + error + ")");
    // The beauty first, then the other layers in the file's (alphabetical) order, each R, G, B.
    std::vector<std::string> names;
    for (const std::string& channel : image.channelNames) {
        const std::string layer = exrLayerOf(channel);
        if (std::find(names.begin(), names.end(), layer) == names.end())
            names.insert(layer == kBeautyLayer ? names.begin() : names.end(), layer);
    }
    const auto refuse = [&] {
        throw std::runtime_error(path.string() + ": expected R, G, B channels in every layer (as writeFilm writes)");
    };
    if (image.channelNames.size() != kRgbChannels.size() * names.size()) refuse();
    std::vector<std::array<std::size_t, 3>> sources(names.size());
    for (std::size_t l = 0; l < names.size(); ++l)
        for (std::size_t c = 0; c < kRgbChannels.size(); ++c) {
            const auto found = std::find(image.channelNames.begin(), image.channelNames.end(),
                                         exrChannelName(names[l], kRgbChannels[c]));
            if (found == image.channelNames.end()) refuse();
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
