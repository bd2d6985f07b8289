#include "io/image_reader.h"

#include <OpenImageIO/imageio.h>

#include <stdexcept>

namespace lightpath {

Film readFilm(const std::filesystem::path& path) {
    auto in = OIIO::ImageInput::open(path.string());
    if (!in) throw std::runtime_error(path.string() + ": cannot read image (" + OIIO::geterror() + ")");
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.nchannels % 3 != 0) throw std::runtime_error(path.string() + ": expected RGB layers");
    std::vector<std::string> names;
    for (int c = 0; c < spec.nchannels; c += 3) {
        const std::string& channel = spec.channelnames[static_cast<std::size_t>(c)];
        names.push_back(channel == "R" ? "beauty" : channel.substr(0, channel.rfind('.')));
    }
    Film film(spec.width, spec.height, names);
    std::vector<float> pixels(static_cast<std::size_t>(spec.width) * spec.height * spec.nchannels);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data()))
        throw std::runtime_error(path.string() + ": cannot read image (" + in->geterror() + ")");
    for (int y = 0; y < spec.height; ++y)
        for (int x = 0; x < spec.width; ++x)
            for (std::size_t l = 0; l < names.size(); ++l) {
                const std::size_t base = ((static_cast<std::size_t>(y) * spec.width + x) * spec.nchannels) + 3 * l;
                film.at(l, x, y) = {pixels[base], pixels[base + 1], pixels[base + 2]};
            }
    return film;
}

}  // namespace lightpath
