#include "accel/simd_path.h"

#include <atomic>
#include <stdexcept>
#include <string>

#include "accel/simd.h"

namespace lightpath::simd {
namespace {

Path detect() {
#if defined(LIGHTPATH_AVX2_PATH)
    // libgcc's check includes the operating system's support for the AVX registers (XGETBV).
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") ? Path::Avx2 : Path::Baseline;
#else
    return Path::Baseline;
#endif
}

std::atomic<Path>& chosen() {
    static std::atomic<Path> path{bestPath()};
    return path;
}

}  // namespace

Path bestPath() {
    static const Path best = detect();
    return best;
}

bool supported(Path path) { return path == Path::Baseline || bestPath() == Path::Avx2; }

Path activePath() { return chosen().load(std::memory_order_relaxed); }

void setPath(Path path) {
    if (!supported(path))
        throw std::invalid_argument("SIMD path " + std::string(pathName(path)) + " is not supported by this processor");
    chosen().store(path, std::memory_order_relaxed);
}

std::string_view pathName(Path path) {
    if (path == Path::Avx2) return "avx2";
#ifdef LIGHTPATH_SSE2
    return "sse2";
#else
    return "portable";
#endif
}

}  // namespace lightpath::simd
