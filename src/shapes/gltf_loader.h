#pragma once
// glTF 2.0 import (`.gltf`, `.glb`) through tinygltf (Debian's libtinygltf-dev): the default scene's
// nodes, their transforms (matrix or translation-rotation-scale, composed down the hierarchy)
// applied to triangles and normals; metallic-roughness materials as `microfacet`, transmission as
// glass; emissive materials; perspective cameras; KHR_lights_punctual lights as plain data (the
// scene loader adds them through the light registry). Base-colour, metallic-roughness, normal and
// emissive textures are opened through materials/texture.h (OpenImageIO): files beside the glTF,
// data URIs and .glb bufferViews from memory; a triangle's uvs are the TEXCOORD_n its material's
// textures name (one set per material). Names become LPE labels (labelFromName),
// collisions numbered.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "geometry/shapes.h"
#include "materials/material.h"
#include "scene/camera.h"

namespace lightpath {

// One label given to a glTF object, material, light or camera whose name is no label (or is
// another's), for the mapping the loader prints.
struct GltfRenaming {
    std::string what;      // e.g. "material 2"
    std::string original;  // as the file spells it
    std::string label;
};

// A part of the scene with one material: a node's mesh primitives that share a material.
struct GltfObject {
    std::string label;           // the node's name, else its mesh's, else "node-K"
    std::uint32_t material = 0;  // index into GltfModel::materials
};

enum class GltfLightKind { point, spot, directional };

// A KHR_lights_punctual light placed by its node, its intensity as the file gives it: candela
// (point, spot) or lux (directional); shapes/gltf.cpp makes it W/sr or W/m^2 (docs/design.md).
struct GltfLight {
    std::string label;
    GltfLightKind kind = GltfLightKind::point;
    Vec3 position{0.0f};
    Vec3 direction{0.0f, 0.0f, -1.0f};  // where it shines (spot, directional): the node's -z
    Rgb intensity{1.0f};                // colour times intensity
    float innerConeRadians = 0.0f, outerConeRadians = 0.0f;
};

struct GltfCamera {
    std::string label;
    CameraDescription camera;
};

struct GltfModel {
    std::vector<MaterialSlot> materials;  // named by label; the last may be the glTF default
    // Per material: the absorption sigma_a of the medium its surface bounds (KHR_materials_volume),
    // or none (no extension, a thin wall, an opaque surface, or nothing absorbed).
    std::vector<std::optional<Rgb>> absorption;
    std::vector<GltfObject> objects;
    std::vector<Triangle> triangles;      // `object` indexes `objects`
    std::vector<TriangleNormals> normals; // empty, or one per triangle (zero: shade flat)
    std::vector<TriangleUvs> uvs;         // empty (no material is textured), or one per triangle
    std::vector<TriangleTangents> tangents;  // empty, or one per triangle (zero: none; TANGENT)
    std::vector<TriangleColors> colors;      // empty, or one per triangle (white: none; COLOR_0)
    std::vector<GltfLight> lights;
    std::vector<GltfCamera> cameras;
    std::vector<GltfRenaming> renamed;
    std::vector<std::string> warnings;    // each begins with the file's name
    std::size_t degenerateDropped = 0;
};

// Throws SceneError naming the file and what was expected ("FILE: meshes[0].primitives[1]:
// accessor 3: expected ..."), never a partial model.
GltfModel loadGltf(const std::filesystem::path& file);
// The same from memory (fuzzing, tests): binary glTF when it starts with "glTF", else JSON;
// `file` names it in errors and external buffers are looked up beside it.
GltfModel loadGltfFromMemory(const std::string& bytes, const std::filesystem::path& file);

}  // namespace lightpath
