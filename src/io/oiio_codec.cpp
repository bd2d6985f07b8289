// The image module, liblightpath-image.so: ImageCodec (io/image_codec.h) over OpenImageIO. It is
// loaded with dlopen only when an image is read or written (io/image_module.h), and exports
// nothing but its entry point.
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <OpenImageIO/texture.h>

#include <algorithm>

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

    TextureFileHandle* openTexture(const std::string& file, std::string& error) const override {
        OIIO::TextureSystem& system = textureSystem();
        OIIO::TextureSystem::TextureHandle* handle = system.get_texture_handle(OIIO::ustring(file));
        int exists = 0;
        if (handle == nullptr || !system.get_texture_info(handle, nullptr, 0, OIIO::ustring("exists"), OIIO::TypeInt, &exists) ||
            exists == 0 || !system.good(handle)) {
            error = system.geterror();
            if (error.empty()) error = "cannot open " + file;
            return nullptr;
        }
        return reinterpret_cast<TextureFileHandle*>(handle);
    }

    void lookupTexture(TextureFileHandle* texture, const TextureQuery& query, float rgb[3]) const override {
        OIIO::TextureSystem& system = textureSystem();
        // Each thread's own state, asked once per thread (pbrt and OSL do the same).
        thread_local OIIO::TextureSystem::Perthread* const perThread = system.get_perthread_info();
        OIIO::TextureOpt options;
        options.swrap = options.twrap = OIIO::TextureOpt::WrapPeriodic;
        if (!query.filtered) {
            options.mipmode = OIIO::TextureOpt::MipModeNoMIP;
            options.interpmode = OIIO::TextureOpt::InterpBilinear;
        }
        if (!system.texture(reinterpret_cast<OIIO::TextureSystem::TextureHandle*>(texture), perThread, options, query.s,
                            query.t, query.dsdx, query.dtdx, query.dsdy, query.dtdy, 3, rgb)) {
            rgb[0] = rgb[1] = rgb[2] = 0.0f;  // opened before the render: only a file changed on disk since
        }
    }

    void averageTexture(TextureFileHandle* texture, float rgb[3]) const override {
        float average[4] = {0.0f, 0.0f, 0.0f, 0.0f};
        OIIO::TextureSystem& system = textureSystem();
        auto* handle = reinterpret_cast<OIIO::TextureSystem::TextureHandle*>(texture);
        int channels = 0;
        system.get_texture_info(handle, nullptr, 0, OIIO::ustring("channels"), OIIO::TypeInt, &channels);
        system.get_texture_info(handle, nullptr, 0, OIIO::ustring("averagecolor"),
                                OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, std::max(1, std::min(channels, 4))), average);
        for (int c = 0; c < 3; ++c) rgb[c] = channels == 1 ? average[0] : average[c];
    }

private:
    // One TextureSystem for the process, shared (with its ImageCache), made on first use.
    static OIIO::TextureSystem& textureSystem() {
        static OIIO::TextureSystem* const system = [] {
            OIIO::TextureSystem* made = OIIO::TextureSystem::create(true);
            made->attribute("automip", 1);      // a plain PNG gets its MIP levels when first read
            made->attribute("autotile", 64);    // and is cached in tiles
            made->attribute("gray_to_rgb", 1);  // a grey image is grey, not red
            return made;
        }();
        return *system;
    }

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
