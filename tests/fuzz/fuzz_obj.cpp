// libFuzzer target for the OBJ/MTL loader. Input: OBJ text, then optionally a line `#mtl` and the
// MTL text that answers every `mtllib` line (the separator is an OBJ comment, so a seed without
// MTL is a plain OBJ file). Any text either loads or is refused with a SceneError; a mesh that
// loads must be usable as it is: triangles with finite corners and an area, vertex normals of unit
// length (or zero where a face has none), valid material indices, and materials within the ranges
// of a scene file's (scenes/README.md) whose names are LPE labels (any name in the MTL is made one). Coordinates are not limited here: the scene loader checks
// them once the mesh is placed.
#include <cmath>
#include <cstdint>
#include <string>

#include "fuzz_support.h"
#include "schema/parameter.h"
#include "shapes/obj_loader.h"
#include "scene/scene_loader.h"

namespace {

using namespace lightpath;
using fuzz::broken;

constexpr std::size_t kMaxInput = 16384;

bool finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
bool withinLimit(float x, double low) { return x >= low && x <= kMaxMagnitude; }
bool colour(const Rgb& c) { return withinLimit(c.r, 0.0) && withinLimit(c.g, 0.0) && withinLimit(c.b, 0.0); }

bool unitOrZero(const Vec3& n) {
    return finite(n) && (n == Vec3(0.0f) || std::abs(glm::length(n) - 1.0f) <= 1e-5f);
}

void checkMaterial(const PhongMaterial& m) {
    for (const Rgb& c : {m.ka.constant(), m.kd.constant(), m.ks.constant(), m.kr.constant(), m.kt.constant(), m.emission.constant()})
        if (!colour(c)) broken("MTL material \"" + m.name + "\" loaded with a colour outside 0..1e6");
    if (!withinLimit(m.n, 0.0)) broken("MTL material \"" + m.name + "\" loaded with an exponent n outside 0..1e6");
    if (!withinLimit(m.ior, 0.0) || m.ior == 0.0f) broken("MTL material \"" + m.name + "\" loaded with an ior outside (0, 1e6]");
}

void checkMesh(const ObjMesh& mesh) {
    for (const PhongMaterial& m : mesh.materials) checkMaterial(m);
    for (const PhongMaterial& m : mesh.materials)
        if (!isValidName(m.name)) broken("MTL material \"" + printableName(m.name) + "\" loaded with a name that is no label");
    if (mesh.originalNames.size() != mesh.materials.size() || mesh.materialLines.size() != mesh.materials.size())
        broken("original names or usemtl lines not one per material");
    if (!mesh.normals.empty() && mesh.normals.size() != mesh.triangles.size())
        broken("vertex normals for " + std::to_string(mesh.normals.size()) + " of " +
               std::to_string(mesh.triangles.size()) + " triangles");
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
        const Triangle& t = mesh.triangles[i];
        const std::string which = "triangle " + std::to_string(i);
        if (!finite(t.a) || !finite(t.b) || !finite(t.c)) broken(which + " has a non-finite corner");
        if (glm::cross(t.b - t.a, t.c - t.a) == Vec3(0.0f)) broken(which + " has no area: it should have been dropped");
        if (t.object != kNoMeshMaterial && t.object >= mesh.materials.size())
            broken(which + " has material " + std::to_string(t.object) + " of " + std::to_string(mesh.materials.size()));
        if (!mesh.normals.empty()) {
            const TriangleNormals& n = mesh.normals[i];
            if (!unitOrZero(n.a) || !unitOrZero(n.b) || !unitOrZero(n.c)) broken(which + " has a vertex normal neither unit nor zero");
        }
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size > kMaxInput) return 0;
    const auto [obj, mtl] = fuzz::splitAtLine(fuzz::asText(data, size), "#mtl");
    ObjMesh mesh;
    try {
        mesh = loadObjFromText(obj, mtl, "/nonexistent-fuzz/mesh.obj");
    } catch (const SceneError&) {
        return 0;
    }
    checkMesh(mesh);
    return 0;
}
