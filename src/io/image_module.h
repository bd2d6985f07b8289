#pragma once
// Opens the image module, liblightpath-image.so (io/image_codec.h), on first use: commands that
// read or write no image never load OpenImageIO and its ~260 shared libraries. A render starts
// loading it in the background while the scene renders, so writing finds it ready.
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

// Starts loading the module on a background thread and returns at once. Idempotent.
void preloadImageModule();
// Waits until a load started by preloadImageModule() has finished. Call it before the process
// exits: exit() runs the destructors of every loaded library, and a loader thread still running
// OpenImageIO's dependencies' constructors would read what they have torn down.
void awaitImageModule();

// The loaded module's codec, loading it (or waiting for the background load) if need be. Throws
// ImageModuleError with the loader's reason when it cannot.
const ImageCodec& imageCodec();

}  // namespace lightpath
