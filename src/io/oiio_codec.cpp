// The image module, liblightpath-image.so: ImageCodec (io/image_codec.h) over OpenImageIO. It is
// loaded with dlopen only when an image is read or written (io/image_module.h), and exports
// nothing but its entry point.
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include "io/image_codec.h"

namespace lightpath {
namespace {

class OiioCodec final : public ImageCodec {
public:
    std::string write(const std::string& formatName, const std::string& file, const ImageFileSpec& spec,
                      const void* pixels) const override {
        return writeThrough(formatName, file, spec, pixels, nullptr);
    }

    std::string encode(const std::string& formatName, const ImageFileSpec& spec, const void* pixels,
                       std::vector<unsigned char>& bytes) const override {
        bytes.clear();
        OIIO::Filesystem::IOVecOutput memory(bytes);
        // The name only tells the writer its format; with the proxy nothing is opened by name.
        return writeThrough(formatName, "memory." + formatName, spec, pixels, &memory);
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

private:
    static std::string writeThrough(const std::string& formatName, const std::string& file, const ImageFileSpec& spec,
                                    const void* pixels, OIIO::Filesystem::IOProxy* proxy) {
        const OIIO::TypeDesc format = spec.format == PixelFormat::Float32 ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8;
        OIIO::ImageSpec oiioSpec(spec.width, spec.height, static_cast<int>(spec.channelNames.size()), format);
        oiioSpec.channelnames = spec.channelNames;
        for (const auto& [key, value] : spec.textAttributes) oiioSpec.attribute(key, value);
        for (const auto& [key, value] : spec.intAttributes) oiioSpec.attribute(key, value);
        auto out = OIIO::ImageOutput::create(formatName);
        if (!out) return "cannot create a " + formatName + " writer (" + OIIO::geterror() + ")";
        if (proxy != nullptr && !(out->supports("ioproxy") && out->set_ioproxy(proxy)))
            return "OpenImageIO's " + formatName + " writer cannot write to memory";
        if (!out->open(file, oiioSpec) || !out->write_image(format, pixels) || !out->close()) return out->geterror();
        return {};
    }
};

}  // namespace
}  // namespace lightpath

extern "C" __attribute__((visibility("default"))) const lightpath::ImageCodec* lightpathImageCodec(int interfaceVersion) {
    static const lightpath::OiioCodec codec;
    return interfaceVersion == lightpath::kImageCodecInterfaceVersion ? &codec : nullptr;
}
