#pragma once
// The alphabet of light paths (docs/design.md): every event is a tuple (event type, scattering type,
// label). Standard library only: this header knows nothing of rays.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace lpe {

// Event types, in OSL's letters (Heckbert's E for the camera): E camera (OSL's C), R reflection,
// T transmission, L light, B background, V volume, O emission from an object that is not a light.
// New types are appended, so code that switches on the first five keeps its meaning.
enum class EventType : std::uint8_t { Camera, Reflection, Transmission, Emitter, Background, Volume, ObjectEmission };
inline constexpr int kEventTypeCount = 7;

// Scattering types: D diffuse, G glossy, S perfectly specular, s straight (pass-through),
// and None for events that do not scatter (camera, emitters, background; written `_`, OSL's `x`).
enum class Scatter : std::uint8_t { Diffuse, Glossy, Specular, Straight, None };
inline constexpr int kScatterCount = 5;

// The one table of LPE letters: every parser and printer in lpe/ reads it. Indexed by enumerator.
inline constexpr std::array<char, kEventTypeCount> kEventTypeLetters = {'E', 'R', 'T', 'L', 'B', 'V', 'O'};
inline constexpr std::array<char, kScatterCount> kScatterLetters = {'D', 'G', 'S', 's', '_'};
// Letters read as well as the table's: OSL's C for the camera, OSL's x for "no scattering".
inline constexpr char kCameraAlias = 'C';
inline constexpr char kNoScatterAlias = 'x';

constexpr char letter(EventType type) { return kEventTypeLetters[static_cast<std::size_t>(type)]; }
constexpr char letter(Scatter scatter) { return kScatterLetters[static_cast<std::size_t>(scatter)]; }

// The event type a letter names (E or C, R, T, L, B, V, O), if any.
constexpr std::optional<EventType> eventTypeOf(char c) {
    if (c == kCameraAlias) return EventType::Camera;
    for (std::size_t i = 0; i < kEventTypeLetters.size(); ++i)
        if (kEventTypeLetters[i] == c) return static_cast<EventType>(i);
    return std::nullopt;
}

// The scattering a letter names (D, G, S, s, _ or x), if any.
constexpr std::optional<Scatter> scatterOf(char c) {
    if (c == kNoScatterAlias) return Scatter::None;
    for (std::size_t i = 0; i < kScatterLetters.size(); ++i)
        if (kScatterLetters[i] == c) return static_cast<Scatter>(i);
    return std::nullopt;
}

// Events that end a path and do not scatter: camera, light, background and object emission match
// as if their scattering were None, whatever it says (Automaton::symbol).
constexpr bool scatters(EventType type) {
    return type == EventType::Reflection || type == EventType::Transmission || type == EventType::Volume;
}

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
