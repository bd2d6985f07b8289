#include "io/exr_file.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfStringAttribute.h>
#include <ImfThreading.h>

#include <algorithm>
#include <cstring>
#include <exception>
#include <mutex>
#include <new>
#include <thread>
#include <utility>

namespace lightpath {
namespace {

// The bytes of a file being written in memory: the writer seeks back to fill in the offsets of
// its scanline chunks, so this is a seekable stream, not an append.
class MemoryStream : public Imf::OStream {
public:
    explicit MemoryStream(std::vector<unsigned char>& bytes) : Imf::OStream("memory"), bytes_(bytes) {}

    void write(const char c[], int n) override {
        const std::size_t end = position_ + static_cast<std::size_t>(n);
        if (end > bytes_.size()) bytes_.resize(end);
        std::memcpy(bytes_.data() + position_, c, static_cast<std::size_t>(n));
        position_ = end;
    }
    std::uint64_t tellp() override { return position_; }
    void seekp(std::uint64_t position) override { position_ = static_cast<std::size_t>(position); }

private:
    std::vector<unsigned char>& bytes_;
    std::size_t position_ = 0;
};

// Scanline chunks are compressed on OpenEXR's global thread pool, one thread per core (as
// OpenImageIO sets it); a 1080p EXR with its AOVs is tens of megabytes before ZIP.
void useEveryCore() {
    static std::once_flag once;
    std::call_once(once, [] { Imf::setGlobalThreadCount(static_cast<int>(std::max(1u, std::thread::hardware_concurrency()))); });
}

Imf::Header headerFor(const ImageFileSpec& spec) {
    Imf::Header header(spec.width, spec.height);
    header.compression() = Imf::ZIP_COMPRESSION;  // 16 scanlines per chunk
    for (const std::string& name : spec.channelNames) header.channels().insert(name, Imf::Channel(Imf::FLOAT));
    for (const auto& [key, value] : spec.textAttributes) header.insert(key, Imf::StringAttribute(value));
    return header;
}

// Float slices into interleaved pixels, `names.size()` per pixel, row by row over `window`: what a
// writer reads from and a reader fills (OpenEXR takes the same slices for both).
Imf::FrameBuffer interleavedFrameBuffer(const std::vector<std::string>& names, const float* pixels,
                                        const Imath::Box2i& window) {
    const std::size_t xStride = names.size() * sizeof(float);
    const std::size_t yStride = xStride * static_cast<std::size_t>(window.max.x - window.min.x + 1);
    Imf::FrameBuffer frameBuffer;
    for (std::size_t c = 0; c < names.size(); ++c)
        frameBuffer.insert(names[c], Imf::Slice::Make(Imf::FLOAT, pixels + c, window, xStride, yStride));
    return frameBuffer;
}

std::string checkSpec(const ImageFileSpec& spec) {
    if (spec.format != PixelFormat::Float32) return "an EXR is written from float pixels";
    if (spec.width <= 0 || spec.height <= 0 || spec.channelNames.empty()) return "an empty image";
    return {};
}

template <typename Target>
std::string write(Target&& target, const ImageFileSpec& spec, const float* pixels) {
    if (std::string invalid = checkSpec(spec); !invalid.empty()) return invalid;
    useEveryCore();
    try {
        Imf::OutputFile out(std::forward<Target>(target), headerFor(spec));
        out.setFrameBuffer(interleavedFrameBuffer(spec.channelNames, pixels, out.header().dataWindow()));
        out.writePixels(spec.height);
    } catch (const std::bad_alloc&) {
        return "out of memory";
    } catch (const std::exception& e) {
        return e.what();
    }
    return {};
}

}  // namespace

std::string writeExrFile(const std::filesystem::path& file, const ImageFileSpec& spec, const float* pixels) {
    const std::string name = file.string();
    return write(name.c_str(), spec, pixels);
}

std::string encodeExrBytes(const ImageFileSpec& spec, const float* pixels, std::vector<unsigned char>& bytes) {
    bytes.clear();
    MemoryStream stream(bytes);
    return write(stream, spec, pixels);
}

std::string readExrFile(const std::filesystem::path& file, ImageData& image) {
    useEveryCore();
    try {
        Imf::InputFile in(file.string().c_str());
        const Imath::Box2i window = in.header().dataWindow();
        image.width = window.max.x - window.min.x + 1;
        image.height = window.max.y - window.min.y + 1;
        image.channelNames.clear();
        for (auto c = in.header().channels().begin(); c != in.header().channels().end(); ++c)
            image.channelNames.emplace_back(c.name());
        const std::size_t channels = image.channelNames.size();
        if (image.width <= 0 || image.height <= 0 || channels == 0) return "an empty image";
        image.pixels.assign(static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * channels, 0.0f);
        // Half and uint channels are converted to float.
        in.setFrameBuffer(interleavedFrameBuffer(image.channelNames, image.pixels.data(), window));
        in.readPixels(window.min.y, window.max.y);
    } catch (const std::bad_alloc&) {
        return "out of memory";
    } catch (const std::exception& e) {
        return e.what();
    }
    return {};
}

}  // namespace lightpath
