#pragma once
// Writes a film as image files (docs/design.md, "Output"), through OpenEXR and libpng:
//   NAME.exr  one multi-layer EXR: the layer "beauty" as R,G,B and each other layer as
//             <layer>.R/.G/.B, the metadata as header attributes;
//   NAME.png  the beauty as NAME.png and every other layer as NAME.<layer>.png, clamped and
//             sRGB-encoded.
// Every file is written under a temporary name in the same folder and renamed only when all were
// written, so a failed run leaves no half-written file and keeps any older image of that name.
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "film/film.h"

namespace lightpath {

class ImageWriteError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

using ImageMetadata = std::vector<std::pair<std::string, std::string>>;

// The files that `writeFilm` would produce for `path`, in layer order. Throws ImageWriteError for
// an extension other than .exr or .png.
std::vector<std::filesystem::path> outputFiles(const Film& film, const std::filesystem::path& path);

// The bytes writeFilm allocates beside the film to write it to `path` on `threads` threads: the
// PNG layers encoded at once (none for an EXR), for the check before a render (issue #28).
std::uint64_t encodingBytes(const std::filesystem::path& path, int width, int height, std::size_t layers, int threads);

// Returns the files written. Files are written side by side on up to `threads` threads (0: one
// per core). Throws ImageWriteError, naming the file, when one cannot be written (the image module
// missing included); then none of them is.
std::vector<std::filesystem::path> writeFilm(const Film& film, const std::filesystem::path& path,
                                             const ImageMetadata& metadata, int threads = 0);

// The same files in memory, for serving them (`lightpath serve`): the multi-layer EXR of writeFilm,
// and one layer as an 8-bit sRGB PNG, each value first multiplied by `scale` (an exposure).
// Written in memory: no file or folder is ever made, so none is left behind however the process
// ends. Throws ImageWriteError.
std::vector<unsigned char> encodeExr(const Film& film, const ImageMetadata& metadata);
std::vector<unsigned char> encodePng(const Film& film, std::size_t layer, float scale = 1.0f);

// The sRGB transfer function (IEC 61966-2-1) of a linear value clamped to [0, 1], in 0..255,
// rounded to nearest; 0 for NaN and infinities.
unsigned char toSrgb8(float linear);

}  // namespace lightpath
