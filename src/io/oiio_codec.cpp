// The image module, liblightpath-image.so: ImageCodec (io/image_codec.h) over OpenImageIO's
// TextureSystem. It is loaded with dlopen only when a scene has a texture (io/image_module.h), and
// exports nothing but its entry point.
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imagecache.h>
#include <OpenImageIO/imageio.h>
#include <OpenImageIO/strutil.h>
#include <OpenImageIO/texture.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <memory>
#include <mutex>
#include <string_view>

#include "io/image_codec.h"

namespace lightpath {
namespace {

// A decoded image the ImageCache reads from memory through MemoryInput (its custom ImageInput:
// OpenImageIO 2.4's TextureSystem applies no colour transform and cannot be handed an ImageBuf,
// so linearised texels reach it as an image of their own, and the cache tiles and MIP-maps it).
struct MemoryImage {
    int width = 0, height = 0, channels = 0;
    std::vector<std::string> channelNames;
    std::vector<float> pixels;

    // Registers `image` under `name` with the shared ImageCache (the TextureSystem's), once: a
    // name already there is the same image (names say the file or the bytes' hash, and the
    // colour space).
    static void add(const std::string& name, std::shared_ptr<const MemoryImage> image);
    static std::shared_ptr<const MemoryImage> find(const std::string& name) {
        const std::lock_guard<std::mutex> lock(mutex());
        const auto found = images().find(name);
        return found == images().end() ? nullptr : found->second;
    }

private:
    static std::mutex& mutex() {
        static std::mutex m;
        return m;
    }
    static std::map<std::string, std::shared_ptr<const MemoryImage>>& images() {
        static std::map<std::string, std::shared_ptr<const MemoryImage>> registered;
        return registered;
    }
};

class MemoryInput final : public OIIO::ImageInput {
public:
    const char* format_name() const override { return "lightpath-memory"; }
    bool open(const std::string& name, OIIO::ImageSpec& newspec) override {
        image_ = MemoryImage::find(name);
        if (!image_) {
            errorfmt("{}: no such image in memory", name);
            return false;
        }
        m_spec = OIIO::ImageSpec(image_->width, image_->height, image_->channels, OIIO::TypeDesc::FLOAT);
        if (int(image_->channelNames.size()) == image_->channels) m_spec.channelnames = image_->channelNames;
        newspec = m_spec;
        return true;
    }
    bool close() override {
        image_.reset();
        return true;
    }
    bool read_native_scanline(int subimage, int miplevel, int y, int /*z*/, void* data) override {
        if (subimage != 0 || miplevel != 0 || !image_ || y < 0 || y >= image_->height) return false;
        const std::size_t row = std::size_t(image_->width) * std::size_t(image_->channels);
        std::memcpy(data, image_->pixels.data() + std::size_t(y) * row, row * sizeof(float));
        return true;
    }

    static OIIO::ImageInput* create() { return new MemoryInput; }

private:
    std::shared_ptr<const MemoryImage> image_;
};

void MemoryImage::add(const std::string& name, std::shared_ptr<const MemoryImage> image) {
    {
        const std::lock_guard<std::mutex> lock(mutex());
        if (!images().emplace(name, std::move(image)).second) return;
    }
    OIIO::ImageCache::create(true)->add_file(OIIO::ustring(name), MemoryInput::create);
}

class OiioCodec final : public ImageCodec {
public:
    TextureFileHandle* openTexture(const TextureRequest& request, std::string& error) const override {
        OIIO::TextureSystem& system = textureSystem();
        std::string name = request.file;
        if (request.bytes != nullptr || request.colorSpace != TextureRequest::ColorSpace::Linear) {
            // Decoded here (and linearised) unless it is a linear file the cache can read itself.
            name = decodedImage(request, error);
            if (name.empty()) return nullptr;
        }
        OIIO::TextureSystem::TextureHandle* handle = system.get_texture_handle(OIIO::ustring(name));
        int exists = 0;
        if (handle == nullptr || !system.get_texture_info(handle, nullptr, 0, OIIO::ustring("exists"), OIIO::TypeInt, &exists) ||
            exists == 0 || !system.good(handle)) {
            error = system.geterror();
            if (error.empty()) error = "cannot open " + request.file;
            return nullptr;
        }
        return reinterpret_cast<TextureFileHandle*>(handle);
    }

