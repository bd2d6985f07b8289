#pragma once
// 8-bit PNG files through libpng: grey, grey + alpha, RGB or RGBA by the channel count, marked
// as sRGB, text attributes as tEXt chunks.
#include <filesystem>
#include <string>
#include <vector>

#include "io/image_file.h"

namespace lightpath {

// zlib's level and the row filter: lossless at any setting, the choice trades size for time.
struct PngCompression {
    int level = 6;              // 0..9, zlib's
    bool rowFilters = true;     // libpng's adaptive choice per row; false: none
};

// The encoded file's bytes in `bytes` (spec.format must be UInt8). Returns an empty string, or why not.
std::string encodePngBytes(const ImageFileSpec& spec, const unsigned char* pixels, PngCompression compression,
                           std::vector<unsigned char>& bytes);

// Encodes and writes `file`. Returns an empty string, or why not.
std::string writePngFile(const std::filesystem::path& file, const ImageFileSpec& spec, const unsigned char* pixels,
                         PngCompression compression);

}  // namespace lightpath
