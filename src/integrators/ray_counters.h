#pragma once
#include <cstdint>

namespace lightpath {

// Rays cast by kind, kept per worker thread and summed at the end (`--stats`).
struct RayCounters {
    std::uint64_t camera = 0;
    std::uint64_t shadow = 0;
    std::uint64_t reflection = 0;
    std::uint64_t refraction = 0;
    std::uint64_t nonFinite = 0;  // contributions dropped because they were NaN or infinite

    std::uint64_t total() const { return camera + shadow + reflection + refraction; }

    RayCounters& operator+=(const RayCounters& o) {
        camera += o.camera;
        shadow += o.shadow;
        reflection += o.reflection;
        refraction += o.refraction;
        nonFinite += o.nonFinite;
        return *this;
    }
};

}  // namespace lightpath