    void lookupTexture(TextureFileHandle* texture, const TextureQuery& query, float rgb[3]) const override {
        if (!lookup(texture, query, 0, 3, rgb)) rgb[0] = rgb[1] = rgb[2] = 0.0f;
    }

    float lookupTextureChannel(TextureFileHandle* texture, const TextureQuery& query, int channel) const override {
        float value = 0.0f;
        return lookup(texture, query, channel, 1, &value) ? value : 0.0f;
    }

    int alphaChannel(TextureFileHandle* texture) const override {
        OIIO::TextureSystem& system = textureSystem();
        const OIIO::ImageSpec* spec = system.imagespec(reinterpret_cast<OIIO::TextureSystem::TextureHandle*>(texture), nullptr);
        if (spec == nullptr) return -1;
        for (int c = 0; c < spec->nchannels && c < int(spec->channelnames.size()); ++c) {
            const std::string& name = spec->channelnames[std::size_t(c)];
            if (OIIO::Strutil::iequals(name, "A") || OIIO::Strutil::iequals(name, "Alpha")) return c;
        }
        if (spec->nchannels == 2) return 1;
        if (spec->nchannels == 4) return 3;
        return -1;
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
    // `count` channels from `first` of `texture` at `query` into `out`; false when the file is
    // gone (opened before the render: only a file changed on disk since).
    static bool lookup(TextureFileHandle* texture, const TextureQuery& query, int first, int count, float* out) {
        OIIO::TextureSystem& system = textureSystem();
        // Each thread's own state, asked once per thread (pbrt and OSL do the same).
        thread_local OIIO::TextureSystem::Perthread* const perThread = system.get_perthread_info();
        OIIO::TextureOpt options;
        options.firstchannel = first;
        options.swrap = wrapMode(query.wrapS);
        options.twrap = wrapMode(query.wrapT);
        if (!query.filtered) {
            options.mipmode = OIIO::TextureOpt::MipModeNoMIP;
            options.interpmode = OIIO::TextureOpt::InterpBilinear;
        }
        return system.texture(reinterpret_cast<OIIO::TextureSystem::TextureHandle*>(texture), perThread, options, query.s,
                              query.t, query.dsdx, query.dtdx, query.dsdy, query.dtdy, count, out);
    }

    static OIIO::TextureOpt::Wrap wrapMode(TextureQuery::Wrap wrap) {
        switch (wrap) {
            case TextureQuery::Wrap::Clamp: return OIIO::TextureOpt::WrapClamp;
            case TextureQuery::Wrap::Mirror: return OIIO::TextureOpt::WrapMirror;
            case TextureQuery::Wrap::Periodic: break;
        }
        return OIIO::TextureOpt::WrapPeriodic;
    }

    // The request's image decoded into memory as float, its colour channels (not alpha)
    // linearised if sRGB, and registered with the ImageCache under a name of its own
    // (MemoryImage); that name, or an empty one with `error` set. A file that turns out linear
    // under Automatic (16-bit, float) is left to the cache: its own name comes back.
    static std::string decodedImage(const TextureRequest& request, std::string& error) {
        std::unique_ptr<OIIO::Filesystem::IOMemReader> memory;
        if (request.bytes != nullptr) memory = std::make_unique<OIIO::Filesystem::IOMemReader>(request.bytes->data(), request.bytes->size());
        // OpenImageIO picks its reader by the name's extension: name the bytes by their signature.
        const std::string readerName = request.bytes != nullptr ? "memory." + formatOf(*request.bytes) : request.file;
        // Colours as the file stores them, not multiplied by alpha (OpenImageIO's default for PNG):
        // glTF's base colour is straight, alpha a cut-out's own channel (materials/alpha.h), and
        // an sRGB texel is decoded before anything multiplies it.
        OIIO::ImageSpec config;
        config.attribute("oiio:UnassociatedAlpha", 1);
        // With a configuration the readers take their proxy from it, not from open's argument.
        if (memory) {
            OIIO::Filesystem::IOProxy* proxy = memory.get();
            config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
        }
        auto in = OIIO::ImageInput::open(readerName, &config, memory.get());
        if (!in) {
            error = OIIO::geterror();
            if (error.empty()) error = "cannot decode the image";
            return {};
        }
        const OIIO::ImageSpec& spec = in->spec();
        const bool srgb = request.colorSpace == TextureRequest::ColorSpace::Srgb ||
                          (request.colorSpace == TextureRequest::ColorSpace::Automatic && spec.format == OIIO::TypeDesc::UINT8);
        if (!srgb && request.bytes == nullptr) return request.file;
        // The bytes are named by their hash: two glTF files may embed different images of one name.
        const std::string name = "lightpath-memory:" + request.file +
                                 (request.bytes != nullptr ? " #" + std::to_string(std::hash<std::string_view>()(std::string_view(
                                                                        reinterpret_cast<const char*>(request.bytes->data()), request.bytes->size())))
                                                           : std::string()) +
                                 (srgb ? " (sRGB)" : " (linear)");
        if (MemoryImage::find(name)) return name;
        auto image = std::make_shared<MemoryImage>();
        image->width = spec.width;
        image->height = spec.height;
        image->channels = spec.nchannels;
        image->channelNames = spec.channelnames;
        image->pixels.resize(std::size_t(spec.width) * std::size_t(spec.height) * std::size_t(spec.nchannels));
        if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0 ||
            !in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image->pixels.data())) {
            error = in->geterror();
            if (error.empty()) error = "cannot decode the image";
            return {};
        }
        if (srgb) {
            for (std::size_t p = 0; p < image->pixels.size(); ++p) {
                const int channel = int(p % std::size_t(spec.nchannels));
                if (channel != spec.alpha_channel) image->pixels[p] = srgbToLinear(image->pixels[p]);
            }
        }
        MemoryImage::add(name, std::move(image));
        return name;
    }

