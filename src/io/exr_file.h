#pragma once
// OpenEXR files through the OpenEXR library (ILM's reference implementation): float channels,
// ZIP-compressed scanlines, text attributes as string attributes. Linked directly: it and its
// few libraries load in milliseconds, so no image written costs OpenImageIO's ~260 libraries.
#include <filesystem>
#include <string>
#include <vector>

#include "io/image_file.h"

namespace lightpath {

// Writes `pixels` (spec.format must be Float32) to `file`. Returns an empty string, or why not.
std::string writeExrFile(const std::filesystem::path& file, const ImageFileSpec& spec, const float* pixels);

// The same file's bytes, written in memory (no file, no folder). Returns an empty string, or why not.
std::string encodeExrBytes(const ImageFileSpec& spec, const float* pixels, std::vector<unsigned char>& bytes);

// Reads every channel of `file`'s first part as float, in the file's channel order (EXR keeps
// channels sorted by name). Returns an empty string, or why not.
std::string readExrFile(const std::filesystem::path& file, ImageData& image);

}  // namespace lightpath
