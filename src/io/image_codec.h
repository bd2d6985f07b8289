#pragma once
// The interface between lightpath and its image module, liblightpath-image.so: the only code that
// includes OpenImageIO, for its TextureSystem (filtered, MIP-mapped, cached texture lookups) and
// its readers of every image format a texture may come in. Debian's libOpenImageIO pulls in about
// 260 shared libraries, which take the dynamic loader a quarter to half a second of CPU to bind;
// a command whose scene has no texture must not pay that (renders write their EXR and PNG files
// through OpenEXR and libpng: io/exr_file.h, io/png_file.h), so the module is opened with dlopen
// on first use (io/image_module.h) and this header is all the two sides share. Both are built
// together by the same compiler, so the types may be C++.
#include <string>
#include <vector>

namespace lightpath {

// The module's entry point, `extern "C"` so dlsym finds it by this name. It returns its codec,
// or nullptr when `interfaceVersion` is not the one it was built with (a stale module).
inline constexpr const char* kImageCodecEntryPoint = "lightpathImageCodec";
// Bumped whenever anything in this header changes.
inline constexpr int kImageCodecInterfaceVersion = 6;

// A filtered texture lookup (OpenImageIO's TextureSystem::texture): the texture coordinates (s, t)
// of a surface point and their change across one pixel in x and in y, which set the filter.
struct TextureQuery {
    float s = 0.0f, t = 0.0f;
    float dsdx = 0.0f, dtdx = 0.0f, dsdy = 0.0f, dtdy = 0.0f;
    bool filtered = true;  // false: the finest level's nearest texels, bilinearly (point sampling)
    // Outside [0, 1] in s and in t: repeat (glTF's REPEAT), the edge texel (CLAMP_TO_EDGE), or
    // repeat mirrored (MIRRORED_REPEAT).
    enum class Wrap { Periodic, Clamp, Mirror };
    Wrap wrapS = Wrap::Periodic, wrapT = Wrap::Periodic;
};

// A texture to open: a file, or an encoded image (PNG, JPEG, ...) in memory, and how its values
// are encoded. sRGB texels are decoded to linear (the sRGB EOTF, IEC 61966-2-1) before the MIP
// levels are built, so the filter averages linear values.
struct TextureRequest {
    enum class ColorSpace { Automatic, Srgb, Linear };  // Automatic: sRGB for 8-bit images
    std::string file;                                 // the file, or the in-memory image's name
    const std::vector<unsigned char>* bytes = nullptr;  // the encoded image, else read `file`
    ColorSpace colorSpace = ColorSpace::Automatic;
};

// A texture file opened in the module's one TextureSystem (shared, with its cache); opaque here.
struct TextureFileHandle;

class ImageCodec {
public:
    // Opens a texture (MIP-mapped on first use if it has no levels, tiled, cached); nullptr with
    // `error` set when it cannot be read. Handles live as long as the process. An sRGB or an
    // in-memory image is decoded once into memory (linearised), never written to disk.
    virtual TextureFileHandle* openTexture(const TextureRequest& request, std::string& error) const = 0;
    // The filtered RGB of `texture` at `query`, wrapped as it says (a grey image is replicated
    // into R, G and B). Safe to call from many threads at once: each uses its own per-thread
    // state of the TextureSystem.
    virtual void lookupTexture(TextureFileHandle* texture, const TextureQuery& query, float rgb[3]) const = 0;
    // The filtered value of channel `channel` alone (its alpha, say), as lookupTexture filters.
    virtual float lookupTextureChannel(TextureFileHandle* texture, const TextureQuery& query, int channel) const = 0;
    // The mean RGB of the whole texture.
    virtual void averageTexture(TextureFileHandle* texture, float rgb[3]) const = 0;
    // Its alpha channel's index: the one named A or Alpha, else the second of two (grey and
    // alpha) or the fourth of four; -1 when it has none.
    virtual int alphaChannel(TextureFileHandle* texture) const = 0;

protected:
    ~ImageCodec() = default;  // the module owns its codec; it lives as long as the process
};

using ImageCodecEntryPoint = const ImageCodec* (*)(int interfaceVersion);

}  // namespace lightpath
