#include "io/image_writer.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>

namespace lightpath {
namespace {

namespace fs = std::filesystem;

constexpr const char* kBeautyLayer = "beauty";

std::string lowerExtension(const fs::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

fs::path temporaryName(const fs::path& target) {
    return target.parent_path() / ("." + target.filename().string() + ".tmp-" + std::to_string(::getpid()));
}

// One image file: `channels` interleaved values per pixel of type `format`.
void writeImageFile(const fs::path& target, const fs::path& temporary, const OIIO::ImageSpec& spec,
                    OIIO::TypeDesc format, const void* data) {
    auto out = OIIO::ImageOutput::create(target.string());
    if (!out) throw ImageWriteError(target.string() + ": cannot create an image writer (" + OIIO::geterror() + ")");
    if (!out->open(temporary.string(), spec) || !out->write_image(format, data) || !out->close()) {
        const std::string message = out->geterror();
        std::error_code ignored;
        fs::remove(temporary, ignored);
        throw ImageWriteError(target.string() + ": cannot write image (" + message + ")");
    }
}

// One image in memory, through OIIO's I/O proxy (no file is touched); `name` picks the format.
std::vector<unsigned char> encodeImage(const std::string& name, const OIIO::ImageSpec& spec, OIIO::TypeDesc format,
                                       const void* data) {
    std::vector<unsigned char> bytes;
    OIIO::Filesystem::IOVecOutput proxy(bytes);
    auto out = OIIO::ImageOutput::create(name);
    if (!out) throw ImageWriteError(name + ": cannot create an image writer (" + OIIO::geterror() + ")");
    out->set_ioproxy(&proxy);
    if (!out->open(name, spec) || !out->write_image(format, data) || !out->close())
        throw ImageWriteError(name + ": cannot encode image (" + out->geterror() + ")");
    return bytes;
}

OIIO::ImageSpec exrSpec(const Film& film, const ImageMetadata& metadata) {
    const std::size_t channels = 3 * film.layerCount();
    OIIO::ImageSpec spec(film.width(), film.height(), static_cast<int>(channels), OIIO::TypeDesc::FLOAT);
    spec.channelnames.clear();
    for (std::size_t l = 0; l < film.layerCount(); ++l) {
        const std::string& name = film.layerNames()[l];
        const std::string prefix = name == kBeautyLayer ? "" : name + ".";
        for (const char* c : {"R", "G", "B"}) spec.channelnames.push_back(prefix + c);
    }
    spec.attribute("compression", "zip");
    for (const auto& [key, value] : metadata) spec.attribute(key, value);
    return spec;
}

// Rgb is three packed floats, so the film is already the EXR's interleaved channel order.
static_assert(sizeof(Rgb) == 3 * sizeof(float));

void writeExr(const Film& film, const fs::path& target, const fs::path& temporary, const ImageMetadata& metadata) {
    writeImageFile(target, temporary, exrSpec(film, metadata), OIIO::TypeDesc::FLOAT, film.interleaved().data());
}

std::vector<unsigned char> srgbPixels(const Film& film, std::size_t layer, float scale) {
    const auto pixels = film.layer(layer);
    std::vector<unsigned char> encoded(pixels.size() * 3);
    for (std::size_t p = 0; p < pixels.size(); ++p)
        for (int c = 0; c < 3; ++c) encoded[p * 3 + static_cast<std::size_t>(c)] = toSrgb8(pixels[p][c] * scale);
    return encoded;
}

void writePng(const Film& film, std::size_t layer, const fs::path& target, const fs::path& temporary,
              const ImageMetadata& metadata) {
    OIIO::ImageSpec spec(film.width(), film.height(), 3, OIIO::TypeDesc::UINT8);
    for (const auto& [key, value] : metadata) spec.attribute(key, value);
    writeImageFile(target, temporary, spec, OIIO::TypeDesc::UINT8, srgbPixels(film, layer, 1.0f).data());
}

}  // namespace

std::vector<unsigned char> encodeExr(const Film& film, const ImageMetadata& metadata) {
    return encodeImage("film.exr", exrSpec(film, metadata), OIIO::TypeDesc::FLOAT, film.interleaved().data());
}

std::vector<unsigned char> encodePng(const Film& film, std::size_t layer, float scale) {
    OIIO::ImageSpec spec(film.width(), film.height(), 3, OIIO::TypeDesc::UINT8);
    // Served once per pass and layer: fast compression matters more than size on a loopback link.
    spec.attribute("png:compressionLevel", 1);
    return encodeImage("layer.png", spec, OIIO::TypeDesc::UINT8, srgbPixels(film, layer, scale).data());
}

unsigned char toSrgb8(float linear) {
    const float v = std::isfinite(linear) ? std::clamp(linear, 0.0f, 1.0f) : 0.0f;
    const float encoded = v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
    return static_cast<unsigned char>(std::lround(encoded * 255.0f));
}

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

std::vector<fs::path> writeFilm(const Film& film, const fs::path& path, const ImageMetadata& metadata) {
    const std::vector<fs::path> targets = outputFiles(film, path);
    std::vector<fs::path> temporaries;
    try {
        if (path.has_parent_path()) fs::create_directories(path.parent_path());
        for (std::size_t i = 0; i < targets.size(); ++i) {
            temporaries.push_back(temporaryName(targets[i]));
            if (lowerExtension(path) == ".exr") writeExr(film, targets[i], temporaries[i], metadata);
            else writePng(film, i, targets[i], temporaries[i], metadata);
        }
        for (std::size_t i = 0; i < targets.size(); ++i) fs::rename(temporaries[i], targets[i]);
    } catch (const std::exception& e) {
        std::error_code ignored;
        for (const fs::path& t : temporaries) fs::remove(t, ignored);
        if (dynamic_cast<const ImageWriteError*>(&e)) throw;
        throw ImageWriteError(path.string() + ": " + e.what());
    }
    return targets;
}

}  // namespace lightpath
