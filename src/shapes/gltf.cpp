// `[[gltf]]`: a glTF 2.0 file (shapes/gltf_loader.h) placed in the scene, registered like every
// shape kind (docs/extending.md). Its triangles join SceneGeometry's triangle array, one object
// per node and material; its materials become scene materials (a [materials] entry of the same
// name wins, as for MTL); its KHR_lights_punctual lights are added through the light registry
// (the types "point", "spot", "directional"); its first perspective camera, or the one `camera`
// names, becomes the scene's camera when the scene has none.
#include <filesystem>
#include <string>
#include <vector>

#include "media/homogeneous_medium.h"
#include "scene/light_type.h"
#include "scene/scene_loader.h"
#include "scene/shape_type.h"
#include "shapes/gltf_loader.h"
#include "shapes/mesh_placement.h"

namespace lightpath {
namespace {

// What a file's light intensities mean: Blender's glTF exporter writes them in one of three
// "Lighting Modes" (io_scene_gltf2, gather_lights), and the file does not say which.
//   standard  candela (point, spot) and lux (directional), as KHR_lights_punctual specifies,
//             converted by Blender at 683 lm/W (the candela's definition, at 540 THz): a lamp of
//             P watts is P / (4 pi) * 683 cd, a sun of E W/m^2 is 683 E lux. Blender's default.
//   unitless  the same without the 683: W/sr and W/m^2.
//   raw       Blender's own strengths: a lamp's watts, a sun's W/m^2.
// Emission (emissiveFactor times KHR_materials_emissive_strength) is radiance as written in every
// mode: Blender exports its emission strength unconverted.
enum class LightingMode { standard, unitless, raw };
constexpr float kLumensPerWatt = 683.0f;

LightingMode lightingModeOf(const ParameterValues& values) {
    const std::string mode = values.text("lighting");
    if (mode == "standard") return LightingMode::standard;
    if (mode == "unitless") return LightingMode::unitless;
    if (mode == "raw") return LightingMode::raw;
    values.fail("lighting", "expected \"standard\", \"unitless\" or \"raw\" (Blender's glTF Lighting Mode), got \"" +
                                mode + "\"");
}

// The file's number as lightpath's: radiant intensity (W/sr) of a point or spot light,
// irradiance (W/m^2) of a directional one.
Rgb radiometric(const GltfLight& light, LightingMode mode) {
    switch (mode) {
        case LightingMode::standard: return light.intensity / kLumensPerWatt;
        case LightingMode::unitless: return light.intensity;
        case LightingMode::raw:
            return light.kind == GltfLightKind::directional ? light.intensity : light.intensity / (4.0f * kPi);
    }
    return light.intensity;
}

// A "point" light's radiant intensity is pi times its `intensity` (lights/point_light.h).
void addLight(const GltfLight& light, LightingMode mode, const MeshPlacement& placement, const ParameterValues& values,
              SceneBuilder& scene) {
    const char* typeName = light.kind == GltfLightKind::point ? "point"
                           : light.kind == GltfLightKind::spot ? "spot"
                                                               : "directional";
    const LightType* type = LightRegistry::instance().find(typeName);
    if (type == nullptr) {
        scene.warn(values.located("file", values.text("file") + ": light \"" + light.label + "\" is a " + typeName +
                                              " light, which lightpath has no type for yet; it is left out"));
        return;
    }
    ParameterValues lightValues(type->schema);
    lightValues.set("name", light.label);
    const Vec3 intensity = radiometric(light, mode);
    if (light.kind == GltfLightKind::directional) {
        lightValues.set("direction", placement.direction(light.direction));
        lightValues.set("irradiance", intensity);
    } else {
        lightValues.set("position", placement.point(light.position));
        lightValues.set("intensity", intensity / kPi);
        if (light.kind == GltfLightKind::point) lightValues.set("attenuation", Vec3(0.0f, 0.0f, 1.0f));
    }
    if (light.kind == GltfLightKind::spot) {
        lightValues.set("direction", placement.direction(light.direction));
        lightValues.set("cone_angle", double(glm::degrees(light.outerConeRadians)));
        lightValues.set("falloff_start", double(glm::degrees(light.innerConeRadians)));
    }
    type->addTo(lightValues, scene);
}

void addCamera(const GltfModel& model, const MeshPlacement& placement, const ParameterValues& values,
               SceneBuilder& scene) {
    if (model.cameras.empty()) {
        if (values.has("camera"))
            values.fail("camera", "expected the name of one of the file's cameras, but it has none");
        return;
    }
    const GltfCamera* chosen = &model.cameras.front();
    if (values.has("camera")) {
        chosen = nullptr;
        std::string known;
        for (const GltfCamera& c : model.cameras) {
            if (c.label == values.text("camera")) chosen = &c;
            known += (known.empty() ? "" : ", ") + c.label;
        }
        if (chosen == nullptr) values.fail("camera", "expected one of the file's cameras: " + known);
    }
    CameraDescription camera = chosen->camera;
    const Vec3 forward = placement.direction(glm::normalize(camera.lookAt - camera.eye));
    camera.eye = placement.point(camera.eye);
    camera.lookAt = camera.eye + forward;
    camera.up = placement.direction(camera.up);
    scene.offerCamera(camera);
}

void addGltf(const ParameterValues& values, SceneBuilder& scene) {
    const std::filesystem::path file = scene.folder() / values.text("file");
    GltfModel model;
    try {
        model = loadGltf(file);
    } catch (const SceneError& e) {
        values.fail("file", e.what());
    }
    for (const std::string& warning : model.warnings) scene.warn(values.located("file", warning));
    // The mapping of names to labels, where a name is no label or collides (issue #26).
    for (const GltfRenaming& r : model.renamed)
        scene.warn(values.located("file", file.string() + ": " + r.what + " \"" + r.original + "\" is labelled \"" +
                                              r.label + "\" in light paths"));
    if (model.degenerateDropped > 0)
        scene.warn(values.located("file", std::to_string(model.degenerateDropped) + " triangles without area were left out"));

    const MeshPlacement placement = placementOf(values);
    const bool override = values.has("material");
    const std::string name = values.has("name") ? values.text("name") : std::string();
    std::vector<std::uint32_t> sceneObject(model.objects.size());
    const std::uint32_t whole = override ? scene.addShapeObject(values) : 0;
    // The media the file's volumes bound (KHR_materials_volume), one per material, made once and
    // named after it. A scene's `interior` (or `material`) overrides them, as it does materials.
    std::vector<std::uint32_t> medium(model.materials.size(), kNoMedium);
    const bool ownMedia = !values.has(kShapeInteriorParameter.name);
    for (std::size_t i = 0; i < model.objects.size(); ++i) {
        if (override) {
            sceneObject[i] = whole;
            continue;
        }
        const GltfObject& object = model.objects[i];
        const std::uint32_t material = scene.sceneMaterial(model.materials[object.material]);
        sceneObject[i] = scene.addObject(name.empty() ? object.label : name, material);
        const std::optional<Rgb>& absorption = model.absorption[object.material];
        if (!ownMedia || !absorption) continue;
        if (medium[object.material] == kNoMedium) {
            HomogeneousMedium absorbing;
            absorbing.sigmaA = *absorption;
            absorbing.name = model.materials[object.material]->name;
            medium[object.material] = scene.addMedium(MediumSlot(absorbing));
        }
        scene.setInterior(sceneObject[i], medium[object.material]);
    }
    for (std::size_t i = 0; i < model.triangles.size(); ++i) {
        const Triangle& t = model.triangles[i];
        const Triangle placed = placeTriangle(placement, t, sceneObject[t.object], values, file, i);
        if (model.normals.empty()) {
            scene.addTriangle(placed);
        } else {
            scene.addTriangle(placed, placement.normals(model.normals[i]));
        }
        if (!model.uvs.empty() && model.uvs[i].given) scene.setTriangleUvs(model.uvs[i]);
        if (!model.tangents.empty()) scene.setTriangleTangents(placement.tangents(model.tangents[i]));
        if (!model.colors.empty()) scene.setTriangleColors(model.colors[i]);
    }
    const LightingMode lighting = lightingModeOf(values);
    if (values.boolean("lights"))
        for (const GltfLight& light : model.lights) addLight(light, lighting, placement, values, scene);
    addCamera(model, placement, values, scene);
}

}  // namespace
}  // namespace lightpath

