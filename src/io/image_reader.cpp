#include "io/image_reader.h"

#include <stdexcept>

#include "io/image_module.h"

namespace lightpath {

Film readFilm(const std::filesystem::path& path) {
    ImageData image;
    const std::string error = imageCodec().read(path.string(), image);
    if (!error.empty()) throw std::runtime_error(path.string() + ": cannot read image (" + error + ")");
    const std::size_t channels = image.channelNames.size();
    if (channels == 0 || channels % 3 != 0) throw std::runtime_error(path.string() + ": expected RGB layers");
    std::vector<std::string> names;
    for (std::size_t c = 0; c < channels; c += 3) {
        const std::string& channel = image.channelNames[c];
        names.push_back(channel == "R" ? "beauty" : channel.substr(0, channel.rfind('.')));
    }
    Film film(image.width, image.height, names);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            for (std::size_t l = 0; l < names.size(); ++l) {
                const std::size_t base = (static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) +
                                          static_cast<std::size_t>(x)) * channels + 3 * l;
                film.at(l, x, y) = {image.pixels[base], image.pixels[base + 1], image.pixels[base + 2]};
            }
    return film;
}

}  // namespace lightpath
