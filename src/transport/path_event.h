#pragma once
// The vocabulary of a light path's events, below the lights and the integrators that both speak it:
// what an event touched, the event itself, and how many a recorded path may hold.
#include <cstddef>
#include <cstdint>

#include "lpe/event.h"
#include "math/types.h"

namespace lightpath {

// What an event touched.
enum class Subject : std::uint8_t {
    None,        // the camera, the background
    Object,      // scene object `index`: a surface it scattered from, or an emissive surface
    SceneLight,  // scene.lights[index], a light without a shape of its own
    Ambient,     // the ambient term ka * Ia
    Medium,      // scene medium `index`: a scattering inside it (a V event)
};

struct PathEvent {
    lpe::EventType type = lpe::EventType::Camera;
    lpe::Scatter scatter = lpe::Scatter::None;
    Subject subject = Subject::None;
    std::uint32_t index = 0;
    // Where it happened, in world space: the eye, a hit point, a point on a light; for the
    // background, a point far along the escaping ray. Only `explain` and `serve` read it.
    Vec3 position{0.0f};
};

// Longest recorded path: the camera, kMaxDepth specular bounces, one surface and the light.
inline constexpr int kMaxDepth = 64;
inline constexpr std::size_t kMaxPathEvents = kMaxDepth + 4;

}  // namespace lightpath
