#include "scene/scene_loader.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>
#include <system_error>

#include "scene/light_type.h"
#include "scene/shape_type.h"
#include "materials/material_type.h"
#include "materials/phong_material.h"
#include "media/medium_type.h"
#include "schema/parameter.h"
#include "schema/schema_error.h"
#include "scene/spelling.h"
#include "scene/toml_reader.h"

namespace lightpath {
namespace {

std::string readName(const TomlValue& value) {
    std::string name = value.string();
    if (!isValidName(name)) value.expected("a name of " + std::string(kNameCharacters));
    return name;
}

Vec3 readNonZeroVector(const TomlValue& value) {
    const Vec3 v = value.vec3();
    if (v == Vec3(0.0f)) value.fail("expected a non-zero vector, got " + formatVec3(v));
    return v;
}

CameraDescription readCamera(const TomlTable& table) {
    table.allowOnly({"eye", "look_at", "up", "projection", "fov", "height", "resolution"});
    CameraDescription camera;
    if (auto projection = table.find("projection")) {
        const std::string name = projection->string();
        if (name == "orthographic") camera.projection = Projection::Orthographic;
        else if (name != "perspective") projection->expected("\"perspective\" or \"orthographic\"");
    }
    const bool orthographic = camera.projection == Projection::Orthographic;
    // Each projection has its own extent: a field of view, or the orthographic view's height.
    if (orthographic && table.find("fov"))
        table.failAtKey("fov", "an orthographic camera has no field of view: `height` sets how much of the scene it shows");
    if (!orthographic && table.find("height"))
        table.failAtKey("height", "`height` is an orthographic camera's; a perspective one's extent is `fov` "
                                  "(or set projection = \"orthographic\")");
    if (auto height = table.find("height"))
        camera.orthographicHeight = height->number({0.0, std::numeric_limits<double>::infinity(), true, false,
                                                    "the view's height in scene units, > 0"});
    if (auto eye = table.find("eye")) camera.eye = eye->vec3();
    if (auto lookAt = table.find("look_at")) camera.lookAt = lookAt->vec3();
    if (camera.lookAt == camera.eye) {
        table.failAtKey("look_at", "expected a point other than camera.eye, got the same point " +
                                       formatVec3(camera.eye));
    }
    if (auto up = table.find("up")) camera.up = readNonZeroVector(*up);
    const Vec3 view = camera.lookAt - camera.eye;
    if (areParallel(camera.up, view)) {
        table.failAtKey("up", "expected a vector not parallel to look_at - eye = " +
                                  formatVec3(view) + ", got " + formatVec3(camera.up));
    }
    if (auto fov = table.find("fov")) {
        constexpr NumberRule openDegrees{0.0, 180.0, true, true,
                                         "a vertical field of view in degrees, 0 < fov < 180"};
        camera.verticalFovDegrees = fov->number(openDegrees);
    }
    if (auto resolution = table.find("resolution")) {
        constexpr int maxPixels = 16384;
        const std::vector<TomlValue> size = resolution->array(2, "2 integers [width, height]");
        camera.width = size[0].integer(1, maxPixels);
        camera.height = size[1].integer(1, maxPixels);
    }
    return camera;
}

// The index of the medium `reference` names, else a located "unknown medium" error with the
// nearest name and the known ones.
std::uint32_t findMedium(const TomlValue& reference, const std::vector<MediumSlot>& media) {
    const std::string name = readName(reference);
    std::vector<std::string> known;
    for (std::uint32_t i = 0; i < media.size(); ++i) {
        if (media[i]->name == name) return i;
        known.push_back(media[i]->name);
    }
    std::sort(known.begin(), known.end());
    reference.fail(unknownNameMessage("medium", name, known, ListKnown::always));
}

void readWorld(const TomlTable& table, Scene& scene) {
    table.allowOnly({"background", "ambient", "medium"});
    if (auto background = table.find("background")) scene.background = background->rgb();
    if (auto ambient = table.find("ambient")) scene.ambient = ambient->rgb();
    if (auto medium = table.find("medium")) scene.worldMedium = findMedium(*medium, scene.media);
}

// Ranges as the reader states them: the loader's messages ("expected a positive number") predate
// the schema and stay word for word.
std::string expectedNumber(const Range& range) {
    if (range.isAny()) return std::string(anyNumber.expected);
    if (!range.lowExclusive && range.low == 0.0 && std::isinf(range.high)) return std::string(nonNegative.expected);
    if (range.lowExclusive && range.low == 0.0 && std::isinf(range.high)) return std::string(positive.expected);
    return "a number " + range.describe();
}

// A Colour given as a texture: `{ texture = "FILE", tint = RGB, uv_scale = N, filter = BOOL,
// colorspace = "srgb" | "linear" }`, FILE relative to the scene file's folder (materials/texture.h
// opens it). A NumberOrTexture's (`alpha`) takes one number as `tint`, may add `cutoff = N`, and
// is linear unless `colorspace` says otherwise: a mask's texels are data, not colours.
TextureReference readTexture(const TomlValue& value, const NumberRule& rule, bool scalar) {
    const TomlTable table = value.table();
    if (scalar) table.allowOnly({"texture", "tint", "cutoff", "uv_scale", "filter", "colorspace"});
    else table.allowOnly({"texture", "tint", "uv_scale", "filter", "colorspace"});
    TextureReference texture;
    if (scalar) texture.colorSpace = TextureColorSpace::linear;
    const std::filesystem::path file = table.required("texture").string();
    texture.file = (file.is_absolute() ? file : value.folder() / file).string();
    if (auto tint = table.find("tint")) texture.tint = scalar ? Vec3(tint->number(rule)) : tint->numberOrVec3(rule);
    if (auto cutoff = table.find("cutoff")) texture.cutoff = cutoff->number({0.0, 1.0, false, false, "a number 0 <= x <= 1"});
    if (auto scale = table.find("uv_scale")) texture.uvScale = scale->number(positive);
    if (auto filter = table.find("filter")) texture.filtered = filter->boolean();
    if (auto space = table.find("colorspace")) {
        const std::string name = space->string();
        if (name == "srgb") texture.colorSpace = TextureColorSpace::srgb;
        else if (name == "linear") texture.colorSpace = TextureColorSpace::linear;
        else space->expected("\"srgb\" or \"linear\"");
    }
    return texture;
}

// One value of a declaration, read as its parameter's type says and checked against its range.
void readParameter(const TomlValue& value, const Parameter& parameter, ParameterValues& values) {
    const std::string expected = expectedNumber(parameter.range);
    const NumberRule rule{parameter.range.low, parameter.range.high, parameter.range.lowExclusive,
                          parameter.range.highExclusive, expected};
    const std::string_view name = parameter.name;
    switch (parameter.type) {
        case ParameterType::Number: values.set(name, static_cast<double>(value.number(rule))); break;
        case ParameterType::Integer: {
            const auto bound = [](double x) {
                return static_cast<int>(std::clamp(x, double(std::numeric_limits<int>::min()),
                                                   double(std::numeric_limits<int>::max())));
            };
            values.set(name, value.integer(bound(parameter.range.low), bound(parameter.range.high)));
            break;
        }
        case ParameterType::Boolean: values.set(name, value.boolean()); break;
        case ParameterType::Colour:
            if (value.isTable()) values.set(name, readTexture(value, rule, false));
            else values.set(name, value.numberOrVec3(rule));
            break;
        case ParameterType::NumberOrTexture:
            if (value.isTable()) values.set(name, readTexture(value, rule, true));
            else values.set(name, static_cast<double>(value.number(rule)));
            break;
        case ParameterType::Point: values.set(name, value.vec3(rule)); break;
        case ParameterType::Vector: values.set(name, readNonZeroVector(value)); break;
        case ParameterType::PerAxis: values.set(name, value.numberOrVec3(rule)); break;
        case ParameterType::ThreePoints: {
            const std::vector<TomlValue> abc = value.array(3, "3 points [[x,y,z], [x,y,z], [x,y,z]]");
            values.set(name, std::array<Vec3, 3>{abc[0].vec3(rule), abc[1].vec3(rule), abc[2].vec3(rule)});
            break;
        }
        case ParameterType::Name: values.set(name, readName(value)); break;
        case ParameterType::Text: values.set(name, value.string()); break;
    }
    values.locate(name, value.position(), value.keyPath());
}

// Whether a declaration names its type with a `type` key (materials, lights) or by its section
// (shapes: `[[disks]]`).
enum class TypeKey : bool { allowed, absent };

// The keys a declaration of `schema` may have, in the order messages list them: a leading `name`,
// then `type` (when allowed), then the rest.
std::vector<std::string_view> allowedKeys(const TypeSchema& schema, TypeKey typeKey) {
    std::vector<std::string_view> keys;
    for (const Parameter& p : schema.parameters) keys.push_back(p.name);
    const auto at = !keys.empty() && keys.front() == "name" ? keys.begin() + 1 : keys.begin();
    if (typeKey == TypeKey::allowed) keys.insert(at, "type");
    return keys;
}

// One key of a declaration: read and checked if given, else an error at the table if required.
void readKey(const TomlTable& table, const Parameter& parameter, ParameterValues& values) {
    if (auto value = table.find(parameter.name)) {
        readParameter(*value, parameter, values);
    } else if (parameter.required) {
        table.required(parameter.name);
    }
}

// A declaration's values: every key allowed by its type's schema, each read and checked, defaults
// for the rest; a missing required key is an error at the table.
ParameterValues readValues(const TomlTable& table, const TypeSchema& schema, TypeKey typeKey = TypeKey::allowed) {
    table.allowOnly(allowedKeys(schema, typeKey));
    ParameterValues values(schema);
    values.locateDeclaration(table.position(), table.keyPath());
    for (const Parameter& parameter : schema.parameters) readKey(table, parameter, values);
    return values;
}

// The index of the material `reference` names, else a located "unknown material" error with the
// nearest name and the known ones.
std::uint32_t findMaterial(const TomlValue& reference,
                           const std::vector<MaterialSlot>& materials) {
    const std::string name = reference.string();
    std::vector<std::string> known;
    for (std::uint32_t i = 0; i < materials.size(); ++i) {
        if (materials[i]->name == name) return i;
        known.push_back(materials[i]->name);
    }
    std::sort(known.begin(), known.end());
    reference.fail(unknownNameMessage("material", name, known, ListKnown::always));
}

// A shape declaration's values: its kind's own keys first, then the `name` and `material` every
// shape has, `material` looked up among the scene's materials before the schema checks it is a
// name: so the first error a declaration reports, and its words ("unknown material", with a
// suggestion), are those the loader gave before shapes were types. A kind whose `material` is
// optional (a mesh's, else its MTL's) looks it up only when given.
ParameterValues readShapeValues(const TomlTable& table, const TypeSchema& schema,
                                const std::vector<MaterialSlot>& materials) {
    table.allowOnly(allowedKeys(schema, TypeKey::absent));
    ParameterValues values(schema);
    values.locateDeclaration(table.position(), table.keyPath());
    const auto common = [](const Parameter& p) {
        return p.name == kShapeNameParameter.name || p.name == kShapeMaterialParameter.name;
    };
    for (const Parameter& parameter : schema.parameters)
        if (!common(parameter)) readKey(table, parameter, values);
    readKey(table, kShapeNameParameter, values);
    const Parameter* materialParameter = schema.find(kShapeMaterialParameter.name);
    if (!materialParameter) return values;
    if (auto material = table.find(materialParameter->name)) {
        findMaterial(*material, materials);
        readParameter(*material, *materialParameter, values);
    } else if (materialParameter->required) {
        table.required(materialParameter->name);
    }
    return values;
}

// The registered type the table's `type` key names, the default (rank 0) when it has none.
template <typename Entry>
const Entry& typeNamedIn(const TomlTable& table, const TypeRegistry<Entry>& registry, std::string_view kind) {
    auto value = table.find("type");
    if (!value) return *registry.entries().front();
    const std::string name = value->string();
    if (const Entry* type = registry.find(name)) return *type;
    value->fail(unknownNameMessage(kind, name, registry.names(), ListKnown::always));
}

// A type's make()/addTo() refuses combinations with ParameterValues::fail, already located.
template <typename Make>
auto asSceneError(Make make) {
    try {
        return make();
    } catch (const SchemaError& error) {
        throw SceneError(error.what());
    }
}

MaterialSlot readMaterial(const std::string& name, const TomlTable& table) {
    const MaterialType& type = typeNamedIn(table, MaterialRegistry::instance(), "material type");
    const ParameterValues values = readValues(table, type.schema);
    MaterialSlot material = asSceneError([&] { return type.make(values); });
    material->name = name;
    material->textured = values.anyTexture();
    return material;
}

// Materials keep the order in which the file defines them.
std::vector<MaterialSlot> readMaterials(const TomlTable& table) {
    std::vector<MaterialSlot> materials;
    for (const auto& [name, value] : table.entries()) {
        if (!isValidName(name)) {
            value.fail("expected a material name of " + std::string(kNameCharacters) + ", got \"" +
                       name + "\"");
        }
        materials.push_back(readMaterial(name, value.table()));
    }
    return materials;
}

// Media keep the order in which the file defines them; a medium's name is its <V'NAME'> label.
std::vector<MediumSlot> readMedia(const TomlTable& table) {
    std::vector<MediumSlot> media;
    for (const auto& [name, value] : table.entries()) {
        if (!isValidName(name)) {
            value.fail("expected a medium name of " + std::string(kNameCharacters) + ", got \"" + name + "\"");
        }
        const TomlTable declaration = value.table();
        const MediumType& type = typeNamedIn(declaration, MediumRegistry::instance(), "medium type");
        const ParameterValues values = readValues(declaration, type.schema);
        MediumSlot medium = asSceneError([&] { return type.make(values); });
        medium->name = name;
        media.push_back(std::move(medium));
    }
    return media;
}

// The loader's side of SceneBuilder: light types add to the scene being read.
class LoadingScene final : public SceneBuilder {
public:
    explicit LoadingScene(Scene& scene) : scene_(scene) {}

