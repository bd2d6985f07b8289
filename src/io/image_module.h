#pragma once
// Opens the image module, liblightpath-image.so (io/image_codec.h), on first use: commands that
// read or write no image never load OpenImageIO and its ~260 shared libraries. A render loads it
// on its calling thread while the other workers render, so writing finds it ready.
//
// Where it is looked for: $LIGHTPATH_IMAGE_MODULE when set (and nowhere else), else next to the
// running executable, else where the build tree made it (for test executables in sub-folders).
#include <filesystem>
#include <stdexcept>

#include "io/image_codec.h"

namespace lightpath {

// The module is missing, cannot be loaded, or is not the one this binary was built with.
class ImageModuleError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// The module's file name, and where this process would load it from; throws ImageModuleError,
// naming every place it looked, when it is in none of them. Cheap (no loading): a render checks
// it before spending minutes on an image it could not write.
std::filesystem::path locateImageModule();

// Loads the module now, on the calling thread, unless it is loaded; a failure is kept for
// imageCodec() to report. Idempotent and thread-safe. Never on a thread of its own: the main
// thread later uses the thread-local storage of the libraries it brings (log4cplus), and clang
// 14's LeakSanitizer crashes reading glibc 2.36's dynamic TLS made that way ("Tracer caught
// signal 11" in ScanRangeForPointers, after a 26-layer EXR write).
void loadImageModule();

// The loaded module's codec, loading it (or waiting for the background load) if need be. Throws
// ImageModuleError with the loader's reason when it cannot.
const ImageCodec& imageCodec();

}  // namespace lightpath
