// The image module, liblightpath-image.so: ImageCodec (io/image_codec.h) over OpenImageIO. It is
// loaded with dlopen only when an image is read or written (io/image_module.h), and exports
// nothing but its entry point.
#include <OpenImageIO/imageio.h>

#include "io/image_codec.h"

namespace lightpath {
namespace {

class OiioCodec final : public ImageCodec {
public:
    std::string write(const std::string& formatName, const std::string& file, const ImageFileSpec& spec,
                      const void* pixels) const override {
        const OIIO::TypeDesc format = spec.format == PixelFormat::Float32 ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8;
        OIIO::ImageSpec oiioSpec(spec.width, spec.height, static_cast<int>(spec.channelNames.size()), format);
        oiioSpec.channelnames = spec.channelNames;
        for (const auto& [key, value] : spec.textAttributes) oiioSpec.attribute(key, value);
        for (const auto& [key, value] : spec.intAttributes) oiioSpec.attribute(key, value);
        auto out = OIIO::ImageOutput::create(formatName);
        if (!out) return "cannot create a " + formatName + " writer (" + OIIO::geterror() + ")";
        if (!out->open(file, oiioSpec) || !out->write_image(format, pixels) || !out->close()) return out->geterror();
        return {};
    }

    std::string read(const std::string& file, ImageData& image) const override {
        auto in = OIIO::ImageInput::open(file);
        if (!in) return OIIO::geterror();
        const OIIO::ImageSpec& spec = in->spec();
        image.width = spec.width;
        image.height = spec.height;
        image.channelNames = spec.channelnames;
        image.pixels.resize(static_cast<std::size_t>(spec.width) * static_cast<std::size_t>(spec.height) *
                            static_cast<std::size_t>(spec.nchannels));
        if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.pixels.data())) return in->geterror();
        return {};
    }
};

}  // namespace
}  // namespace lightpath

extern "C" __attribute__((visibility("default"))) const lightpath::ImageCodec* lightpathImageCodec(int interfaceVersion) {
    static const lightpath::OiioCodec codec;
    return interfaceVersion == lightpath::kImageCodecInterfaceVersion ? &codec : nullptr;
}
