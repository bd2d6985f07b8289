#include "io/image_writer.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <mutex>
#include <thread>

#include "film/large_buffer.h"
#include "io/exr_file.h"
#include "io/exr_layers.h"
#include "io/png_file.h"
#include "io/text_file.h"

namespace lightpath {
namespace {

namespace fs = std::filesystem;

// PNG is lossless at any setting; the choice trades file size for time. Measured on the seven
// PNGs of a 1920x1080 Whitted render of scenes/lecture-room.toml, CPU seconds on one thread
// (docs/performance.md): OpenImageIO's default (zlib level 6, libpng's adaptive row filters)
// 0.51 s and 611 KB; level 6 without filters 0.22 s, 576 KB; level 1 without filters 0.148 s,
// 1.0 MB. Rendered images (smooth shading, AOVs mostly black) compress well without filters, and
// trying five filters on every row costs more than it saves; level 1 is zlib's fastest.
constexpr PngCompression kPngCompression{.level = 1, .rowFilters = false};
constexpr std::size_t kPngBytesPerPixel = 3;  // 8-bit R, G, B

std::string lowerExtension(const fs::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

// sRGB's transfer function (IEC 61966-2-1), in double: the definition toSrgb8 reproduces exactly.
double srgbEncode(double linear) {
    return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}
double srgbDecode(double encoded) {
    return encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4);
}
int srgbCode(float linear) { return static_cast<int>(std::lround(255.0 * srgbEncode(linear))); }

// toSrgb8 without a pow per value (a 1080p image with its AOVs has 40 million of them). Linear
// values in (0, 1) are split into buckets by the top bits of their float representation; a
// bucket is 2^-8 of an octave wide while two codes' thresholds are at least 0.9% apart (sRGB's
// slope, 2.4/255 relative, at its steepest), so a bucket holds at most one threshold: the code
// is the bucket's first code, plus one past that threshold.
class Srgb8Table {
public:
    Srgb8Table() {
        for (int k = 1; k <= 255; ++k) {
            // The least float whose code is k: start from the exact inverse, step to the boundary.
            float t = static_cast<float>(srgbDecode((k - 0.5) / 255.0));
            while (srgbCode(t) >= k) t = std::nextafter(t, 0.0f);
            while (srgbCode(t) < k) t = std::nextafter(t, 2.0f);
            thresholds_[static_cast<std::size_t>(k)] = t;
        }
        thresholds_[0] = 0.0f;
        thresholds_[256] = std::numeric_limits<float>::infinity();
        for (std::uint32_t b = 0; b < kBuckets; ++b) {
            const float first = std::bit_cast<float>(b << kBucketShift);
            const auto above = std::upper_bound(thresholds_.begin() + 1, thresholds_.end(), first);
            bucketCodes_[b] = static_cast<std::uint8_t>(above - thresholds_.begin() - 1);
        }
    }

