#include "shapes/obj_loader.h"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string_view>

#include "scene/scene_loader.h"
#include "schema/parameter.h"

namespace lightpath {
namespace {

Rgb rgb(const float v[3]) { return {v[0], v[1], v[2]}; }

// The `usemtl` and `mtllib` lines of an OBJ text, numbered as tinyobjloader reads lines (ended by
// "\n", "\r\n" or "\r"), each `usemtl` name parsed as it parses it: the first word after it.
struct ObjStatementLines {
    std::vector<ObjLineRef> usemtl;
    std::vector<ObjLineRef> mtllib;  // the rest of the line, the library names
};

ObjStatementLines scanStatementLines(std::string_view text) {
    ObjStatementLines found;
    std::size_t number = 0;
    for (std::size_t begin = 0; begin < text.size();) {
        std::size_t end = text.find_first_of("\r\n", begin);
        if (end == std::string_view::npos) end = text.size();
        std::string_view line = text.substr(begin, end - begin);
        begin = end + (text.compare(end, 2, "\r\n") == 0 ? 2 : 1);
        ++number;
        line.remove_prefix(std::min(line.find_first_not_of(" \t"), line.size()));
        const auto rest = [&](std::size_t skip) {
            std::string_view after = line.substr(skip);
            after.remove_prefix(std::min(after.find_first_not_of(" \t"), after.size()));
            return after;
        };
        if (line.rfind("usemtl", 0) == 0) {
            const std::string_view after = rest(6);
            found.usemtl.push_back({std::string(after.substr(0, after.find_first_of(" \t"))), number});
        } else if (line.rfind("mtllib", 0) == 0 && line.size() > 6 && (line[6] == ' ' || line[6] == '\t')) {
            found.mtllib.push_back({std::string(rest(6)), number});
        }
    }
    return found;
}

// Whether an `mtllib` line's library names (separated by blanks) include `name` exactly.
bool namesLibrary(const std::string& names, const std::string& name) {
    std::istringstream words(names);
    for (std::string word; words >> word;)
        if (word == name) return true;
    return false;
}

// tinyobjloader reports a missing material library and a `usemtl` it cannot resolve only in its
// warning text, in file order: "Material file [ NAME ] not found in a path : DIR" and
// "material [ 'NAME' ] not found in .mtl". Each is read back from there and given the OBJ line
// that names it; each name once.
void readMaterialWarnings(const std::filesystem::path& file, const std::string& warnings,
                          const ObjStatementLines& statements, ObjMesh& mesh) {
    std::istringstream lines(warnings);
    const auto between = [](const std::string& line, const std::string& open, const std::string& close,
                            std::string& inside) {
        const auto begin = line.find(open);
        if (begin == std::string::npos) return false;
        const auto end = line.find(close, begin + open.size());
        if (end == std::string::npos) return false;
        inside = line.substr(begin + open.size(), end - begin - open.size());
        return true;
    };
    const auto listed = [](const std::vector<ObjLineRef>& refs, const std::string& text) {
        return std::any_of(refs.begin(), refs.end(), [&](const ObjLineRef& r) { return r.text == text; });
    };
    std::size_t nextUsemtl = 0;  // the warnings of `usemtl` lines come in the order of those lines
    for (std::string line, name; std::getline(lines, line);) {
        if (between(line, "Material file [ ", " ]", name)) {
            const std::string path = (file.parent_path() / name).string();
            if (listed(mesh.missingLibraries, path)) continue;
            const auto naming = std::find_if(statements.mtllib.begin(), statements.mtllib.end(),
                                             [&](const ObjLineRef& r) { return namesLibrary(r.text, name); });
            mesh.missingLibraries.push_back({path, naming == statements.mtllib.end() ? 0 : naming->line});
        } else if (between(line, "material [ '", "' ] not found", name)) {
            std::size_t at = 0;
            for (; nextUsemtl < statements.usemtl.size(); ++nextUsemtl) {
                if (statements.usemtl[nextUsemtl].text == name) {
                    at = statements.usemtl[nextUsemtl++].line;
                    break;
                }
            }
            if (!listed(mesh.unknownMaterials, name)) mesh.unknownMaterials.push_back({name, at});
        }
    }
}

// Gives every material a label (ObjMesh::originalNames) and the line of its first `usemtl`.
// A name that is no label is made one; one that collides with another material's is numbered.
void labelMaterials(const ObjStatementLines& statements, ObjMesh& mesh) {
    std::vector<std::string> taken;
    for (const PhongMaterial& m : mesh.materials)
        if (isValidName(m.name)) taken.push_back(m.name);
    const auto isTaken = [&](const std::string& label) {
        return std::find(taken.begin(), taken.end(), label) != taken.end();
    };
    for (PhongMaterial& m : mesh.materials) {
        const auto first = std::find_if(statements.usemtl.begin(), statements.usemtl.end(),
                                        [&](const ObjLineRef& r) { return r.text == m.name; });
        mesh.materialLines.push_back(first == statements.usemtl.end() ? 0 : first->line);
        if (isValidName(m.name)) {
            mesh.originalNames.push_back(std::nullopt);
            continue;
        }
        const std::string base = labelFromName(m.name);
        std::string label = base;
        for (int k = 2; isTaken(label); ++k) label = base + "-" + std::to_string(k);
        taken.push_back(label);
        mesh.originalNames.push_back(m.name);
        m.name = label;
    }
}

}  // namespace

std::string labelFromName(std::string_view name) {
    const std::size_t first = name.find_first_not_of(" \t"), last = name.find_last_not_of(" \t");
    name = first == std::string_view::npos ? std::string_view() : name.substr(first, last - first + 1);
    std::string label;
    for (std::size_t i = 0; i < name.size(); ++i) {
        if (isNameCharacter(name[i])) {
            label += name[i];
        } else if (i == 0 || isNameCharacter(name[i - 1])) {
            label += '_';
        }
    }
    return label.empty() ? "unnamed" : label;
}

std::string printableName(std::string_view text) {
    std::string shown;
    for (unsigned char c : text) {
        if (c >= 0x20 && c < 0x7f && c != '\\') {
            shown += static_cast<char>(c);
        } else {
            const char* digits = "0123456789ABCDEF";
            shown += "\\x";
            shown += digits[c >> 4];
            shown += digits[c & 15];
        }
    }
    return shown;
}

PhongMaterial defaultMeshMaterial() {
    PhongMaterial grey;
    grey.name = "obj-default-grey";
    grey.ka = Rgb(0.5f);
    grey.kd = Rgb(0.5f);
    return grey;
}

PhongMaterial phongFromMtl(const std::string& name, const float ambient[3], const float diffuse[3],
                           const float specular[3], const float transmittance[3], const float emission[3],
                           float shininess, float ior, float dissolve, int illum) {
    PhongMaterial m;
    m.name = name;
    m.ka = rgb(ambient);
    m.kd = rgb(diffuse);
    m.ks = rgb(specular);
    m.n = std::max(shininess, 0.0f);
    m.emission = rgb(emission);
    // MTL illumination models (Wavefront's spec): 3 "reflection on, ray trace", 5 "Fresnel on,
    // ray trace" reflect in the mirror direction weighted by Ks; 4, 6, 7 and 9 also transmit, and
    // 7, "refraction on, Fresnel on", splits kt between reflection and refraction by Fresnel.
    const bool mirror = illum == 3 || illum == 4 || illum == 5 || illum == 6 || illum == 7 || illum == 9;
    const bool transmits = illum == 4 || illum == 6 || illum == 7 || illum == 9;
    if (mirror) m.kr = m.ks;
    if (transmits) {
        const Rgb filter = rgb(transmittance);
        m.kt = isBlack(filter) ? Rgb(1.0f - std::clamp(dissolve, 0.0f, 1.0f)) : filter;
        if (ior > 0.0f) m.ior = ior;
        m.fresnel = illum == 7;
    }
    return m;
}

namespace {

// "-1", or "[-1, 0, 0]" for a colour: MTL numbers as an error shows them.
std::string listed(const float* values, int count) {
    std::string text;
    for (int i = 0; i < count; ++i) {
        char buffer[32];
        const auto end = std::to_chars(buffer, buffer + sizeof buffer, values[i]).ptr;
        text += (i > 0 ? ", " : "") + std::string(buffer, end);
    }
    return count == 1 ? text : "[" + text + "]";
}

// tinyobjloader passes negative numbers on and reads 1e39 as infinity: an MTL material is held to
// the rules of a scene file's (scenes/README.md), its colours from 0 to kMaxMagnitude and its Ns
// and Ni within +-kMaxMagnitude, so that no negative or overflowing weight reaches the renderer.
void refuseBadMaterial(const tinyobj::material_t& m, const std::filesystem::path& file) {
    const auto refuse = [&](const char* statement, const std::string& expected, const float* values, int count) {
        throw SceneError(file.string() + ": material \"" + m.name + "\": " + statement + ": expected " + expected +
                         ", got " + listed(values, count));
    };
    const auto within = [](float value, double low) { return value >= low && value <= kMaxMagnitude; };
    const std::pair<const char*, const float*> colours[] = {
        {"Ka", m.ambient}, {"Kd", m.diffuse}, {"Ks", m.specular}, {"Tf", m.transmittance}, {"Ke", m.emission}};
    for (const auto& [statement, values] : colours)
        for (int c = 0; c < 3; ++c)
            if (!within(values[c], 0.0)) refuse(statement, "3 numbers from 0 to " + std::string(kMaxMagnitudeText), values, 3);
    if (!within(m.shininess, -kMaxMagnitude)) refuse("Ns", "a number " + std::string(kMagnitudeRange), &m.shininess, 1);
    if (!within(m.ior, -kMaxMagnitude)) refuse("Ni", "a number " + std::string(kMagnitudeRange), &m.ior, 1);
}

// The triangles and materials a successful parse produced. tinyobjloader passes on vertex
// indices beyond the file's vertices and numbers that overflow to infinity; both are refused here,
// naming `file`, so that no triangle is built from memory outside the file or from non-finite
// corners.
ObjMesh meshFrom(const tinyobj::ObjReader& reader, const std::filesystem::path& file) {
    const tinyobj::attrib_t& attrib = reader.GetAttrib();
    const auto refuseNonFinite = [&](const std::vector<tinyobj::real_t>& xyz, const char* what, const char* part,
                                     std::size_t stride = 3) {
        for (std::size_t k = 0; k < xyz.size(); ++k)
            if (!std::isfinite(xyz[k]))
                throw SceneError(file.string() + ": " + what + " " + std::to_string(k / stride + 1) + " has a " + part +
                                 " that is not a finite single-precision number");
    };
    refuseNonFinite(attrib.vertices, "vertex", "coordinate");
    refuseNonFinite(attrib.normals, "normal", "component");
    refuseNonFinite(attrib.texcoords, "texture coordinate", "component", 2);
    const auto refuseIndex = [&](std::size_t face, const char* what, int index, std::size_t count) {
        throw SceneError(file.string() + ": face " + std::to_string(face + 1) + " refers to " + what + " " +
                         std::to_string(index + 1) + ", but the file has " + std::to_string(count));
    };

    ObjMesh mesh;
    for (const tinyobj::material_t& m : reader.GetMaterials()) {
        refuseBadMaterial(m, file);
        mesh.materials.push_back(phongFromMtl(m.name, m.ambient, m.diffuse, m.specular, m.transmittance, m.emission,
                                              m.shininess, m.ior, m.dissolve, m.illum));
        mesh.diffuseTextures.push_back(m.diffuse_texname);
        mesh.emissionTextures.push_back(m.emissive_texname);
        mesh.alphaTextures.push_back(m.alpha_texname);
    }

    const auto position = [&](const tinyobj::index_t& i) {
        const auto k = static_cast<std::size_t>(3 * i.vertex_index);
        return Vec3(attrib.vertices[k], attrib.vertices[k + 1], attrib.vertices[k + 2]);
    };
    const auto normal = [&](const tinyobj::index_t& i) {
        if (i.normal_index < 0) return Vec3(0.0f);
        const auto k = static_cast<std::size_t>(3 * i.normal_index);
        // In double: the squared length of a float vector can overflow or underflow in float.
        const glm::dvec3 n(attrib.normals[k], attrib.normals[k + 1], attrib.normals[k + 2]);
        const double length = glm::length(n);
        return length > 0.0 ? Vec3(n / length) : Vec3(0.0f);
    };
    const auto texcoord = [&](const tinyobj::index_t& i) {
        const auto k = static_cast<std::size_t>(2 * i.texcoord_index);
        return Vec2(attrib.texcoords[k], attrib.texcoords[k + 1]);
    };
    const bool hasNormals = !attrib.normals.empty();
    const bool hasUvs = !attrib.texcoords.empty();
    const std::size_t vertexCount = attrib.vertices.size() / 3, normalCount = attrib.normals.size() / 3;
    const std::size_t uvCount = attrib.texcoords.size() / 2;
    std::size_t face = 0;
    for (const tinyobj::shape_t& shape : reader.GetShapes()) {
        const std::vector<tinyobj::index_t>& indices = shape.mesh.indices;
        // Triangulation leaves faces of 3 corners; anything else (a point or a line) has no area.
        std::size_t offset = 0;
        for (std::size_t f = 0; f < shape.mesh.num_face_vertices.size(); ++f, ++face) {
            const std::size_t cornerCount = shape.mesh.num_face_vertices[f];
            const tinyobj::index_t* corner = indices.data() + offset;
            offset += cornerCount;
            if (cornerCount != 3 || offset > indices.size()) {
                ++mesh.degenerateDropped;
                continue;
            }
            for (int c = 0; c < 3; ++c) {
                const tinyobj::index_t& i = corner[c];
                if (i.vertex_index < 0 || static_cast<std::size_t>(i.vertex_index) >= vertexCount)
                    refuseIndex(face, "vertex", i.vertex_index, vertexCount);
                if (i.normal_index >= 0 && static_cast<std::size_t>(i.normal_index) >= normalCount)
                    refuseIndex(face, "normal", i.normal_index, normalCount);
                if (i.texcoord_index >= 0 && static_cast<std::size_t>(i.texcoord_index) >= uvCount)
                    refuseIndex(face, "texture coordinate", i.texcoord_index, uvCount);
            }
            Triangle triangle{position(corner[0]), position(corner[1]), position(corner[2]), kNoMeshMaterial};
            if (glm::cross(triangle.b - triangle.a, triangle.c - triangle.a) == Vec3(0.0f)) {
                ++mesh.degenerateDropped;
                continue;
            }
            const int material = f < shape.mesh.material_ids.size() ? shape.mesh.material_ids[f] : -1;
            if (material >= 0 && static_cast<std::size_t>(material) < mesh.materials.size()) triangle.object = static_cast<std::uint32_t>(material);
            mesh.triangles.push_back(triangle);
            if (hasNormals) mesh.normals.push_back({normal(corner[0]), normal(corner[1]), normal(corner[2])});
            if (hasUvs) {
                const bool given = corner[0].texcoord_index >= 0 && corner[1].texcoord_index >= 0 &&
                                   corner[2].texcoord_index >= 0;
                mesh.uvs.push_back(given ? TriangleUvs{texcoord(corner[0]), texcoord(corner[1]), texcoord(corner[2]), true}
                                         : TriangleUvs{});
            }
        }
    }
    return mesh;
}

tinyobj::ObjReaderConfig readerConfig() {
    tinyobj::ObjReaderConfig config;
    config.triangulate = true;
    config.vertex_color = false;
    return config;
}

// The mesh with what only the OBJ text tells: the lines of its material statements and labels.
ObjMesh completed(ObjMesh mesh, const std::filesystem::path& file, const tinyobj::ObjReader& reader,
                  std::string_view objText) {
    const ObjStatementLines statements = scanStatementLines(objText);
    readMaterialWarnings(file, reader.Warning(), statements, mesh);
    labelMaterials(statements, mesh);
    return mesh;
}

[[noreturn]] void failToRead(const std::filesystem::path& file, const tinyobj::ObjReader& reader) {
    std::string reason = reader.Error();
    while (!reason.empty() && (reason.back() == '\n' || reason.back() == '\r')) reason.pop_back();
    throw SceneError(file.string() + ": cannot read mesh file: " + reason);
}

}  // namespace

ObjMesh loadObj(const std::filesystem::path& file) {
    std::ostringstream text;
    {
        std::ifstream in(file, std::ios::binary);
        if (!in || std::filesystem::is_directory(file))
            throw SceneError(file.string() + ": cannot open mesh file");
        text << in.rdbuf();
    }
    tinyobj::ObjReaderConfig config = readerConfig();
    config.mtl_search_path = file.parent_path().string();
    tinyobj::ObjReader reader;
    if (!reader.ParseFromFile(file.string(), config)) failToRead(file, reader);
    return completed(meshFrom(reader, file), file, reader, text.str());
}

ObjMesh loadObjFromText(const std::string& objText, const std::string& mtlText, const std::filesystem::path& file) {
    tinyobj::ObjReader reader;
    if (!reader.ParseFromString(objText, mtlText, readerConfig())) failToRead(file, reader);
    return completed(meshFrom(reader, file), file, reader, objText);
}

}  // namespace lightpath
