#include "io/image_module.h"

#include <dlfcn.h>

#include <cstdlib>
#include <chrono>
#include <future>
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

// One load per process, started in the background or on first use, whichever comes first. The
// future of a background load joins its thread when destroyed at exit, so a process that never
// writes (an interrupted render) still waits for the loader to finish before unloading anything.
class ModuleLoader {
public:
    void startInBackground() {
        const std::lock_guard lock(mutex_);
        if (result_.valid()) return;
        try {
            result_ = std::async(std::launch::async, load).share();
        } catch (const std::system_error&) {
            result_ = std::async(std::launch::deferred, load).share();  // no thread to spare: load on use
        }
    }

    void await() {
        std::shared_future<LoadResult> started;
        {
            const std::lock_guard lock(mutex_);
            started = result_;
        }
        // Only a load running on its thread is waited for; waiting on a deferred one would run it.
        if (started.valid() && started.wait_for(std::chrono::seconds(0)) != std::future_status::deferred) started.wait();
    }

    const LoadResult& result() {
        std::shared_future<LoadResult> result;
        {
            const std::lock_guard lock(mutex_);
            if (!result_.valid()) result_ = std::async(std::launch::deferred, load).share();
            result = result_;
        }
        return result.get();  // the shared state outlives this copy: result_ holds it
    }

private:
    std::mutex mutex_;
    std::shared_future<LoadResult> result_;
};

ModuleLoader& loader() {
    static ModuleLoader instance;
    return instance;
}

}  // namespace

fs::path locateImageModule() {
    const std::vector<fs::path> places = placesToLook();
    std::string looked;
    for (const fs::path& place : places) {
        std::error_code error;
        if (fs::is_regular_file(place, error)) return place;
        looked += (looked.empty() ? "" : ", ") + place.string();
    }
    throw ImageModuleError(std::string("cannot read or write images: the image module ") + kModuleFileName +
                           " is not at " + looked + " (it is built with lightpath: cmake --build build --target " +
                           "lightpath-image; or set " + kModuleVariable + " to its path)");
}

void preloadImageModule() { loader().startInBackground(); }

void awaitImageModule() { loader().await(); }

const ImageCodec& imageCodec() {
    const LoadResult& loaded = loader().result();
    if (loaded.codec == nullptr) throw ImageModuleError(loaded.error);
    return *loaded.codec;
}

}  // namespace lightpath
