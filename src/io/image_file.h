#pragma once
// An image as the file writers take it (io/exr_file.h, io/png_file.h): its size, its channels'
// names and pixel format, and the text attributes a file keeps beside the pixels.
#include <string>
#include <utility>
#include <vector>

namespace lightpath {

enum class PixelFormat { UInt8, Float32 };

// `channelNames.size()` interleaved values per pixel, row by row from the top.
struct ImageFileSpec {
    int width = 0;
    int height = 0;
    std::vector<std::string> channelNames;
    PixelFormat format = PixelFormat::UInt8;
    std::vector<std::pair<std::string, std::string>> textAttributes;  // metadata: EXR string attributes, PNG tEXt
};

// An image read back: every channel as float, interleaved in `channelNames` order, row by row.
struct ImageData {
    int width = 0;
    int height = 0;
    std::vector<std::string> channelNames;
    std::vector<float> pixels;
};

}  // namespace lightpath
