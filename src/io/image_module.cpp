#include "io/image_module.h"

#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <string>
#include <system_error>
#include <vector>

namespace lightpath {
namespace {

namespace fs = std::filesystem;

constexpr const char* kModuleFileName = "liblightpath-image.so";
constexpr const char* kModuleVariable = "LIGHTPATH_IMAGE_MODULE";

std::vector<fs::path> placesToLook() {
    if (const char* chosen = std::getenv(kModuleVariable); chosen != nullptr && *chosen != '\0') return {chosen};
    std::vector<fs::path> places;
    std::error_code error;
    const fs::path executable = fs::read_symlink("/proc/self/exe", error);
    if (!error) places.push_back(executable.parent_path() / kModuleFileName);
#ifdef LIGHTPATH_IMAGE_MODULE_BUILD_PATH
    places.emplace_back(LIGHTPATH_IMAGE_MODULE_BUILD_PATH);
#endif
    return places;
}

// The module's path: the first of placesToLook that exists; throws ImageModuleError naming every
// place it looked.
fs::path locateImageModule() {
    const std::vector<fs::path> places = placesToLook();
    std::string looked;
    for (const fs::path& place : places) {
        std::error_code error;
        if (fs::is_regular_file(place, error)) return place;
        looked += (looked.empty() ? "" : ", ") + place.string();
    }
    throw ImageModuleError(std::string("cannot read textures: the image module ") + kModuleFileName +
                           " is not at " + looked + " (it is built with lightpath: cmake --build build --target " +
                           "lightpath-image; or set " + kModuleVariable + " to its path)");
}

struct LoadResult {
    const ImageCodec* codec = nullptr;
    std::string error;  // why codec is null
};

LoadResult load() {
    fs::path path;
    try {
        path = locateImageModule();
    } catch (const ImageModuleError& e) {
        return {nullptr, e.what()};
    }
    // Lazy binding, as for a linked library: symbols are resolved when first called. Never
    // closed: OpenImageIO keeps threads and static state for the life of the process.
    void* handle = dlopen(path.c_str(), RTLD_LAZY | RTLD_LOCAL);
    if (handle == nullptr) return {nullptr, "cannot load the image module: " + std::string(dlerror())};
    void* entry = dlsym(handle, kImageCodecEntryPoint);
    if (entry == nullptr)
        return {nullptr, path.string() + ": not lightpath's image module (it has no " + kImageCodecEntryPoint + ")"};
    const ImageCodec* codec = reinterpret_cast<ImageCodecEntryPoint>(entry)(kImageCodecInterfaceVersion);
    if (codec == nullptr)
        return {nullptr, path.string() + ": an image module from another build of lightpath (interface version " +
                             std::to_string(kImageCodecInterfaceVersion) + " expected); rebuild it"};
    return {codec, {}};
}

// One load per process, on the first thread that asks.
const LoadResult& loaded() {
    static std::once_flag once;
    static LoadResult result;
    std::call_once(once, [] { result = load(); });
    return result;
}

}  // namespace

const ImageCodec& imageCodec() {
    const LoadResult& result = loaded();
    if (result.codec == nullptr) throw ImageModuleError(result.error);
    return *result.codec;
}

}  // namespace lightpath