    unsigned char encode(float linear) const {
        if (linear == std::numeric_limits<float>::infinity()) return 0;  // never in a film: non-finite is dropped
        // Branch-free for the common values: NaN and negatives to 0 (a comparison with NaN is false),
        // above 1 to 1, whose bucket is the table's last.
        const float clamped = std::min(linear > 0.0f ? linear : 0.0f, 1.0f);
        const int code = bucketCodes_[std::bit_cast<std::uint32_t>(clamped) >> kBucketShift];
        return static_cast<unsigned char>(code + (clamped >= thresholds_[static_cast<std::size_t>(code) + 1] ? 1 : 0));
    }

private:
    static constexpr int kBucketShift = 15;  // 23 mantissa bits - 15 = 8 bits per octave
    static constexpr std::uint32_t kBuckets = (std::bit_cast<std::uint32_t>(1.0f) >> kBucketShift) + 1;  // [0, 1]
    std::array<float, 257> thresholds_{};  // [k]: the least linear value of code k
    std::array<std::uint8_t, kBuckets> bucketCodes_{};
};

const Srgb8Table& srgb8Table() {
    static const Srgb8Table table;
    return table;
}

ImageFileSpec specFor(const Film& film, PixelFormat format, const ImageMetadata& metadata) {
    ImageFileSpec spec;
    spec.width = film.width();
    spec.height = film.height();
    spec.format = format;
    spec.textAttributes = metadata;
    return spec;
}

// One multi-layer EXR: "beauty" as R,G,B and every other layer as <layer>.R/.G/.B. Rgb is three
// packed floats, so the film (film.interleaved()) is already the EXR's interleaved channel order.
ImageFileSpec exrSpec(const Film& film, const ImageMetadata& metadata) {
    static_assert(sizeof(Rgb) == 3 * sizeof(float));
    ImageFileSpec spec = specFor(film, PixelFormat::Float32, metadata);
    for (const std::string& name : film.layerNames())
        for (const char* c : kRgbChannels) spec.channelNames.push_back(exrChannelName(name, c));
    return spec;
}

const float* exrPixels(const Film& film) { return reinterpret_cast<const float*>(film.interleaved().data()); }

// One layer as an 8-bit sRGB PNG: its spec, and its pixels.
ImageFileSpec pngSpec(const Film& film, const ImageMetadata& metadata) {
    ImageFileSpec spec = specFor(film, PixelFormat::UInt8, metadata);
    spec.channelNames = {"R", "G", "B"};
    return spec;
}

std::vector<unsigned char, LargeBufferAllocator<unsigned char>> pngPixels(const Film& film, std::size_t layer, float scale) {
    const std::span<const Rgb> all = film.interleaved();
    const std::size_t stride = film.layerCount();
    const Srgb8Table& table = srgb8Table();
    std::vector<unsigned char, LargeBufferAllocator<unsigned char>> encoded(all.size() / stride * kPngBytesPerPixel);
    for (std::size_t p = 0, i = layer; i < all.size(); ++p, i += stride)
        for (int c = 0; c < 3; ++c) encoded[p * kPngBytesPerPixel + static_cast<std::size_t>(c)] = table.encode(all[i][c] * scale);
    return encoded;
}

std::string writePng(const Film& film, std::size_t layer, const fs::path& temporary, const ImageMetadata& metadata) {
    return writePngFile(temporary, pngSpec(film, metadata), pngPixels(film, layer, 1.0f).data(), kPngCompression);
}

// Runs task(0..count-1) on up to `threads` threads (0: one per core); returns the first failure.
std::size_t parallelWorkers(std::size_t count, int threads) {
    const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
    return std::min<std::size_t>(count, threads > 0 ? static_cast<std::size_t>(threads) : cores);
}

template <typename Task>
std::string runInParallel(std::size_t count, int threads, const Task& task) {
    const std::size_t workers = parallelWorkers(count, threads);
    std::atomic<std::size_t> next{0};
    std::atomic<bool> failed{false};
    std::mutex mutex;
    std::string firstError;
    auto work = [&] {
        for (std::size_t i = next++; i < count && !failed.load(); i = next++) {
            std::string error;
            try {
                error = task(i);
            } catch (const std::bad_alloc&) {
                error = "out of memory";
            } catch (const std::exception& e) {
                error = e.what();
            }
            if (error.empty()) continue;
            const std::lock_guard lock(mutex);
            if (!failed.exchange(true)) firstError = std::move(error);
        }
    };
    {
        std::vector<std::jthread> pool;
        for (std::size_t w = 1; w < workers; ++w) pool.emplace_back(work);
        work();
    }
    return firstError;
}

std::vector<unsigned char> checked(const std::string& failure, std::vector<unsigned char>& bytes) {
    if (!failure.empty()) throw ImageWriteError(failure);
    return std::move(bytes);
}

}  // namespace

std::vector<unsigned char> encodeExr(const Film& film, const ImageMetadata& metadata) {
    std::vector<unsigned char> bytes;
    return checked(encodeExrBytes(exrSpec(film, metadata), exrPixels(film), bytes), bytes);
}

std::vector<unsigned char> encodePng(const Film& film, std::size_t layer, float scale) {
    std::vector<unsigned char> bytes;
    return checked(encodePngBytes(pngSpec(film, {}), pngPixels(film, layer, scale).data(), kPngCompression, bytes), bytes);
}

unsigned char toSrgb8(float linear) { return srgb8Table().encode(linear); }

std::vector<fs::path> outputFiles(const Film& film, const fs::path& path) {
    const std::string ext = lowerExtension(path);
    if (ext == ".exr") return {path};
    if (ext != ".png")
        throw ImageWriteError(path.string() + ": unsupported output extension \"" + path.extension().string() +
                              "\"; expected .exr (one multi-layer file) or .png (one file per layer)");
    std::vector<fs::path> files;
    for (const std::string& name : film.layerNames()) {
        fs::path file = path;
        if (name != kBeautyLayer) file.replace_extension(name + path.extension().string());
        files.push_back(file);
    }
    return files;
}

std::uint64_t encodingBytes(const fs::path& path, int width, int height, std::size_t layers, int threads) {
    if (lowerExtension(path) != ".png") return 0;  // the EXR is written from the film itself
    const std::uint64_t pixels = static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height);
    return parallelWorkers(layers, threads) * pixels * kPngBytesPerPixel;
}

std::vector<fs::path> writeFilm(const Film& film, const fs::path& path, const ImageMetadata& metadata, int threads) {
    const std::vector<fs::path> targets = outputFiles(film, path);
    std::vector<fs::path> temporaries;
    for (const fs::path& target : targets) temporaries.push_back(temporaryName(target));
    const auto removeTemporaries = [&] {
        std::error_code ignored;
        for (const fs::path& t : temporaries) fs::remove(t, ignored);
    };
    try {
        if (path.has_parent_path()) fs::create_directories(path.parent_path());
        const bool exr = lowerExtension(path) == ".exr";
        // One task per file: PNG layers are tone-mapped and compressed side by side.
        const std::string error = runInParallel(targets.size(), threads, [&](std::size_t i) {
            const std::string failure = exr ? writeExrFile(temporaries[i], exrSpec(film, metadata), exrPixels(film))
                                            : writePng(film, i, temporaries[i], metadata);
            return failure.empty() ? failure : targets[i].string() + ": cannot write image (" + failure + ")";
        });
        if (!error.empty()) throw ImageWriteError(error);
        for (std::size_t i = 0; i < targets.size(); ++i) fs::rename(temporaries[i], targets[i]);
    } catch (const ImageWriteError&) {
        removeTemporaries();
        throw;
    } catch (const std::exception& e) {
        removeTemporaries();
        throw ImageWriteError(path.string() + ": " + e.what());
    }
    return targets;
}

}  // namespace lightpath
