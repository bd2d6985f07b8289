// libFuzzer target for the glTF reader (shapes/gltf_loader.h). Input: a glTF file, JSON (.gltf,
// buffers as base64 data URIs) or binary (.glb, from its "glTF" magic); it lives in
// /nonexistent-fuzz/, so no external buffer or image loads. Any input either loads or is refused
// with a SceneError; a model that loads must be usable as it is: triangles with finite corners and
// an area, vertex normals of unit length (or zero), object and material indices in range, labels
// that are LPE labels, finite lights and cameras that see somewhere.
#include <cmath>
#include <cstdint>
#include <string>

#include "fuzz_support.h"
#include "schema/parameter.h"
#include "scene/scene_loader.h"
#include "shapes/gltf_loader.h"

namespace {

using namespace lightpath;
using fuzz::broken;

constexpr std::size_t kMaxInput = 65536;

bool finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
bool finiteNonNegative(const Rgb& c) { return finite(c) && c.r >= 0.0f && c.g >= 0.0f && c.b >= 0.0f; }
bool unitOrZero(const Vec3& n) { return finite(n) && (n == Vec3(0.0f) || std::abs(glm::length(n) - 1.0f) <= 1e-4f); }

void checkModel(const GltfModel& model) {
    for (const MaterialSlot& m : model.materials) {
        if (!isValidName(m->name)) broken("material labelled \"" + m->name + "\", no label");
        if (!finiteNonNegative(m->emission.constant()))
            broken("material \"" + m->name + "\" emits a negative or non-finite radiance");
    }
    for (const GltfObject& o : model.objects) {
        if (!isValidName(o.label)) broken("object labelled \"" + o.label + "\", no label");
        if (o.material >= model.materials.size()) broken("object \"" + o.label + "\" has no material");
    }
    if (!model.normals.empty() && model.normals.size() != model.triangles.size())
        broken("vertex normals for " + std::to_string(model.normals.size()) + " of " +
               std::to_string(model.triangles.size()) + " triangles");
    for (std::size_t i = 0; i < model.triangles.size(); ++i) {
        const Triangle& t = model.triangles[i];
        const std::string which = "triangle " + std::to_string(i);
        if (!finite(t.a) || !finite(t.b) || !finite(t.c)) broken(which + " has a non-finite corner");
        if (glm::cross(t.b - t.a, t.c - t.a) == Vec3(0.0f)) broken(which + " has no area: it should have been dropped");
        if (t.object >= model.objects.size()) broken(which + " belongs to no object");
        if (!model.normals.empty()) {
            const TriangleNormals& n = model.normals[i];
            if (!unitOrZero(n.a) || !unitOrZero(n.b) || !unitOrZero(n.c)) broken(which + " has a normal neither unit nor zero");
        }
    }
    for (const GltfLight& l : model.lights) {
        if (!isValidName(l.label) || l.label == "ambient") broken("light labelled \"" + l.label + "\"");
        if (!finite(l.position) || !unitOrZero(l.direction) || l.direction == Vec3(0.0f))
            broken("light \"" + l.label + "\" has no finite position or unit direction");
        if (!finiteNonNegative(l.intensity))
            broken("light \"" + l.label + "\" has a negative or non-finite intensity");
    }
    for (const GltfCamera& c : model.cameras) {
        const CameraDescription& d = c.camera;
        if (!finite(d.eye) || !finite(d.lookAt) || !finite(d.up) || d.eye == d.lookAt)
            broken("camera \"" + c.label + "\" sees nowhere");
        if (!(d.verticalFovDegrees > 0.0f && d.verticalFovDegrees < 180.0f) || d.width < 1 || d.height < 1)
            broken("camera \"" + c.label + "\" has no field of view or image");
        if (!(d.orthographicHeight > 0.0f && std::isfinite(d.orthographicHeight)))
            broken("camera \"" + c.label + "\" has an orthographic view of no height");
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size > kMaxInput) return 0;
    GltfModel model;
    try {
        model = loadGltfFromMemory(std::string(fuzz::asText(data, size)), "/nonexistent-fuzz/model.gltf");
    } catch (const SceneError&) {
        return 0;
    }
    checkModel(model);
    return 0;
}