    // sRGB's EOTF (IEC 61966-2-1): encoded value to linear.
    static float srgbToLinear(float v) {
        return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
    }

    static std::string formatOf(const std::vector<unsigned char>& bytes) {
        const auto starts = [&](std::initializer_list<unsigned char> magic) {
            return bytes.size() >= magic.size() && std::equal(magic.begin(), magic.end(), bytes.begin());
        };
        if (starts({0x89, 'P', 'N', 'G'})) return "png";
        if (starts({0xFF, 0xD8, 0xFF})) return "jpg";
        if (starts({'R', 'I', 'F', 'F'})) return "webp";
        if (starts({'v', '/', '1', 0x01})) return "exr";
        return "png";  // glTF's images are PNG or JPEG; an unknown one fails in the PNG reader
    }

    // One TextureSystem for the process, shared (with its ImageCache), made on first use.
    static OIIO::TextureSystem& textureSystem() {
        static OIIO::TextureSystem* const system = [] {
            OIIO::TextureSystem* made = OIIO::TextureSystem::create(true);
            made->attribute("automip", 1);      // a plain PNG gets its MIP levels when first read
            made->attribute("autotile", 64);    // and is cached in tiles
            made->attribute("gray_to_rgb", 1);  // a grey image is grey, not red
            made->attribute("unassociatedalpha", 1);  // colours straight, as decodedImage reads them
            return made;
        }();
        return *system;
    }
};

}  // namespace
}  // namespace lightpath

extern "C" __attribute__((visibility("default"))) const lightpath::ImageCodec* lightpathImageCodec(int interfaceVersion) {
    static const lightpath::OiioCodec codec;
    return interfaceVersion == lightpath::kImageCodecInterfaceVersion ? &codec : nullptr;
}
