#pragma once
// Opens the image module, liblightpath-image.so (io/image_codec.h), on first use: only a scene
// with a texture loads OpenImageIO and its ~260 shared libraries, while the scene is read.
//
// Where it is looked for: $LIGHTPATH_IMAGE_MODULE when set (and nowhere else), else next to the
// running executable, else where the build tree made it (for test executables in sub-folders).
#include <stdexcept>

#include "io/image_codec.h"

namespace lightpath {

// The module is missing, cannot be loaded, or is not the one this binary was built with.
class ImageModuleError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// The loaded module's codec, loading it on the first call (once per process, thread-safe).
// Throws ImageModuleError with the loader's reason when it cannot.
const ImageCodec& imageCodec();

}  // namespace lightpath
