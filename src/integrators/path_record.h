#pragma once
// The events of the light path currently being traced, kept on a fixed-size stack so recording
// costs no allocation. Only `lightpath explain` ever turns them into strings.
#include <array>
#include <cassert>
#include <cstddef>
#include <cstdint>

#include "lpe/event.h"
#include "math/random.h"
#include "math/types.h"

namespace lightpath {

// What an event touched.
enum class Subject : std::uint8_t {
    None,        // the camera, the background
    Object,      // scene object `index`: a surface it scattered from, or an emissive surface
    SceneLight,  // scene.lights[index], a light without a shape of its own
    Ambient,     // the ambient term ka * Ia
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

class PathRecord {
public:
    void push(const PathEvent& event) {
        assert(size_ < events_.size());
        events_[size_++] = event;
    }
    void pop() { --size_; }
    std::size_t size() const { return size_; }
    // A hash of the events so far: names the vertex this path has reached.
    std::uint64_t key() const {
        std::uint64_t key = size_;
        for (std::size_t i = 0; i < size_; ++i) {
            const PathEvent& e = events_[i];
            key = mixBits(key ^ ((std::uint64_t{static_cast<std::uint8_t>(e.type)} << 40) |
                                 (std::uint64_t{static_cast<std::uint8_t>(e.scatter)} << 32) | e.index));
        }
        return key;
    }
    const PathEvent& operator[](std::size_t i) const { return events_[i]; }

private:
    std::array<PathEvent, kMaxPathEvents> events_{};
    std::size_t size_ = 0;
};

}  // namespace lightpath
