#pragma once
// The alphabet of light paths (DESIGN.md): every event is a tuple (event type, scattering type,
// label). Standard library only: this header knows nothing of rays.
#include <cstdint>
#include <string>
#include <vector>

namespace lpe {

// Event types, in Heckbert/OSL letters: E (camera, OSL's C), R, T, L (emitter), B (background).
enum class EventType : std::uint8_t { Camera, Reflection, Transmission, Emitter, Background };
inline constexpr int kEventTypeCount = 5;

// Scattering types: D diffuse, G glossy, S perfectly specular, s straight (pass-through),
// and None for events that do not scatter (camera, emitters, background; written `_`).
enum class Scatter : std::uint8_t { Diffuse, Glossy, Specular, Straight, None };
inline constexpr int kScatterCount = 5;

char letter(EventType type);   // 'E' 'R' 'T' 'L' 'B'
char letter(Scatter scatter);  // 'D' 'G' 'S' 's' '_'

// One event of a path as text knows it. An empty label means "no label".
struct Event {
    EventType type = EventType::Camera;
    Scatter scatter = Scatter::None;
    std::string label;

    bool operator==(const Event&) const = default;
};

// A path runs from the eye (first event) to an emitter or the background (last event).
using Path = std::vector<Event>;

}  // namespace lpe