// Rank 1002: after the OBJ meshes, model by model.
LIGHTPATH_REGISTER_SHAPE(lightpath::ShapeType{
    {"shape", "gltf",
     "a glTF 2.0 file (.gltf, .glb): its meshes, materials, lights and camera, placed by scale, rotate_y and translate",
     {{"name", lightpath::ParameterType::Name, "", "", {}, "the label of every part; default: each node's name (else its mesh's)"},
      {"file", lightpath::ParameterType::Text, "", "", {}, "a .gltf or .glb file, relative to the scene file", true},
      {"material", lightpath::ParameterType::Name, "", "", {},
       "a material of `[materials]`: the whole model in it, ignoring the file's materials"},
      {"camera", lightpath::ParameterType::Name, "", "", {},
       "which of the file's cameras (by its label) becomes the scene's camera when the scene has no `[camera]`; "
       "default: the first"},
      {"lights", lightpath::ParameterType::Boolean, "", "true", {}, "whether the file's KHR_lights_punctual lights are added"},
      {"lighting", lightpath::ParameterType::Name, "", "standard", {},
       "what the lights' intensities mean, as Blender's glTF exporter's Lighting Mode: `standard` (candela and lux "
       "at 683 lm/W: W/sr = cd / 683, W/m² = lux / 683; Blender's default), `unitless` (W/sr and W/m²) or `raw` "
       "(a lamp's watts, W/sr = W / 4π; a sun's W/m²)"},
      {"scale", lightpath::ParameterType::PerAxis, "", "1", lightpath::kPositive,
       "applied first, about the file's origin: one factor for every axis or one per axis"},
      {"rotate_y", lightpath::ParameterType::Number, "degrees", "0", {}, "then a turn about the y axis (x towards −z)"},
      {"translate", lightpath::ParameterType::Point, "m", "[0, 0, 0]", {}, "then a move by this vector"},
      {lightpath::kShapeInteriorParameter.name, lightpath::ParameterType::Name, "", "", {},
       "a medium of `[media]` filling every part, in place of the file's own (KHR_materials_volume); default: "
       "the file's, else none (vacuum)"}},
     ""},
    1002, "gltf", lightpath::addGltf, lightpath::ShapeStorage::triangles})
