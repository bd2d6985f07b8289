#include "scene/scene_loader.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <limits>
#include <fstream>
#include <optional>
#include <sstream>
#include <system_error>

#include "scene/light_type.h"
#include "scene/shape_type.h"
#include "materials/material_type.h"
#include "materials/phong_material.h"
#include "schema/parameter.h"
#include "schema/schema_error.h"
#include "scene/obj_loader.h"
#include "scene/spelling.h"
#include "scene/toml_reader.h"

namespace lightpath {
namespace {

std::string readName(const TomlValue& value) {
    std::string name = value.string();
    if (!isValidName(name)) value.expected("a name of " + std::string(kNameCharacters));
    return name;
}

// The cross product of two parallel vectors vanishes; compare against their lengths so the test
// does not depend on how long the student wrote them.
bool areParallel(const Vec3& a, const Vec3& b) {
    const glm::dvec3 da(a), db(b);
    return glm::length(glm::cross(da, db)) <= 1e-6 * glm::length(da) * glm::length(db);
}

Vec3 readNonZeroVector(const TomlValue& value) {
    const Vec3 v = value.vec3();
    if (v == Vec3(0.0f)) value.fail("expected a non-zero vector, got " + formatVec3(v));
    return v;
}

CameraDescription readCamera(const TomlTable& table) {
    table.allowOnly({"eye", "look_at", "up", "fov", "resolution"});
    CameraDescription camera;
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

void readWorld(const TomlTable& table, Scene& scene) {
    table.allowOnly({"background", "ambient"});
    if (auto background = table.find("background")) scene.background = background->rgb();
    if (auto ambient = table.find("ambient")) scene.ambient = ambient->rgb();
}

// Ranges as the reader states them: the loader's messages ("expected a positive number") predate
// the schema and stay word for word.
std::string expectedNumber(const Range& range) {
    if (range.isAny()) return std::string(anyNumber.expected);
    if (!range.lowExclusive && range.low == 0.0 && std::isinf(range.high)) return std::string(nonNegative.expected);
    if (range.lowExclusive && range.low == 0.0 && std::isinf(range.high)) return std::string(positive.expected);
    return "a number " + range.describe();
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
        case ParameterType::Colour: values.set(name, value.rgb()); break;
        case ParameterType::Point: values.set(name, value.vec3(rule)); break;
        case ParameterType::Vector: values.set(name, readNonZeroVector(value)); break;
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
// suggestion), are those the loader gave before shapes were types.
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
    const TomlValue material = table.required(kShapeMaterialParameter.name);
    findMaterial(material, materials);
    readParameter(material, kShapeMaterialParameter, values);
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

// The loader's side of SceneBuilder: light types add to the scene being read.
class LoadingScene final : public SceneBuilder {
public:
    explicit LoadingScene(Scene& scene) : scene_(scene) {}

    void addLight(LightSlot light) override { scene_.lights.push_back(std::move(light)); }
    std::uint32_t addEmitterObject(std::string name, const Rgb& radiance) override {
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
    std::uint32_t addShapeObject(const ParameterValues& values) override;
    Rgb emissionOf(std::uint32_t object) const override {
        return scene_.materials[scene_.objects[object].material]->emission;
    }
    void addShape(const ShapeRecord& shape) override { scene_.shapes.push_back(shape); }
    void warn(std::string located) override { scene_.warnings.push_back(std::move(located)); }

private:
    Scene& scene_;
};

void readLight(const TomlTable& table, Scene& scene) {
    const LightType& type = typeNamedIn(table, LightRegistry::instance(), "light type");
    const ParameterValues values = readValues(table, type.schema);
    LoadingScene builder(scene);
    asSceneError([&] { type.addTo(values, builder); });
}

// A shape that emits but is too small to be light-sampled is said once, where it is declared.
void warnIfTooSmallToSample(const TomlValue& where, const char* what, double area, const Rgb& emission, Scene& scene) {
    if (auto warning = tooSmallToSampleWarning(what, area, emission)) scene.warnings.push_back(where.located(*warning));
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
    LoadingScene builder(scene);
    asSceneError([&] { type.addTo(values, builder); });
}

// Every shape is one scene object: its name (optional) and material are read here; the returned
// index is what the shape stores in its `object` field.
std::uint32_t addObject(const TomlTable& table, Scene& scene) {
    SceneObject object;
    if (auto name = table.find("name")) object.name = readName(*name);
    object.material = findMaterial(table.required("material"), scene.materials);
    scene.objects.push_back(object);
    return static_cast<std::uint32_t>(scene.objects.size() - 1);
}

Triangle readTriangle(const TomlTable& table, Scene& scene) {
    table.allowOnly({"name", "vertices", "material"});
    const TomlValue vertices = table.required("vertices");
    const std::vector<TomlValue> abc = vertices.array(3, "3 points [[x,y,z], [x,y,z], [x,y,z]]");
    Triangle triangle;
    triangle.a = abc[0].vec3();
    triangle.b = abc[1].vec3();
    triangle.c = abc[2].vec3();
    // Legal but invisible: a triangle without area is never hit (its determinant is zero), so it
    // is kept and only worth a warning.
    if (areParallel(triangle.b - triangle.a, triangle.c - triangle.a)) {
        scene.warnings.push_back(vertices.located("the 3 points lie on one line: the triangle has no area and is never seen"));
    }
    triangle.object = addObject(table, scene);
    if (!areParallel(triangle.b - triangle.a, triangle.c - triangle.a)) {
        warnIfTooSmallToSample(vertices, "triangle", surfaceArea(triangle),
                               scene.materials[scene.objects.back().material]->emission, scene);
    }
    return triangle;
}

// scale, then rotate_y, then translate: a mesh is placed as its file describes it, resized about
// its own origin, turned about the vertical axis and moved.
struct MeshPlacement {
    Vec3 scale{1.0f};
    float rotateY = 0.0f;  // radians
    Vec3 translate{0.0f};

    Vec3 point(Vec3 p) const {
        p *= scale;
        const float c = std::cos(rotateY), s = std::sin(rotateY);
        return Vec3(c * p.x + s * p.z, p.y, -s * p.x + c * p.z) + translate;
    }
    // Normals take the inverse transpose: divide by the scale, rotate like points.
    Vec3 normal(Vec3 n) const {
        if (n == Vec3(0.0f)) return n;
        n /= scale;
        const float c = std::cos(rotateY), s = std::sin(rotateY);
        return glm::normalize(Vec3(c * n.x + s * n.z, n.y, -s * n.x + c * n.z));
    }
};

MeshPlacement readPlacement(const TomlTable& table) {
    MeshPlacement placement;
    if (auto scale = table.find("scale")) {
        placement.scale = scale->rgb();
        if (placement.scale.x <= 0.0f || placement.scale.y <= 0.0f || placement.scale.z <= 0.0f)
            scale->fail("expected a positive number or 3 positive numbers, got " + formatVec3(placement.scale));
    }
    if (auto rotate = table.find("rotate_y")) placement.rotateY = glm::radians(rotate->number());
    if (auto translate = table.find("translate")) placement.translate = translate->vec3();
    return placement;
}

// The scene material called `name`, added from the mesh's MTL unless the scene (its
// [materials] or an earlier mesh) already has one of that name, which then wins.
std::uint32_t sceneMaterialFor(const PhongMaterial& mtl, Scene& scene) {
    for (std::uint32_t i = 0; i < scene.materials.size(); ++i)
        if (scene.materials[i]->name == mtl.name) return i;
    scene.materials.push_back(mtl);
    return static_cast<std::uint32_t>(scene.materials.size() - 1);
}

// A [[meshes]] entry: every MTL material used becomes one scene object (labelled by the mesh's
// name, else by the material's MTL name); `material` puts the whole mesh in one scene material.
void readMesh(const TomlTable& table, const std::filesystem::path& sceneFile, Scene& scene) {
    table.allowOnly({"name", "file", "material", "scale", "rotate_y", "translate"});
    const TomlValue fileValue = table.required("file");
    const std::filesystem::path file = sceneFile.parent_path() / fileValue.string();
    ObjMesh mesh;
    try {
        mesh = loadObj(file);
    } catch (const SceneError& e) {
        fileValue.fail(e.what());
    }
    std::string name;
    if (auto nameValue = table.find("name")) name = readName(*nameValue);
    std::optional<std::uint32_t> override;
    if (auto material = table.find("material")) override = findMaterial(*material, scene.materials);
    const MeshPlacement placement = readPlacement(table);
    // A missing material library is only a warning (most tools go on); a face whose `usemtl`
    // names a material no library defines is an error only when the scene gives no `material`.
    for (const std::string& library : mesh.missingLibraries) {
        scene.warnings.push_back(fileValue.located(
            file.string() + ": cannot open material library \"" + library + "\" named by its mtllib line; " +
            (override ? "the mesh's `material` is used" : "faces without a known material are grey")));
    }
    if (!override && !mesh.unknownMaterials.empty()) {
        fileValue.fail(file.string() + ": usemtl \"" + mesh.unknownMaterials.front() +
                       "\" names no material of its material libraries" +
                       (mesh.missingLibraries.empty() ? "" : " (\"" + mesh.missingLibraries.front() + "\" is missing)") +
                       "; give the mesh a `material`");
    }

    // Scene object of each MTL material index, created on first use, in order of first use.
    std::vector<std::uint32_t> objectOf(mesh.materials.size() + 1, kNoMeshMaterial);
    const auto objectFor = [&](std::uint32_t mtlIndex) {
        // With `material`, the whole mesh is one object.
        const std::size_t slot = override || mtlIndex == kNoMeshMaterial ? mesh.materials.size() : mtlIndex;
        if (objectOf[slot] != kNoMeshMaterial) return objectOf[slot];
        SceneObject object;
        object.name = name;
        if (override) {
            object.material = *override;
        } else if (mtlIndex == kNoMeshMaterial) {
            object.material = sceneMaterialFor(defaultMeshMaterial(), scene);
        } else {
            const PhongMaterial& mtl = mesh.materials[mtlIndex];
            if (!isValidName(mtl.name))
                fileValue.fail(file.string() + ": material \"" + mtl.name + "\" is not a name of " +
                               std::string(kNameCharacters) + "; give the mesh a `material`");
            object.material = sceneMaterialFor(mtl, scene);
        }
        scene.objects.push_back(object);
        objectOf[slot] = static_cast<std::uint32_t>(scene.objects.size() - 1);
        return objectOf[slot];
    };

    if (mesh.degenerateDropped > 0) {
        scene.warnings.push_back(fileValue.located(std::to_string(mesh.degenerateDropped) +
                                                   " faces without area were left out"));
    }
    const bool smooth = !mesh.normals.empty();
    if (smooth && scene.triangleNormals.empty()) scene.triangleNormals.resize(scene.triangles.size());
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
        const Triangle& t = mesh.triangles[i];
        const Triangle placed{placement.point(t.a), placement.point(t.b), placement.point(t.c), objectFor(t.object)};
        // The limit of the file's own numbers holds for the mesh's vertices where they end up.
        for (const Vec3& corner : {placed.a, placed.b, placed.c}) {
            if (!(glm::all(glm::lessThanEqual(glm::abs(corner), Vec3(kMaxMagnitude))))) {
                fileValue.fail(file.string() + ": triangle " + std::to_string(i + 1) + " has a corner at " +
                               formatVec3(corner) + " once placed; expected coordinates " + std::string(kMagnitudeRange));
            }
        }
        scene.triangles.push_back(placed);
        if (smooth) {
            const TriangleNormals& n = mesh.normals[i];
            scene.triangleNormals.push_back({placement.normal(n.a), placement.normal(n.b), placement.normal(n.c)});
        } else if (!scene.triangleNormals.empty()) {
            scene.triangleNormals.emplace_back();
        }
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

Scene loadScene(const std::filesystem::path& path) {
    return loadSceneFromText(readFile(path), path);
}

Scene loadSceneFromText(std::string_view text, const std::filesystem::path& path) {
    const toml::table document = parseText(text, path);
    const TomlTable root(document, "");
    // The registered shape kinds' sections, by rank (spheres, planes, then the others): their
    // objects are numbered in that order.
    std::vector<std::string_view> sections{"camera", "world", "materials", "lights"};
    const std::vector<const ShapeType*> shapeTypes = ShapeRegistry::instance().entries();
    for (const ShapeType* type : shapeTypes) sections.push_back(type->section);
    sections.insert(sections.end(), {"triangles", "meshes"});
    root.allowOnly(sections);

    Scene scene;
    scene.source = path;
    if (auto camera = root.find("camera")) scene.camera = readCamera(camera->table());
    if (auto world = root.find("world")) readWorld(world->table(), scene);
    if (auto materials = root.find("materials")) {
        scene.materials = readMaterials(materials->table());
    }
    forEachSection(root, "lights", [&](const TomlTable& light) { readLight(light, scene); });
    // Objects are numbered by each registered shape kind's rank (spheres first, then planes, then
    // the others), then triangles, each in file order.
    for (const ShapeType* type : shapeTypes)
        forEachSection(root, type->section, [&](const TomlTable& shape) { readShape(shape, *type, scene); });
    forEachSection(root, "triangles", [&](const TomlTable& triangle) {
        scene.triangles.push_back(readTriangle(triangle, scene));
    });
    forEachSection(root, "meshes", [&](const TomlTable& mesh) { readMesh(mesh, path, scene); });
    if (!scene.triangleNormals.empty()) scene.triangleNormals.resize(scene.triangles.size());
    return scene;
}

}  // namespace lightpath
