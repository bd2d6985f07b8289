// `[[meshes]]`: a Wavefront OBJ file (shapes/obj_loader.h) placed in the scene, read and
// registered here like every shape kind (docs/extending.md). Its faces become triangles of
// SceneGeometry's triangle array; each MTL material its faces use becomes a scene material and
// the faces using it one object.
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "shapes/mesh_placement.h"
#include "shapes/obj_loader.h"
#include "scene/scene_loader.h"
#include "scene/shape_type.h"

namespace lightpath {
namespace {

// Every MTL material used becomes one scene object (labelled by the mesh's name, else by the
// material's MTL name); `material` puts the whole mesh in one scene material. Errors and warnings
// about the OBJ file are located at `file`.
void addMesh(const ParameterValues& values, SceneBuilder& scene) {
    const std::filesystem::path file = scene.folder() / values.text("file");
    ObjMesh mesh;
    try {
        mesh = loadObj(file);
    } catch (const SceneError& e) {
        values.fail("file", e.what());
    }
    const std::string name = values.has("name") ? values.text("name") : std::string();
    const bool override = values.has("material");
    const MeshPlacement placement = placementOf(values);
    // What other tools forgive is a warning naming the OBJ file and line, never a refusal: a
    // missing material library, a `usemtl` no library defines (its faces take the mesh's
    // `material`, else a grey), a material name that is no label (it is given one).
    const auto at = [&](std::size_t line) {
        std::string where = file.string();
        if (line > 0) where.append(":").append(std::to_string(line));
        return where.append(": ");
    };
    const std::string instead = override ? "the mesh's `material` is used" : "its faces are grey";
    for (const ObjLineRef& library : mesh.missingLibraries)
        scene.warn(values.located("file", at(library.line) + "cannot open material library \"" +
                                              printableName(library.text) + "\"; " + instead));
    for (const ObjLineRef& unknown : mesh.unknownMaterials)
        scene.warn(values.located("file", at(unknown.line) + "usemtl \"" + printableName(unknown.text) +
                                              "\" names no material of its material libraries; " + instead));

    // `map_Kd` (`map_Ke`) makes the material's kd (emission) a texture, relative to the OBJ's
    // folder, times Kd (Ke) (the MTL spec; a black Kd or Ke, which some tools write beside a map,
    // counts as white). One that cannot be read is a warning, as everything else other tools
    // forgive: Kd (Ke) alone is used.
    // A map's image, relative to the OBJ's folder; null, and a warning ending `instead`, when it
    // cannot be read.
    const auto openMap = [&](const std::string& image, std::uint32_t mtlIndex, const char* statement,
                             const std::string& instead, TextureColorSpace colorSpace) {
        std::string error;
        std::shared_ptr<const Texture> texture =
            openTexture({(file.parent_path() / image).string(), nullptr, colorSpace}, error);
        if (!texture)
            scene.warn(values.located("file", at(mesh.materialLines[mtlIndex]) + "material \"" +
                                                  mesh.materials[mtlIndex].name + "\": cannot read its " + statement +
                                                  " \"" + printableName(image) + "\" (" + error + "); " + instead));
        return texture;
    };
    const auto textured = [&](const ColorParameter& constant, const std::string& image, std::uint32_t mtlIndex,
                              const char* statement, const char* colour) -> std::optional<ColorParameter> {
        if (image.empty()) return std::nullopt;
        std::shared_ptr<const Texture> texture =
            openMap(image, mtlIndex, statement, std::string(colour) + " is used", TextureColorSpace::automatic);
        if (!texture) return std::nullopt;
        const Rgb tint = constant.black() ? Rgb{1.0f} : constant.constant();
        return ColorParameter(std::move(texture), tint, 1.0f, true);
    };
    const auto withTextures = [&](const PhongMaterial& mtl, std::uint32_t mtlIndex) {
        PhongMaterial material = mtl;
        if (auto kd = textured(mtl.kd, mesh.diffuseTextures[mtlIndex], mtlIndex, "map_Kd", "Kd")) {
            material.kd = std::move(*kd);
            material.textured = true;  // shading points then carry their uv
        }
        // The emission's light finds its own uvs (lights/area_light.h): no shading point reads
        // it, so `textured` stays as kd left it.
        if (auto ke = textured(mtl.emission, mesh.emissionTextures[mtlIndex], mtlIndex, "map_Ke", "Ke"))
            material.emission = std::move(*ke);
        if (const std::string& image = mesh.alphaTextures[mtlIndex]; !image.empty()) {
            // `map_d`: the dissolve map, a cut-out (materials/alpha.h): its alpha channel, else
            // its grey, the fraction of rays the surface stops (linear: a mask's texels are data).
            if (auto texture = openMap(image, mtlIndex, "map_d", "the surface is opaque", TextureColorSpace::linear))
                material.alpha = std::make_shared<const Alpha>(std::move(texture), 1.0f, std::nullopt, TextureSampling{});
        }
        return material;
    };

    // Scene object of each MTL material index, created on first use, in order of first use.
    std::vector<std::uint32_t> objectOf(mesh.materials.size() + 1, kNoMeshMaterial);
    const auto objectFor = [&](std::uint32_t mtlIndex) {
        // With `material`, the whole mesh is one object.
        const std::size_t slot = override || mtlIndex == kNoMeshMaterial ? mesh.materials.size() : mtlIndex;
        if (objectOf[slot] != kNoMeshMaterial) return objectOf[slot];
        if (override) {
            objectOf[slot] = scene.addShapeObject(values);
        } else if (mtlIndex == kNoMeshMaterial) {
            objectOf[slot] = scene.addObject(name, scene.sceneMaterial(defaultMeshMaterial()));
        } else {
            const PhongMaterial& mtl = mesh.materials[mtlIndex];
            if (const std::optional<std::string>& original = mesh.originalNames[mtlIndex])
                scene.warn(values.located("file", at(mesh.materialLines[mtlIndex]) + "material \"" +
                                                      printableName(*original) + "\" is no label of " +
                                                      std::string(kNameCharacters) + "; it is labelled \"" + mtl.name + "\""));
            objectOf[slot] = scene.addObject(name, scene.sceneMaterial(withTextures(mtl, mtlIndex)));
        }
        return objectOf[slot];
    };

    if (mesh.degenerateDropped > 0)
        scene.warn(values.located("file", std::to_string(mesh.degenerateDropped) + " faces without area were left out"));
    const bool smooth = !mesh.normals.empty();
    const bool hasUvs = !mesh.uvs.empty();
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
        const Triangle& t = mesh.triangles[i];
        const Triangle placed = placeTriangle(placement, t, objectFor(t.object), values, file, i);
        if (smooth) {
            scene.addTriangle(placed, placement.normals(mesh.normals[i]));
        } else {
            scene.addTriangle(placed);
        }
        if (hasUvs && mesh.uvs[i].given) scene.setTriangleUvs(mesh.uvs[i]);
    }
}

}  // namespace
}  // namespace lightpath

// Rank 1001: meshes are numbered last, after the triangles, mesh by mesh.
LIGHTPATH_REGISTER_SHAPE(lightpath::ShapeType{
    {"shape", "mesh", "a Wavefront OBJ file and its MTL materials, placed by scale, rotate_y and translate",
     {{"name", lightpath::ParameterType::Name, "", "", {}, "the label of every part; default: each part's material's name"},
      {"file", lightpath::ParameterType::Text, "", "", {}, "an OBJ file, relative to the scene file; its `mtllib` relative to the OBJ", true},
      {"material", lightpath::ParameterType::Name, "", "", {},
       "a material of `[materials]`: the whole mesh in it, ignoring the MTL"},
      {"scale", lightpath::ParameterType::PerAxis, "", "1", lightpath::kPositive,
       "applied first, about the file's origin: one factor for every axis or one per axis"},
      {"rotate_y", lightpath::ParameterType::Number, "degrees", "0", {}, "then a turn about the y axis (x towards −z)"},
      {"translate", lightpath::ParameterType::Point, "m", "[0, 0, 0]", {}, "then a move by this vector"},
      lightpath::kShapeInteriorParameter},
     ""},
    1001, "meshes", lightpath::addMesh, lightpath::ShapeStorage::triangles})
