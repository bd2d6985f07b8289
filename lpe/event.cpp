#include "lpe/event.h"

namespace lpe {

char letter(EventType type) {
    switch (type) {
        case EventType::Camera: return 'E';
        case EventType::Reflection: return 'R';
        case EventType::Transmission: return 'T';
        case EventType::Emitter: return 'L';
        case EventType::Background: return 'B';
    }
    return '?';
}

char letter(Scatter scatter) {
    switch (scatter) {
        case Scatter::Diffuse: return 'D';
        case Scatter::Glossy: return 'G';
        case Scatter::Specular: return 'S';
        case Scatter::Straight: return 's';
        case Scatter::None: return '_';
    }
    return '?';
}

}  // namespace lpe
