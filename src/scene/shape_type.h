#pragma once
// A shape kind a scene declares with `[[SECTION]]` (e.g. `[[disks]]`): its schema and how it adds
// itself to the scene. Each kind's file in src/shapes/ defines its geometry (a ShapeOps table,
// geometry/shape.h) and registers its type here with LIGHTPATH_REGISTER_SHAPE.
#include <string_view>

#include "schema/parameter.h"
#include "schema/parameter_values.h"
#include "schema/registry.h"
#include "scene/scene_builder.h"

namespace lightpath {

// What a kind's declarations become in SceneGeometry: shapes of its table (spheres, planes,
// disks: records of a ShapeOps table, which the conformance kit checks as shapes), or triangles
// (`[[triangles]]`, `[[meshes]]`: the triangle array with its own fast paths, checked by
// tests/accel and, as a light, through the quad light's two triangles).
enum class ShapeStorage : bool { records, triangles };

struct ShapeType {
    TypeSchema schema;          // family "shape"
    int rank = 0;               // listing and loading order: objects are numbered in it
    std::string_view section;   // the scene file's array of tables, e.g. "disks"
    // Adds the declaration's object and shape; may refuse a combination with values.fail(key, ...).
    void (*addTo)(const ParameterValues& values, SceneBuilder& scene) = nullptr;
    ShapeStorage storage = ShapeStorage::records;
};

using ShapeRegistry = TypeRegistry<ShapeType>;

// The keys every shape declaration has, as spheres, planes and triangles have them (a mesh's
// `material` is optional: its MTL gives one).
inline constexpr Parameter kShapeNameParameter{
    "name", ParameterType::Name, "", "", {}, "its label in light paths; default: its material's name"};
inline constexpr Parameter kShapeMaterialParameter{
    "material", ParameterType::Name, "", "", {}, "a material of `[materials]`", true};
// What fills a closed shape (a sphere, a closed mesh): a medium of `[media]`. The loader resolves it
// for every object the declaration adds.
inline constexpr Parameter kShapeInteriorParameter{
    "interior", ParameterType::Name, "", "", {}, "a medium of `[media]` filling its inside; default: none (vacuum)"};

}  // namespace lightpath

#define LIGHTPATH_REGISTER_SHAPE(...) \
    namespace { const ::lightpath::Registrar<::lightpath::ShapeType> LIGHTPATH_SCHEMA_CONCAT(kShapeRegistrar, __COUNTER__){__VA_ARGS__}; }
