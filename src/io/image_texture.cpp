// The textures of materials/texture.h, read through the image module's OpenImageIO TextureSystem:
// registered as the texture opener when the renderer's library is linked in (materials cannot
// include io/, which sits above them).
#include <memory>
#include <string>

#include "io/image_codec.h"
#include "io/image_module.h"
#include "materials/texture.h"

namespace lightpath {
namespace {

class ImageTexture final : public Texture {
public:
    ImageTexture(const ImageCodec& codec, TextureFileHandle* handle) : codec_(codec), handle_(handle) {
        float rgb[3];
        codec_.averageTexture(handle_, rgb);
        average_ = {rgb[0], rgb[1], rgb[2]};
        alphaChannel_ = codec_.alphaChannel(handle_);
    }

    Rgb lookup(const TextureFootprint& f, const TextureSampling& sampling) const override {
        float rgb[3];
        codec_.lookupTexture(handle_, query(f, sampling), rgb);
        return {rgb[0], rgb[1], rgb[2]};
    }

    float lookupChannel(const TextureFootprint& f, const TextureSampling& sampling, int channel) const override {
        return codec_.lookupTextureChannel(handle_, query(f, sampling), channel);
    }

    Rgb average() const override { return average_; }
    int alphaChannel() const override { return alphaChannel_; }

private:
    static TextureQuery query(const TextureFootprint& f, const TextureSampling& sampling) {
        // Image rows run down from t = 0 while v runs up (OBJ's vt, OpenGL): t = 1 - v.
        return {f.uv.x,    1.0f - f.uv.y, f.dUVdx.x, -f.dUVdx.y, f.dUVdy.x, -f.dUVdy.y,
                sampling.filtered, wrap(sampling.wrapS), wrap(sampling.wrapT)};
    }

    static TextureQuery::Wrap wrap(TextureWrap wrap) {
        switch (wrap) {
            case TextureWrap::clamp: return TextureQuery::Wrap::Clamp;
            case TextureWrap::mirror: return TextureQuery::Wrap::Mirror;
            case TextureWrap::repeat: break;
        }
        return TextureQuery::Wrap::Periodic;
    }

    const ImageCodec& codec_;
    TextureFileHandle* handle_;  // the TextureSystem's, alive for the process
    Rgb average_{0.0f};
    int alphaChannel_ = -1;
};

// A missing or broken image module is no fault of the scene: ImageModuleError goes to the
// command, which fails with exit code 1 (a file that cannot be read is the scene's, in `error`).
std::shared_ptr<const Texture> openImageTexture(const TextureSource& source, std::string& error) {
    const ImageCodec& codec = imageCodec();
    const TextureRequest::ColorSpace colorSpace = source.colorSpace == TextureColorSpace::srgb     ? TextureRequest::ColorSpace::Srgb
                                                  : source.colorSpace == TextureColorSpace::linear ? TextureRequest::ColorSpace::Linear
                                                                                                   : TextureRequest::ColorSpace::Automatic;
    TextureFileHandle* handle = codec.openTexture({source.file, source.bytes, colorSpace}, error);
    if (handle == nullptr) return nullptr;
    return std::make_shared<const ImageTexture>(codec, handle);
}

const bool kRegistered = (registerTextureOpener(openImageTexture), true);

}  // namespace
}  // namespace lightpath
