#pragma once
// Which event ends a path at an emitting surface: the one answer the light set (the events it
// emits), the command line's label placement (what it accepts and suggests) and serve's light
// groups (what it offers) read, so the three cannot disagree.
#include <cstdint>
#include <optional>

#include "lpe/event.h"
#include "scene/scene.h"

namespace lightpath {

// L for a [[lights]] quad or sphere, O (OSL's object emission) for any other surface whose material
// emits; none when `object` emits nothing.
inline std::optional<lpe::EventType> emissionEventOf(const Scene& scene, std::uint32_t object) {
    const SceneObject& o = scene.objects[object];
    if (scene.materials[o.material]->emission.black()) return std::nullopt;
    return o.declaredLight ? lpe::EventType::Emitter : lpe::EventType::ObjectEmission;
}

}  // namespace lightpath
