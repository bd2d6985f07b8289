#include "scene/obj_loader.h"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "scene/scene_loader.h"

namespace lightpath {
namespace {

Rgb rgb(const float v[3]) { return {v[0], v[1], v[2]}; }

// tinyobjloader reports a missing material library only as a warning; a scene that names one
// must have it, so the warning becomes an error that names the file.
void refuseMissingMaterialLibrary(const std::filesystem::path& file, const std::string& warnings) {
    std::istringstream lines(warnings);
    for (std::string line; std::getline(lines, line);) {
        const std::string prefix = "Material file [ ";
        const auto begin = line.find(prefix);
        if (begin == std::string::npos) continue;
        const auto nameBegin = begin + prefix.size();
        const auto nameEnd = line.find(" ]", nameBegin);
        const std::string library = line.substr(nameBegin, nameEnd - nameBegin);
        throw SceneError(file.string() + ": cannot open material library \"" +
                         (file.parent_path() / library).string() + "\" named by its mtllib line");
    }
}

}  // namespace

PhongMaterial phongFromMtl(const std::string& name, const float ambient[3], const float diffuse[3],
                           const float specular[3], const float transmittance[3], const float emission[3],
                           float shininess, float ior, float dissolve, int illum) {
    PhongMaterial m;
    m.name = name;
    m.ka = rgb(ambient);
    m.kd = rgb(diffuse);
    m.ks = rgb(specular);
    m.n = std::max(shininess, 0.0f);
    m.emission = glm::max(rgb(emission), Rgb(0.0f));
    // MTL illumination models (Wavefront's spec): 3 "reflection on, ray trace", 5 "Fresnel on,
    // ray trace" reflect in the mirror direction weighted by Ks; 4, 6, 7 and 9 also transmit.
    const bool mirror = illum == 3 || illum == 4 || illum == 5 || illum == 6 || illum == 7 || illum == 9;
    const bool transmits = illum == 4 || illum == 6 || illum == 7 || illum == 9;
    if (mirror) m.kr = m.ks;
    if (transmits) {
        const Rgb filter = rgb(transmittance);
        m.kt = isBlack(filter) ? Rgb(1.0f - std::clamp(dissolve, 0.0f, 1.0f)) : filter;
        if (ior > 0.0f) m.ior = ior;
    }
    return m;
}

ObjMesh loadObj(const std::filesystem::path& file) {
    {
        std::ifstream probe(file);
        if (!probe || std::filesystem::is_directory(file))
            throw SceneError(file.string() + ": cannot open mesh file");
    }
    tinyobj::ObjReaderConfig config;
    config.triangulate = true;
    config.vertex_color = false;
    config.mtl_search_path = file.parent_path().string();
    tinyobj::ObjReader reader;
    if (!reader.ParseFromFile(file.string(), config)) {
        std::string reason = reader.Error();
        while (!reason.empty() && (reason.back() == '\n' || reason.back() == '\r')) reason.pop_back();
        throw SceneError(file.string() + ": cannot read mesh file: " + reason);
    }
    refuseMissingMaterialLibrary(file, reader.Warning());

    ObjMesh mesh;
    for (const tinyobj::material_t& m : reader.GetMaterials())
        mesh.materials.push_back(phongFromMtl(m.name, m.ambient, m.diffuse, m.specular, m.transmittance, m.emission,
                                              m.shininess, m.ior, m.dissolve, m.illum));

    const tinyobj::attrib_t& attrib = reader.GetAttrib();
    const auto position = [&](const tinyobj::index_t& i) {
        const auto k = static_cast<std::size_t>(3 * i.vertex_index);
        return Vec3(attrib.vertices[k], attrib.vertices[k + 1], attrib.vertices[k + 2]);
    };
    const auto normal = [&](const tinyobj::index_t& i) {
        if (i.normal_index < 0) return Vec3(0.0f);
        const auto k = static_cast<std::size_t>(3 * i.normal_index);
        const Vec3 n(attrib.normals[k], attrib.normals[k + 1], attrib.normals[k + 2]);
        const float length = glm::length(n);
        return length > 0.0f ? n / length : Vec3(0.0f);
    };
    const bool hasNormals = !attrib.normals.empty();
    for (const tinyobj::shape_t& shape : reader.GetShapes()) {
        const std::vector<tinyobj::index_t>& indices = shape.mesh.indices;
        for (std::size_t f = 0; f < shape.mesh.num_face_vertices.size(); ++f) {
            const tinyobj::index_t* corner = &indices[3 * f];
            Triangle triangle{position(corner[0]), position(corner[1]), position(corner[2]), kNoMeshMaterial};
            if (glm::cross(triangle.b - triangle.a, triangle.c - triangle.a) == Vec3(0.0f)) {
                ++mesh.degenerateDropped;
                continue;
            }
            const int material = shape.mesh.material_ids[f];
            if (material >= 0) triangle.object = static_cast<std::uint32_t>(material);
            mesh.triangles.push_back(triangle);
            if (hasNormals) mesh.normals.push_back({normal(corner[0]), normal(corner[1]), normal(corner[2])});
        }
    }
    return mesh;
}

}  // namespace lightpath
