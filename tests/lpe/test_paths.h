#pragma once
// Paths built by hand for the tests, independently of lpe::parsePath (which is under test too).
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "lpe/event.h"

namespace lpe_test {

inline lpe::Event event(lpe::EventType type, lpe::Scatter scatter = lpe::Scatter::None,
                        std::string label = {}) {
    return lpe::Event{type, scatter, std::move(label)};
}

// Heckbert's letters: E camera, L emitter, B background, D G S s reflections, R T unscattered.
inline lpe::Event compactEvent(char c) {
    using lpe::EventType;
    using lpe::Scatter;
    switch (c) {
        case 'E': return event(EventType::Camera);
        case 'L': return event(EventType::Emitter);
        case 'B': return event(EventType::Background);
        case 'D': return event(EventType::Reflection, Scatter::Diffuse);
        case 'G': return event(EventType::Reflection, Scatter::Glossy);
        case 'S': return event(EventType::Reflection, Scatter::Specular);
        case 's': return event(EventType::Reflection, Scatter::Straight);
        case 'R': return event(EventType::Reflection);
        case 'T': return event(EventType::Transmission);
        default: throw std::invalid_argument(std::string("test path letter ") + c);
    }
}

// For failure messages: type, scattering and label as letters.
inline std::string describe(const lpe::Event& e) {
    return std::string(1, lpe::letter(e.type)) + lpe::letter(e.scatter) + "'" + e.label + "'";
}

inline lpe::Path compactPath(std::string_view letters) {
    lpe::Path path;
    for (const char c : letters) path.push_back(compactEvent(c));
    return path;
}

inline // Every compact string over `alphabet` of length 0..maxLength.
std::vector<std::string> allStrings(const std::string& alphabet, std::size_t maxLength) {
    std::vector<std::string> result{""};
    for (std::size_t begin = 0, length = 1; length <= maxLength; ++length) {
        const std::size_t end = result.size();
        for (std::size_t i = begin; i < end; ++i) {
            for (const char c : alphabet) result.push_back(result[i] + c);
        }
        begin = end;
    }
    return result;
}

}  // namespace lpe_test
