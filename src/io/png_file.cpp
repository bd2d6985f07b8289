#include "io/png_file.h"

#include <png.h>

#include <cerrno>
#include <csetjmp>
#include <cstring>
#include <cstdio>
#include <memory>
#include <new>

namespace lightpath {
namespace {

// Where the encoded bytes go (a vector or a file), and libpng's error. libpng reports errors by
// longjmp to the encoder's setjmp; the callbacks keep the message and never let a C++ exception
// cross its C frames.
struct PngWriteState {
    std::vector<unsigned char>* bytes = nullptr;
    std::FILE* file = nullptr;
    std::string error;
};

void onError(png_structp png, png_const_charp message) {
    auto* state = static_cast<PngWriteState*>(png_get_error_ptr(png));
    try {
        state->error = message;
    } catch (...) {
    }
    png_longjmp(png, 1);
}

void onWarning(png_structp, png_const_charp) {}

void onWrite(png_structp png, png_bytep data, png_size_t size) {
    auto* state = static_cast<PngWriteState*>(png_get_io_ptr(png));
    if (state->file != nullptr) {
        if (std::fwrite(data, 1, size, state->file) != size) png_error(png, std::strerror(errno));
        return;
    }
    bool full = false;
    try {
        state->bytes->insert(state->bytes->end(), data, data + size);
    } catch (const std::bad_alloc&) {
        full = true;
    }
    if (full) png_error(png, "out of memory");
}

void onFlush(png_structp) {}

int colorTypeOf(std::size_t channels) {
    switch (channels) {
        case 1: return PNG_COLOR_TYPE_GRAY;
        case 2: return PNG_COLOR_TYPE_GRAY_ALPHA;
        case 3: return PNG_COLOR_TYPE_RGB;
        case 4: return PNG_COLOR_TYPE_RGB_ALPHA;
        default: return -1;
    }
}

// The libpng calls, between one setjmp and the longjmp of any error: no object with a destructor
// lives in this frame, so an error skips none (the caller owns them all).
bool encode(png_structp png, png_infop info, const ImageFileSpec& spec, const unsigned char* pixels,
            PngCompression compression, std::vector<png_text>& texts, PngWriteState& state) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_set_write_fn(png, &state, onWrite, onFlush);
    const std::size_t channels = spec.channelNames.size();
    png_set_IHDR(png, info, static_cast<png_uint_32>(spec.width), static_cast<png_uint_32>(spec.height), 8,
                 colorTypeOf(channels), PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_PERCEPTUAL);  // the values are sRGB-encoded
    if (!texts.empty()) png_set_text(png, info, texts.data(), static_cast<int>(texts.size()));
    png_set_compression_level(png, compression.level);
    png_set_filter(png, PNG_FILTER_TYPE_BASE, compression.rowFilters ? PNG_ALL_FILTERS : PNG_FILTER_NONE);
    png_write_info(png, info);
    const std::size_t rowBytes = static_cast<std::size_t>(spec.width) * channels;
    for (int y = 0; y < spec.height; ++y)  // libpng's row type is mutable; it only reads the row
        png_write_row(png, const_cast<png_bytep>(pixels + static_cast<std::size_t>(y) * rowBytes));
    png_write_end(png, info);
    return true;
}

// Encodes into state's vector or file.
std::string encodeInto(const ImageFileSpec& spec, const unsigned char* pixels, PngCompression compression,
                       PngWriteState& state) {
    if (spec.format != PixelFormat::UInt8) return "a PNG is written from 8-bit pixels";
    if (colorTypeOf(spec.channelNames.size()) < 0) return "a PNG has 1 to 4 channels";
    if (spec.width <= 0 || spec.height <= 0) return "an empty image";
    std::vector<png_text> texts;
    for (const auto& [key, value] : spec.textAttributes) {
        png_text text{};
        text.compression = PNG_TEXT_COMPRESSION_NONE;
        text.key = const_cast<png_charp>(key.c_str());  // libpng copies keys and texts
        text.text = const_cast<png_charp>(value.c_str());
        text.text_length = value.size();
        texts.push_back(text);
    }
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &state, onError, onWarning);
    png_infop info = png == nullptr ? nullptr : png_create_info_struct(png);
    if (info == nullptr) {
        png_destroy_write_struct(&png, nullptr);
        return "out of memory";
    }
    const bool encoded = encode(png, info, spec, pixels, compression, texts, state);
    png_destroy_write_struct(&png, &info);
    if (!encoded) return state.error.empty() ? "libpng failed" : state.error;
    return {};
}

}  // namespace

std::string encodePngBytes(const ImageFileSpec& spec, const unsigned char* pixels, PngCompression compression,
                           std::vector<unsigned char>& bytes) {
    bytes.clear();
    PngWriteState state{.bytes = &bytes};
    std::string failure = encodeInto(spec, pixels, compression, state);
    if (!failure.empty()) bytes.clear();
    return failure;
}

std::string writePngFile(const std::filesystem::path& file, const ImageFileSpec& spec, const unsigned char* pixels,
                         PngCompression compression) {
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> out(std::fopen(file.c_str(), "wb"), std::fclose);
    if (!out) return std::string("cannot create the file: ") + std::strerror(errno);
    PngWriteState state{.file = out.get()};
    std::string failure = encodeInto(spec, pixels, compression, state);
    if (std::fclose(out.release()) != 0 && failure.empty()) failure = std::strerror(errno);  // a late write error
    return failure;
}

}  // namespace lightpath
