#pragma once
// A light type a scene names with `[[lights]] type = "..."`: its schema and how it adds itself to
// the scene. Each type's .cpp registers its own with LIGHTPATH_REGISTER_LIGHT.
#include "schema/parameter_values.h"
#include "schema/registry.h"
#include "scene/scene_builder.h"

namespace lightpath {

struct LightType {
    TypeSchema schema;
    int rank = 0;  // listing order; rank 0 is the default type
    // May refuse a combination with values.fail(key, ...).
    void (*addTo)(const ParameterValues& values, SceneBuilder& scene) = nullptr;
};

using LightRegistry = TypeRegistry<LightType>;

// The label 'ambient' belongs to the ambient term of the illumination formula (docs/design.md):
// refused as a light's `name`, located at it.
inline void checkLightName(const ParameterValues& values) {
    if (values.has("name") && values.text("name") == "ambient") {
        values.fail("name", "expected a light name other than \"ambient\", which is reserved for the ambient term");
    }
}

// The `name` parameter every light type has.
inline constexpr Parameter kLightNameParameter{
    "name", ParameterType::Name, "", "", {}, "its label in light paths (`<L'name'>`); not `\"ambient\"`"};

}  // namespace lightpath

#define LIGHTPATH_REGISTER_LIGHT(...) \
    namespace { const ::lightpath::Registrar<::lightpath::LightType> LIGHTPATH_SCHEMA_CONCAT(kLightRegistrar, __COUNTER__){__VA_ARGS__}; }
