#pragma once
// Wavefront OBJ/MTL import through tinyobjloader: triangles (polygons fanned), vertex normals when
// the file has them, and MTL materials mapped to the Phong material (table in scenes/README.md).
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/shapes.h"
#include "materials/phong_material.h"

namespace lightpath {

inline constexpr std::uint32_t kNoMeshMaterial = 0xffffffffu;

// A name or path an OBJ file gives, and the line (1-based) that gives it; 0 when no line does.
struct ObjLineRef {
    std::string text;
    std::size_t line = 0;
};

struct ObjMesh {
    std::vector<PhongMaterial> materials;  // the MTL's, in file order, named by their MTL name
    // `object` of each triangle is an index into `materials`, or kNoMeshMaterial (no usemtl).
    std::vector<Triangle> triangles;
    // Empty when the file has no normals, else one per triangle (zero for faces without `vn`).
    std::vector<TriangleNormals> normals;
    // Empty when the file has no texture coordinates, else one per triangle (`given` false for
    // faces without `vt`).
    std::vector<TriangleUvs> uvs;
    // Per material: its `map_Kd` image as the MTL names it (empty: none); the mesh's reader opens
    // it relative to the OBJ file's folder and makes it the material's kd texture.
    std::vector<std::string> diffuseTextures;
    // Per material: its `map_Ke` image likewise (empty: none), the material's emission texture.
    std::vector<std::string> emissionTextures;
    // Per material: its `map_d` (dissolve) image likewise (empty: none), the material's alpha.
    std::vector<std::string> alphaTextures;
    std::size_t degenerateDropped = 0;  // faces without area: they have no normal to shade with
    // Material libraries named by `mtllib` lines that could not be opened (paths as looked for),
    // and `usemtl` names that no library read defines, each with the OBJ line naming it. Faces of
    // either have no MTL material (kNoMeshMaterial): the scene loader warns and gives them the
    // scene's material or a grey.
    std::vector<ObjLineRef> missingLibraries;
    std::vector<ObjLineRef> unknownMaterials;
    // Per material: its name as the MTL file spells it when that is no LPE label (empty, spaced,
    // non-ASCII, Latin-1), else nullopt; `materials[i].name` is then its label (labelFromName).
    std::vector<std::optional<std::string>> originalNames;
    // Per material: the first OBJ line whose `usemtl` names it (0: none does).
    std::vector<std::size_t> materialLines;
};

// A name for LPE labels made of any text: every run of characters other than letters, digits,
// '_', '-' and '.' becomes one '_' (spaces at either end are dropped), "unnamed" if nothing is left.
std::string labelFromName(std::string_view name);
// `text` as a terminal shows it safely: bytes outside printable ASCII as \xHH.
std::string printableName(std::string_view text);

// What faces without an MTL material get when the scene gives the mesh no `material`.
PhongMaterial defaultMeshMaterial();

// Throws SceneError naming the OBJ file, or an MTL file that is broken, when they cannot be read.
// A missing MTL file, an unknown `usemtl` and a material name that is no label are not errors
// (ObjMesh::missingLibraries, unknownMaterials, originalNames): other tools open such files.
ObjMesh loadObj(const std::filesystem::path& file);
// The same from memory (for fuzzing and tests): `mtlText` answers every mtllib line; `file` only
// names the mesh in errors.
ObjMesh loadObjFromText(const std::string& objText, const std::string& mtlText, const std::filesystem::path& file);

// MTL to Phong: Ka Kd Ks Ns as they are; illum 3/5 makes Ks the mirror weight kr; illum 4/6/7/9
// makes Tf (else 1 - d) the transmission weight kt with Ni the index of refraction; Ke emission.
PhongMaterial phongFromMtl(const std::string& name, const float ambient[3], const float diffuse[3],
                           const float specular[3], const float transmittance[3], const float emission[3],
                           float shininess, float ior, float dissolve, int illum);

}  // namespace lightpath
