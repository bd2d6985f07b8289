#pragma once
// Wavefront OBJ/MTL import through tinyobjloader: triangles (polygons fanned), vertex normals when
// the file has them, and MTL materials mapped to the Phong material (table in scenes/README.md).
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "geometry/shapes.h"
#include "materials/phong_material.h"

namespace lightpath {

inline constexpr std::uint32_t kNoMeshMaterial = 0xffffffffu;

struct ObjMesh {
    std::vector<PhongMaterial> materials;  // the MTL's, in file order, named by their MTL name
    // `object` of each triangle is an index into `materials`, or kNoMeshMaterial (no usemtl).
    std::vector<Triangle> triangles;
    // Empty when the file has no normals, else one per triangle (zero for faces without `vn`).
    std::vector<TriangleNormals> normals;
    std::size_t degenerateDropped = 0;  // faces without area: they have no normal to shade with
    // Material libraries named by `mtllib` lines that could not be opened (paths as looked for),
    // and `usemtl` names that no library read defines. Faces of either have no MTL material
    // (kNoMeshMaterial): the scene loader warns and gives them the scene's material or a grey.
    std::vector<std::string> missingLibraries;
    std::vector<std::string> unknownMaterials;
};

// What faces without an MTL material get when the scene gives the mesh no `material`.
PhongMaterial defaultMeshMaterial();

// Throws SceneError naming the OBJ file, or an MTL file that is broken, when they cannot be read.
// A missing MTL file is not an error (ObjMesh::missingLibraries).
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