    void addLight(LightSlot light) override { scene_.lights.push_back(std::move(light)); }
    std::uint32_t addEmitterObject(std::string name, const ColorParameter& radiance) override {
        PhongMaterial material;
        material.name = "area-light-" + std::to_string(scene_.materials.size());
        material.emission = radiance;
        scene_.materials.push_back(material);
        scene_.objects.push_back({std::move(name), static_cast<std::uint32_t>(scene_.materials.size() - 1), true});
        return static_cast<std::uint32_t>(scene_.objects.size() - 1);
    }
    void addSphere(const Sphere& sphere) override { scene_.spheres.push_back(sphere); }
    void addPlane(const Plane& plane) override { scene_.planes.push_back(plane); }
    void addTriangle(const Triangle& triangle) override { scene_.triangles.push_back(triangle); }
    void addTriangle(const Triangle& triangle, const TriangleNormals& normals) override {
        // triangleNormals is empty until a triangle has normals; then one per triangle, the
        // flat ones before it zero (Scene::triangleNormals).
        scene_.triangleNormals.resize(scene_.triangles.size());
        scene_.triangles.push_back(triangle);
        scene_.triangleNormals.push_back(normals);
    }
    void setTriangleUvs(const TriangleUvs& uvs) override {
        // Like triangleNormals: empty until a triangle has uvs, then one per triangle.
        scene_.triangleUvs.resize(scene_.triangles.size());
        scene_.triangleUvs.back() = uvs;
    }
    void setTriangleTangents(const TriangleTangents& tangents) override {
        scene_.triangleTangents.resize(scene_.triangles.size());
        scene_.triangleTangents.back() = tangents;
    }
    void setTriangleColors(const TriangleColors& colors) override {
        scene_.triangleColors.resize(scene_.triangles.size());  // white for the triangles before
        scene_.triangleColors.back() = colors;
    }
    std::uint32_t addShapeObject(const ParameterValues& values) override;
    std::uint32_t addObject(std::string name, std::uint32_t material) override {
        scene_.objects.push_back({std::move(name), material});
        return static_cast<std::uint32_t>(scene_.objects.size() - 1);
    }
    std::uint32_t addMedium(MediumSlot medium) override {
        scene_.media.push_back(std::move(medium));
        return static_cast<std::uint32_t>(scene_.media.size() - 1);
    }
    void setInterior(std::uint32_t object, std::uint32_t medium) override { scene_.objects[object].interior = medium; }
    std::uint32_t sceneMaterial(MaterialSlot material) override {
        for (std::uint32_t i = 0; i < scene_.materials.size(); ++i)
            if (scene_.materials[i]->name == material->name) return i;
        scene_.materials.push_back(std::move(material));
        return static_cast<std::uint32_t>(scene_.materials.size() - 1);
    }
    std::filesystem::path folder() const override { return scene_.source.parent_path(); }
    Rgb emissionOf(std::uint32_t object) const override {
        return scene_.materials[scene_.objects[object].material]->emission.mean();
    }
    void addShape(const ShapeRecord& shape) override { scene_.shapes.push_back(shape); }
    void warn(std::string located) override { scene_.warnings.push_back(std::move(located)); }
    bool offerCamera(const CameraDescription& camera) override {
        if (scene_.cameraGiven) return false;
        scene_.camera = camera;
        scene_.cameraGiven = true;
        return true;
    }

private:
    Scene& scene_;
};

void readLight(const TomlTable& table, Scene& scene) {
    const LightType& type = typeNamedIn(table, LightRegistry::instance(), "light type");
    const ParameterValues values = readValues(table, type.schema);
    LoadingScene builder(scene);
    asSceneError([&] { type.addTo(values, builder); });
}

std::uint32_t LoadingScene::addShapeObject(const ParameterValues& values) {
    SceneObject object;
    if (values.has("name")) object.name = values.text("name");
    const std::string& material = values.text("material");
    const auto named = [&](const MaterialSlot& m) { return m->name == material; };
    const auto found = std::find_if(scene_.materials.begin(), scene_.materials.end(), named);
    if (found == scene_.materials.end()) {
        std::vector<std::string> known;
        for (const MaterialSlot& m : scene_.materials) known.push_back(m->name);
        std::sort(known.begin(), known.end());
        values.fail("material", unknownNameMessage("material", material, known, ListKnown::always));
    }
    object.material = static_cast<std::uint32_t>(found - scene_.materials.begin());
    scene_.objects.push_back(object);
    return static_cast<std::uint32_t>(scene_.objects.size() - 1);
}

// A [[SECTION]] of a registered shape kind, read through its schema.
void readShape(const TomlTable& table, const ShapeType& type, Scene& scene) {
    const ParameterValues values = readShapeValues(table, type.schema, scene.materials);
    std::uint32_t interior = kNoMedium;
    if (auto medium = table.find(kShapeInteriorParameter.name)) interior = findMedium(*medium, scene.media);
    const std::size_t firstObject = scene.objects.size();
    LoadingScene builder(scene);
    asSceneError([&] { type.addTo(values, builder); });
    // Every object the declaration added (a mesh's parts) bounds the same medium, if its kind can:
    // its `interior`, else what its file gave (SceneBuilder::setInterior), else vacuum.
    const bool enclosesVolume = type.schema.find(kShapeInteriorParameter.name) != nullptr;
    for (std::size_t i = firstObject; i < scene.objects.size(); ++i) {
        scene.objects[i].enclosesVolume = enclosesVolume;
        if (interior != kNoMedium) scene.objects[i].interior = interior;
    }
}

// The whole file as text. Reading it here (rather than in toml++) lets a missing file report the
// operating system's reason.
std::string readFile(const std::filesystem::path& path) {
    const auto cannotOpen = [&](std::error_code reason) {
        return SceneError(path.string() + ": cannot open scene file (" + reason.message() + ")");
    };
    std::error_code ignored;  // if the check itself fails, opening the file below says why
    if (std::filesystem::is_directory(path, ignored)) {
        throw cannotOpen(std::make_error_code(std::errc::is_a_directory));
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) throw cannotOpen(std::error_code(errno, std::generic_category()));
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

toml::table parseText(std::string_view text, const std::filesystem::path& path) {
    try {
        return toml::parse(text, path.string());
    } catch (const toml::parse_error& error) {
        const toml::source_position& at = error.source().begin;
        throw SceneError(path.string() + ":" + std::to_string(at.line) + ":" +
                         std::to_string(at.column) + ": TOML syntax error: " +
                         std::string(error.description()));
    }
}

// Calls `read` on every [[key]] section of the file, in file order.
template <typename Read>
void forEachSection(const TomlTable& root, std::string_view key, Read read) {
    if (auto sections = root.find(key)) {
        for (const TomlTable& section : sections->tables()) read(section);
    }
}

}  // namespace

namespace {

std::string lowerExtension(const std::filesystem::path& path) {
    std::string extension = path.extension().string();
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return extension;
}

}  // namespace

bool isObjFile(const std::filesystem::path& path) { return lowerExtension(path) == ".obj"; }

bool isGltfFile(const std::filesystem::path& path) {
    const std::string extension = lowerExtension(path);
    return extension == ".gltf" || extension == ".glb";
}

namespace {

// `text` as a TOML basic string.
std::string tomlString(const std::string& text) {
    std::string quoted = "\"";
    for (const char c : text) {
        if (c == '"' || c == '\\') {
            quoted += '\\';
            quoted += c;
        } else if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\u%04x", static_cast<unsigned>(static_cast<unsigned char>(c)));
            quoted += escaped;
        } else {
            quoted += c;
        }
    }
    return quoted + "\"";
}

// A model file as the whole scene is the scene `[[SECTION]] file = "NAME"` beside it (`meshes` for
// OBJ, `gltf` for glTF): an OBJ has no camera and no light, which the render then chooses
// (scene/framing.h), as it does for a glTF file without them. Its messages name the model file
// only, not that one-line scene.
Scene loadModelAsScene(const std::filesystem::path& path, const std::string& section) {
    const std::string text = "[[" + section + "]]\nfile = " + tomlString(path.filename().string()) + "\n";
    const auto ownMessage = [&](const std::string& message) {
        const std::string key = section + "[0].file: ";
        const auto at = message.find(key);
        return at == std::string::npos ? message : message.substr(at + key.size());
    };
    Scene scene;
    try {
        scene = loadSceneFromText(text, path);
    } catch (const SceneError& e) {
        throw SceneError(ownMessage(e.what()));
    }
    for (std::string& warning : scene.warnings) warning = ownMessage(warning);
    return scene;
}

}  // namespace

Scene loadScene(const std::filesystem::path& path) {
    if (isObjFile(path)) {
        readFile(path);  // says why a missing or unreadable file cannot be opened, as for a scene file
        return loadModelAsScene(path, "meshes");
    }
    if (isGltfFile(path)) {
        readFile(path);
        return loadModelAsScene(path, "gltf");
    }
    return loadSceneFromText(readFile(path), path);
}

Scene loadSceneFromText(std::string_view text, const std::filesystem::path& path) {
    const toml::table document = parseText(text, path);
    const TomlTable root(document, "");
    // The registered shape kinds' sections, by rank (spheres, planes, the others, then triangles
    // and meshes): their objects are numbered in that order.
    std::vector<std::string_view> sections{"camera", "world", "materials", "media", "lights"};
    const std::vector<const ShapeType*> shapeTypes = ShapeRegistry::instance().entries();
    for (const ShapeType* type : shapeTypes) sections.push_back(type->section);
    root.allowOnly(sections);

    Scene scene;
    scene.source = path;
    if (auto camera = root.find("camera")) {
        scene.camera = readCamera(camera->table());
        scene.cameraGiven = true;
    }
    // Media before the world and the shapes, which name them.
    if (auto media = root.find("media")) scene.media = readMedia(media->table());
    if (auto world = root.find("world")) readWorld(world->table(), scene);
    if (auto materials = root.find("materials")) {
        scene.materials = readMaterials(materials->table());
        for (const MaterialSlot& m : scene.materials) scene.interfaces = scene.interfaces || m->isInterface();
    }
    forEachSection(root, "lights", [&](const TomlTable& light) { readLight(light, scene); });
    // Objects are numbered by each registered shape kind's rank (spheres first, then planes, the
    // others, triangles and meshes), each in file order.
    for (const ShapeType* type : shapeTypes)
        forEachSection(root, type->section, [&](const TomlTable& shape) { readShape(shape, *type, scene); });
    // Flat triangles after the last one with normals have none yet.
    if (!scene.triangleNormals.empty()) scene.triangleNormals.resize(scene.triangles.size());
    if (!scene.triangleUvs.empty()) scene.triangleUvs.resize(scene.triangles.size());
    if (!scene.triangleTangents.empty()) scene.triangleTangents.resize(scene.triangles.size());
    if (!scene.triangleColors.empty()) scene.triangleColors.resize(scene.triangles.size());
    // An emitter is never cut out (Scene::objectCoverage): said once for each material that is both.
    for (const MaterialSlot& m : scene.materials)
        if (m->alpha && !m->emission.black())
            scene.warnings.push_back("material \"" + m->name + "\" emits, so its alpha is not read: an emitter is never cut out");
    // Nor is the boundary of a medium (Scene::objectCoverage): said once for each such object.
    for (std::uint32_t i = 0; i < scene.objects.size(); ++i)
        if (scene.objects[i].interior != kNoMedium && scene.materials[scene.objects[i].material]->alpha)
            scene.warnings.push_back("object \"" + scene.labelOf(i) +
                                     "\" bounds a medium (interior), so its alpha is not read: a ray through a hole "
                                     "would be inside it without having entered");
    return scene;
}

}  // namespace lightpath
