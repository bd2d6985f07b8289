#pragma once
// A light a scene file declares in [[lights]] without a shape of its own (a point light; a spot or
// a directional light would be others): its name labels its `L` events, its position places it in
// drawings and bounds, and it makes the light source the integrators sample (lights/light.h). A
// new type is its own file: description, source and its registered LightType (lights/light_type.h).
// Quad and sphere lights are not here: they are emissive objects with geometry.
#include <cstdint>
#include <memory>
#include <string>

#include "math/types.h"
#include "util/polymorphic_value.h"

namespace lightpath {

class Light;

class SceneLight {
public:
    virtual ~SceneLight() = default;

    std::string name;

    virtual std::unique_ptr<SceneLight> clone() const = 0;
    // Where the light is, for drawings and scene bounds.
    virtual Vec3 position() const = 0;
    // The source the integrators sample; `index` is this light's place in Scene::lights, the
    // index of its events (Subject::SceneLight).
    virtual std::unique_ptr<Light> makeSource(std::uint32_t index) const = 0;

protected:
    SceneLight() = default;
    explicit SceneLight(std::string lightName) : name(std::move(lightName)) {}
    SceneLight(const SceneLight&) = default;
    SceneLight& operator=(const SceneLight&) = default;
};

// A scene's light: owned, polymorphic, and copied with the scene.
using LightSlot = PolymorphicValue<SceneLight>;

}  // namespace lightpath
