#pragma once
// Building the stress rows' scenes in code: an object with its own material.
#include <cstdint>
#include <string>

#include "materials/phong_material.h"
#include "scene/scene.h"

namespace lightpath::stress {

// Adds `material` under `name` and an object of that name using it; returns the object's index.
inline std::uint32_t addObject(Scene& scene, const std::string& name, PhongMaterial material) {
    material.name = name;
    scene.materials.push_back(material);
    scene.objects.push_back({name, static_cast<std::uint32_t>(scene.materials.size() - 1)});
    return static_cast<std::uint32_t>(scene.objects.size() - 1);
}

}  // namespace lightpath::stress
