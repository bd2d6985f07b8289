#include "shapes/gltf_loader.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <sstream>
#include <string_view>
#include <utility>

#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "materials/dielectric_material.h"
#include "materials/microfacet_material.h"
#include "materials/phong_material.h"
#include "materials/texture.h"
#include "scene/scene_loader.h"
#include "schema/format.h"
#include "schema/parameter.h"
#include "shapes/obj_loader.h"

namespace lightpath {
namespace {

// The extensions the Reader reads; docs: scenes/README.md, [[gltf]].
constexpr std::array<std::string_view, 9> kReadExtensions{
    "KHR_lights_punctual",        "KHR_materials_clearcoat",    "KHR_materials_emissive_strength",
    "KHR_materials_ior",          "KHR_materials_specular",     "KHR_materials_transmission",
    "KHR_materials_volume",       "KHR_mesh_quantization",      "KHR_texture_transform"};

// glTF's own default material (glTF 2.0, 3.9.6): metallic-roughness with every factor 1.
constexpr const char* kDefaultMaterialLabel = "gltf-default";

// The encoded bytes of each image given by a URI (a data URI or a file beside the glTF, which
// tinygltf percent-decodes and reads), filled by the image loader; images in bufferViews are read
// by the Reader, bounds-checked.
using ImageBytes = std::vector<std::vector<unsigned char>>;

class Reader {
public:
    Reader(const tinygltf::Model& model, const std::filesystem::path& file, const ImageBytes& images)
        : model_(model), file_(file), imageBytes_(images) {}

    GltfModel read() {
        checkExtensions();
        warnUnread();
        findVertexColors();
        readMaterials();
        const std::vector<int> roots = rootNodes();
        visited_.assign(model_.nodes.size(), false);
        for (int root : roots) visit(root, glm::dmat4(1.0), "scene nodes");
        return std::move(out_);
    }

private:
    [[noreturn]] void fail(const std::string& where, const std::string& what) const {
        throw SceneError(file_.string() + ": " + where + ": " + what);
    }
    void warn(const std::string& text) { out_.warnings.push_back(file_.string() + ": " + text); }

    // A label for `name` unique among `taken`: the name made a label, numbered on a collision;
    // `fallback` when the name is empty. A changed name is reported in `renamed`.
    std::string label(const std::string& name, const std::string& fallback, std::vector<std::string>& taken,
                      const std::string& what) {
        const std::string base = name.empty() ? fallback : labelFromName(name);
        std::string result = base;
        for (int k = 2; std::find(taken.begin(), taken.end(), result) != taken.end(); ++k)
            result = base + "-" + std::to_string(k);
        taken.push_back(result);
        if (!name.empty() && result != name) out_.renamed.push_back({what, printableName(name), result});
        return result;
    }

    static bool finite(double x) { return std::isfinite(x) && std::abs(x) <= kMaxMagnitude; }

    // A factor of `count` numbers each within [low, high], else its default.
    std::vector<double> factor(const std::vector<double>& given, std::size_t count, double low, double high,
                               std::vector<double> fallback, const std::string& where) const {
        if (given.empty()) return fallback;
        if (given.size() != count)
            fail(where, "expected " + std::to_string(count) + " numbers, got " + std::to_string(given.size()));
        for (double x : given)
            if (!(x >= low && x <= high))
                fail(where, "expected numbers from " + formatNumber(low) + " to " + formatNumber(high) + ", got " +
                                formatNumber(x));
        return given;
    }
    double number(double given, double low, double high, const std::string& where) const {
        if (!(given >= low && given <= high))
            fail(where, "expected a number from " + formatNumber(low) + " to " + formatNumber(high) + ", got " +
                            formatNumber(given));
        return given;
    }

    // glTF 2.0, 3.12: a file that requires an extension this reader does not read cannot be read as
    // meant (a Draco-compressed mesh keeps its triangles in the extension): refused, naming it. One
    // it merely uses is left out, with a warning, so that what a viewer shows and this render omits
    // is said (KHR_materials_clearcoat, say, which adds a coat over a surface).
    void checkExtensions() {
        const auto reads = [](const std::string& name) {
            return std::find(kReadExtensions.begin(), kReadExtensions.end(), name) != kReadExtensions.end();
        };
        std::string known;
        for (std::string_view name : kReadExtensions) known += (known.empty() ? "" : ", ") + std::string(name);
        for (std::size_t i = 0; i < model_.extensionsRequired.size(); ++i)
            if (!reads(model_.extensionsRequired[i]))
                fail("extensionsRequired[" + std::to_string(i) + "]",
                     "the file requires \"" + printableName(model_.extensionsRequired[i]) +
                         "\", which lightpath does not read (it reads " + known + ")");
        const auto lists = [](const std::vector<std::string>& names, std::string_view name) {
            return std::find(names.begin(), names.end(), name) != names.end();
        };
        quantized_ = lists(model_.extensionsUsed, "KHR_mesh_quantization") ||
                     lists(model_.extensionsRequired, "KHR_mesh_quantization");
        std::string left;
        std::size_t count = 0;
        for (const std::string& name : model_.extensionsUsed)
            if (!reads(name)) {
                left += (left.empty() ? "" : ", ") + printableName(name);
                ++count;
            }
        if (count > 0)
            warn("extensionsUsed: " + left + (count == 1 ? " is" : " are") +
                 " not read by lightpath: the render leaves " + (count == 1 ? "it" : "them") + " out");
    }

    // What a still render leaves out of the file, said once each rather than dropped in silence.
    void warnUnread() {
        if (const std::size_t n = model_.animations.size(); n > 0)
            warn("animations: " + std::to_string(n) + (n == 1 ? " animation is" : " animations are") +
                 " not played: the scene renders as its nodes stand");
        if (!model_.skins.empty())
            warn("skins: not applied: a skinned mesh renders as its vertices stand, placed by its node");
        for (const tinygltf::Mesh& mesh : model_.meshes)
            for (const tinygltf::Primitive& primitive : mesh.primitives)
                if (!primitive.targets.empty()) {
                    warn("meshes[" + std::to_string(&mesh - model_.meshes.data()) +
                         "]: morph targets are not applied: the mesh renders without them");
                    break;
                }
    }

    // An extension object's colour `key`: three numbers from 0 to `high`, else white when absent;
    // anything else is an error located at `at`.key.
    Rgb extensionRgb(const tinygltf::Value& extension, const std::string& key, double high, const std::string& at) const {
        Rgb colour{1.0f};
        if (!extension.Has(key)) return colour;
        const std::string expected = "expected three numbers from 0 to " + formatNumber(high);
        const tinygltf::Value& c = extension.Get(key);
        if (!c.IsArray() || c.ArrayLen() != 3) fail(at + "." + key, expected);
        for (int k = 0; k < 3; ++k) {
            const tinygltf::Value& x = c.Get(k);
            const double value = x.IsNumber() ? x.GetNumberAsDouble() : std::nan("");
            if (!(value >= 0.0 && value <= high)) fail(at + "." + key, expected);
            colour[k] = float(value);
        }
        return colour;
    }

    // A number in an extension object, else `fallback`.
    static double extensionNumber(const tinygltf::ExtensionMap& extensions, const std::string& extension,
                                  const std::string& key, double fallback) {
        const auto found = extensions.find(extension);
        if (found == extensions.end() || !found->second.IsObject() || !found->second.Has(key)) return fallback;
        const tinygltf::Value& value = found->second.Get(key);
        return value.IsNumber() ? value.GetNumberAsDouble() : std::nan("");
    }

    // The dielectric's F0 of an opaque material: ((n - 1)/(n + 1))^2 of KHR_materials_ior's n,
    // times KHR_materials_specular's specularColorFactor (clamped to 1), as Blender writes its
    // Principled BSDF's specular (F0 = 0.08 specular); specularFactor, which the extension applies
    // to the whole specular layer, scales F0 here (a warning), and its textures are not read.
    Rgb dielectricF0(const tinygltf::Material& m, double ior, const std::string& where) {
        const float f0 = float(((ior - 1.0) / (ior + 1.0)) * ((ior - 1.0) / (ior + 1.0)));
        const auto found = m.extensions.find("KHR_materials_specular");
        if (found == m.extensions.end()) return Rgb{f0};
        const std::string at = where + ".extensions.KHR_materials_specular";
        const tinygltf::Value& e = found->second;
        if (!e.IsObject()) fail(at, "expected an object");
        const Rgb colour = extensionRgb(e, "specularColorFactor", kMaxMagnitude, at);
        const double weight = number(extensionNumber(m.extensions, "KHR_materials_specular", "specularFactor", 1.0), 0.0,
                                     1.0, at + ".specularFactor");
        if (weight != 1.0)
            warn(at + ".specularFactor " + formatNumber(weight) +
                 " scales the reflectance at normal incidence only; at grazing angles the surface still reflects all");
        for (const char* texture : {"specularTexture", "specularColorTexture"})
            if (e.Has(texture)) warn(at + "." + texture + " is not read: its factor alone is used");
        return glm::min(Rgb{1.0f}, f0 * colour) * float(weight);
    }

    // Which materials' primitives carry COLOR_0 (the last slot: primitives without a material): their
    // base colour is multiplied by it (glTF 2.0, 3.7.2.1), a material's parameter built once. And
    // which MASK or BLEND materials' primitives give some vertex an alpha below 1: that alpha
    // multiplies theirs, so they keep their cut-out even where their own alpha is 1.
    void findVertexColors() {
        coloredMaterial_.assign(model_.materials.size() + 1, false);
        vertexAlphaMaterial_.assign(model_.materials.size(), false);
        for (std::size_t m = 0; m < model_.meshes.size(); ++m)
            for (std::size_t p = 0; p < model_.meshes[m].primitives.size(); ++p) {
                const tinygltf::Primitive& primitive = model_.meshes[m].primitives[p];
                const auto color = primitive.attributes.find("COLOR_0");
                if (color == primitive.attributes.end()) continue;
                const bool named = primitive.material >= 0 && std::size_t(primitive.material) < model_.materials.size();
                coloredMaterial_[named ? std::size_t(primitive.material) : model_.materials.size()] = true;
                if (!named || vertexAlphaMaterial_[std::size_t(primitive.material)]) continue;
                const std::string& mode = model_.materials[std::size_t(primitive.material)].alphaMode;
                if (mode != "MASK" && mode != "BLEND") continue;
                const std::string where = "meshes[" + std::to_string(m) + "].primitives[" + std::to_string(p) +
                                          "].attributes.COLOR_0";
                for (const Vec4& c : vertexColors(color->second, where))
                    if (c.w < 1.0f) vertexAlphaMaterial_[std::size_t(primitive.material)] = true;
            }
    }

    // `parameter`, times the vertex colour when the material's primitives have one.
    static ColorParameter colored(ColorParameter parameter, bool vertexColors) {
        return vertexColors ? parameter.timesVertexColor() : parameter;
    }

    void readMaterials() {
        std::vector<std::string> taken;
        for (std::size_t i = 0; i < model_.materials.size(); ++i) {
            const tinygltf::Material& m = model_.materials[i];
            const std::string where = "materials[" + std::to_string(i) + "]";
            uvSet_ = kNoUvSet;
            const auto& pbr = m.pbrMetallicRoughness;
            const std::vector<double> base =
                factor(pbr.baseColorFactor, 4, 0.0, 1.0, {1, 1, 1, 1}, where + ".pbrMetallicRoughness.baseColorFactor");
            const Rgb baseColor{float(base[0]), float(base[1]), float(base[2])};
            const float metallic = float(number(pbr.metallicFactor, 0.0, 1.0, where + ".pbrMetallicRoughness.metallicFactor"));
            const float roughness = float(number(pbr.roughnessFactor, 0.0, 1.0, where + ".pbrMetallicRoughness.roughnessFactor"));
            const std::vector<double> emissive = factor(m.emissiveFactor, 3, 0.0, 1.0, {0, 0, 0}, where + ".emissiveFactor");
            const double strength = number(extensionNumber(m.extensions, "KHR_materials_emissive_strength", "emissiveStrength", 1.0),
                                           0.0, kMaxMagnitude, where + ".extensions.KHR_materials_emissive_strength.emissiveStrength");
            const double transmission = number(extensionNumber(m.extensions, "KHR_materials_transmission", "transmissionFactor", 0.0),
                                               0.0, 1.0, where + ".extensions.KHR_materials_transmission.transmissionFactor");
            const double ior = number(extensionNumber(m.extensions, "KHR_materials_ior", "ior", 1.5), 1.0, kMaxMagnitude,
                                      where + ".extensions.KHR_materials_ior.ior");
            const bool vertexColors = coloredMaterial_[i];
            // The base colour's texture, opened (and any warning about it given) once, when the
            // base colour or alpha first reads it.
            std::optional<std::optional<OpenedTexture>> baseTexture;
            const auto baseColorTexture = [&]() -> const std::optional<OpenedTexture>& {
                if (!baseTexture)
                    baseTexture = open(pbr.baseColorTexture, TextureColorSpace::srgb,
                                       where + ".pbrMetallicRoughness.baseColorTexture");
                return *baseTexture;
            };
            MaterialSlot material = [&]() -> MaterialSlot {
                if (transmission > 0.0) {
                    if (m.extensions.count("KHR_materials_clearcoat") != 0)
                        warn(where + ".extensions.KHR_materials_clearcoat: a transmitting material is rendered without "
                                     "its clear coat");
                    // Rough: the rough dielectric (Walter et al. 2007), whose tint is the transmitted
                    // share of the base colour; it has no diffuse base for the rest (a warning).
                    if (roughness > 0.0f) {
                        if (transmission < 1.0 || metallic > 0.0f)
                            warn(where + ": a rough transmitting material is rendered as rough glass tinted by " +
                                 "transmission * baseColor; its diffuse and metallic share is dropped");
                        return DielectricMaterial(float(ior), colored(float(transmission) * baseColor, vertexColors),
                                                  roughness);
                    }
                    // Smooth: Fresnel glass of the lecture's material (its kt tints the mirror ray
                    // too, which the dielectric's tint does not), with the rest as its diffuse part.
                    PhongMaterial glass;
                    glass.kd = colored(float(1.0 - transmission) * (1.0f - metallic) * baseColor, vertexColors);
                    glass.kt = colored(float(transmission) * baseColor, vertexColors);
                    glass.ior = float(ior);
                    glass.fresnel = true;
                    return glass;
                }
                const std::string at = where + ".pbrMetallicRoughness";
                ColorParameter base(baseColor);
                ScalarParameter metal(metallic), rough(roughness);
                if (const auto& texture = baseColorTexture()) base = ColorParameter(texture->first, baseColor, texture->second);
                // glTF 2.0, 3.9.2: metalness in B, roughness in G, linear, times the factors.
                if (auto texture = open(pbr.metallicRoughnessTexture, TextureColorSpace::linear,
                                        at + ".metallicRoughnessTexture")) {
                    metal = ScalarParameter(texture->first, 2, metallic, texture->second);
                    rough = ScalarParameter(texture->first, 1, roughness, texture->second);
                }
                MicrofacetMaterial::Clearcoat coat = clearcoat(m, where);
                const bool textured =
                    base.textured() || metal.textured() || coat.weight.textured() || coat.roughness.textured();
                MaterialSlot slot = MicrofacetMaterial(colored(std::move(base), vertexColors), std::move(metal),
                                                       std::move(rough), dielectricF0(m, ior, where), std::move(coat));
                slot->textured = textured;  // shading points then carry their uv and footprint
                return slot;
            }();
            // glTF 2.0, 3.9.3: the sRGB emissiveTexture times emissiveFactor (times the strength).
            const Rgb emission = float(strength) * Rgb(float(emissive[0]), float(emissive[1]), float(emissive[2]));
            material->emission = emission;
            if (auto texture = open(m.emissiveTexture, TextureColorSpace::srgb, where + ".emissiveTexture")) {
                if (isBlack(emission))
                    warn(where + ".emissiveTexture: its emissiveFactor (default [0, 0, 0]) is black: it emits nothing");
                else
                    material->emission = ColorParameter(texture->first, emission, texture->second);
            }
            // A doubleSided surface is lit and seen from both sides (glTF 2.0, 3.9.5), so it emits
            // from both too, as Blender's mesh lights do in Cycles (Blender writes doubleSided
            // unless backface culling is on).
            material->twoSidedEmission = m.doubleSided;
            material->alpha = alpha(m, float(base[3]), where, baseColorTexture, vertexAlphaMaterial_[i]);
            material->vertexColored = vertexColors;
            material->name = label(m.name, "material-" + std::to_string(i), taken, where);
            if (auto texture = open(m.normalTexture, TextureColorSpace::linear, where + ".normalTexture")) {
                material->normalMap = {texture->first, float(number(m.normalTexture.scale, -kMaxMagnitude, kMaxMagnitude,
                                                                    where + ".normalTexture.scale")),
                                       texture->second};
                material->textured = true;
            }
            out_.materials.push_back(std::move(material));
            out_.absorption.push_back(volumeAbsorption(m, where, transmission > 0.0));
            uvSetOfMaterial_.push_back(uvSet_);
        }
        materialLabels_ = std::move(taken);
    }

    // KHR_materials_clearcoat: the coat's weight, clearcoatFactor times clearcoatTexture's R, and
    // its roughness, clearcoatRoughnessFactor times clearcoatRoughnessTexture's G (both linear).
    // No extension: no coat. Its own normal map is not read: the coat takes the surface's normal.
    MicrofacetMaterial::Clearcoat clearcoat(const tinygltf::Material& m, const std::string& where) {
        MicrofacetMaterial::Clearcoat coat;
        const auto found = m.extensions.find("KHR_materials_clearcoat");
        if (found == m.extensions.end()) return coat;
        const std::string at = where + ".extensions.KHR_materials_clearcoat";
        const tinygltf::Value& e = found->second;
        if (!e.IsObject()) fail(at, "expected an object");
        const float weight = float(
            number(extensionNumber(m.extensions, "KHR_materials_clearcoat", "clearcoatFactor", 0.0), 0.0, 1.0, at + ".clearcoatFactor"));
        const float roughness = float(number(extensionNumber(m.extensions, "KHR_materials_clearcoat", "clearcoatRoughnessFactor", 0.0),
                                             0.0, 1.0, at + ".clearcoatRoughnessFactor"));
        coat.weight = weight;
        coat.roughness = roughness;
        if (weight == 0.0f) return coat;  // glTF: a factor of 0 disables the coat, whatever its texture
        if (auto texture = open(extensionTexture(e, "clearcoatTexture", at), TextureColorSpace::linear,
                                at + ".clearcoatTexture"))
            coat.weight = ScalarParameter(texture->first, 0, weight, texture->second);
        if (auto texture = open(extensionTexture(e, "clearcoatRoughnessTexture", at), TextureColorSpace::linear,
                                at + ".clearcoatRoughnessTexture"))
            coat.roughness = ScalarParameter(texture->first, 1, roughness, texture->second);
        if (e.Has("clearcoatNormalTexture"))
            warn(at + ".clearcoatNormalTexture is not read: the coat takes the surface's normal");
        return coat;
    }

    // KHR_materials_volume: the surface bounds a medium that absorbs sigma_a = -ln(attenuationColor)
    // / attenuationDistance per channel (Beer-Lambert: white light is attenuationColor after that
    // distance). Only where light enters (a transmitting material) and the surface is no thin wall
    // (thicknessFactor > 0) with a finite distance. thicknessTexture is a rasteriser's stand-in for
    // the distance a ray travels inside, which a ray tracer measures: not read, and not needed.
    std::optional<Rgb> volumeAbsorption(const tinygltf::Material& m, const std::string& where, bool transmits) {
        const auto found = m.extensions.find("KHR_materials_volume");
        if (found == m.extensions.end()) return std::nullopt;
        const std::string at = where + ".extensions.KHR_materials_volume";
        const tinygltf::Value& e = found->second;
        if (!e.IsObject()) fail(at, "expected an object");
        const double thickness = number(extensionNumber(m.extensions, "KHR_materials_volume", "thicknessFactor", 0.0), 0.0,
                                        kMaxMagnitude, at + ".thicknessFactor");
        // Absent, the distance is infinite: nothing is absorbed.
        double distance = std::numeric_limits<double>::infinity();
        if (e.Has("attenuationDistance")) {
            distance = extensionNumber(m.extensions, "KHR_materials_volume", "attenuationDistance", distance);
            if (!(distance > 0.0) || !finite(distance))
                fail(at + ".attenuationDistance", "expected a number above 0 and at most " +
                                                      std::string(kMaxMagnitudeText) + ", got " + formatNumber(distance));
        }
        const Rgb colour = extensionRgb(e, "attenuationColor", 1.0, at);
        if (!transmits || thickness == 0.0 || std::isinf(distance)) return std::nullopt;
        // A channel of 0 absorbs everything: the largest coefficient a scene may hold. ln(1 / c),
        // not -ln(c): a channel of 1 absorbs +0, not -0.
        Rgb sigma;
        for (int k = 0; k < 3; ++k)
            sigma[k] = float(std::min(std::log(1.0 / double(colour[k])) / distance, kMaxMagnitude));
        return sigma;
    }

    // A textureInfo inside an extension object (tinygltf leaves it as JSON): its index, texCoord
    // and extensions; index -1 when the key is absent.
    tinygltf::TextureInfo extensionTexture(const tinygltf::Value& object, const std::string& key,
                                           const std::string& where) const {
        tinygltf::TextureInfo info;
        if (!object.Has(key)) return info;
        const std::string at = where + "." + key;
        const tinygltf::Value& t = object.Get(key);
        if (!t.IsObject()) fail(at, "expected a textureInfo object");
        if (!t.Has("index") || !t.Get("index").IsInt() || t.Get("index").GetNumberAsInt() < 0)
            fail(at + ".index", "expected a texture index of 0 or more");
        info.index = t.Get("index").GetNumberAsInt();
        if (t.Has("texCoord")) {
            if (!t.Get("texCoord").IsInt()) fail(at + ".texCoord", "expected a set from 0 to " + std::to_string(kMaxUvSet));
            info.texCoord = t.Get("texCoord").GetNumberAsInt();
        }
        if (t.Has("extensions")) {
            const tinygltf::Value& extensions = t.Get("extensions");
            if (!extensions.IsObject()) fail(at + ".extensions", "expected an object");
            for (const std::string& name : extensions.Keys()) info.extensions[name] = extensions.Get(name);
        }
        return info;
    }

    // glTF 2.0, 3.9.4: alpha is baseColorTexture's alpha (1 without an alpha channel) times
    // baseColorFactor's, times COLOR_0's where a primitive has one (SceneGeometry::vertexAlphaAt).
    // MASK: the surface is where alpha >= alphaCutoff (default 0.5), cut out elsewhere; BLEND:
    // alpha is the fraction of light it stops, as Cycles renders it (a stochastic cut-out,
    // materials/alpha.h); OPAQUE (the default) ignores alpha. Null: opaque. vertexAlpha: some
    // vertex of the material's primitives has an alpha below 1.
    template <class BaseColorTexture>
    std::shared_ptr<const Alpha> alpha(const tinygltf::Material& m, float factor, const std::string& where,
                                       const BaseColorTexture& baseColorTexture, bool vertexAlpha) {
        if (m.alphaMode == "OPAQUE" || m.alphaMode.empty()) return nullptr;
        if (m.alphaMode != "MASK" && m.alphaMode != "BLEND")
            fail(where + ".alphaMode", "expected OPAQUE, MASK or BLEND, got \"" + printableName(m.alphaMode) + "\"");
        std::optional<float> cutoff;
        if (m.alphaMode == "MASK") cutoff = float(number(m.alphaCutoff, 0.0, kMaxMagnitude, where + ".alphaCutoff"));
        std::shared_ptr<const Alpha> alpha;
        const auto& texture = baseColorTexture();
        if (texture && texture->first->alphaChannel() >= 0)
            alpha = std::make_shared<const Alpha>(texture->first, factor, cutoff, texture->second);
        else
            alpha = std::make_shared<const Alpha>(factor, cutoff);
        return alpha->opaque() && !vertexAlpha ? nullptr : alpha;
    }

    // ---- textures

    using OpenedTexture = std::pair<std::shared_ptr<const Texture>, TextureSampling>;

    // A material's textureInfo opened with its sampler's wrap modes and its KHR_texture_transform;
    // nothing (and a warning: the material keeps its factor) when there is none or it cannot be
    // read. Its texCoord becomes the material's uv set (uvSet_): a triangle carries one set, its
    // material's.
    template <class TextureInfo>
    std::optional<OpenedTexture> open(const TextureInfo& info, TextureColorSpace colorSpace, const std::string& where) {
        const int index = info.index;
        if (index < 0) return std::nullopt;
        int texCoord = info.texCoord;
        const UvTransform transform = uvTransform(info.extensions, texCoord, where + ".extensions.KHR_texture_transform");
        if (std::size_t(index) >= model_.textures.size())
            fail(where + ".index", "expected a texture index below " + std::to_string(model_.textures.size()) + ", got " +
                                       std::to_string(index));
        if (texCoord < 0 || texCoord > kMaxUvSet)
            fail(where + ".texCoord", "expected a set from 0 to " + std::to_string(kMaxUvSet) + ", got " +
                                          std::to_string(texCoord));
        const tinygltf::Texture& t = model_.textures[std::size_t(index)];
        const std::string at = "textures[" + std::to_string(index) + "]";
        if (t.source < 0 || std::size_t(t.source) >= model_.images.size()) {
            warn(at + ": no image (source " + std::to_string(t.source) + "); the material's factor alone is used");
            return std::nullopt;
        }
        TextureSampling sampling;
        sampling.transform = transform;
        if (t.sampler >= 0) {
            if (std::size_t(t.sampler) >= model_.samplers.size())
                fail(at + ".sampler", "expected a sampler index below " + std::to_string(model_.samplers.size()) + ", got " +
                                          std::to_string(t.sampler));
            const tinygltf::Sampler& sampler = model_.samplers[std::size_t(t.sampler)];
            sampling.wrapS = wrap(sampler.wrapS);
            sampling.wrapT = wrap(sampler.wrapT);
        }
        std::shared_ptr<const Texture> texture = image(t.source, colorSpace);
        if (!texture) return std::nullopt;
        usesTextures_ = true;
        if (uvSet_ == kNoUvSet) {
            uvSet_ = texCoord;
        } else if (texCoord != uvSet_) {
            warn(where + ": texCoord " + std::to_string(texCoord) + " is read as TEXCOORD_" + std::to_string(uvSet_) +
                 ", the set of the material's other textures (a material's textures share one set)");
        }
        return OpenedTexture{std::move(texture), sampling};
    }

    // KHR_texture_transform: uv' = T(offset) R(rotation) S(scale) uv in glTF's texture coordinates,
    // whose v runs down the image, R = [cos sin; -sin cos]; its texCoord, when given, replaces
    // the textureInfo's. As lightpath's v = 1 - glTF's (D = diag(1, -1), e = (0, 1)), the map is
    // D L D uv + D (L e + offset) + e, L = R S.
    UvTransform uvTransform(const tinygltf::ExtensionMap& extensions, int& texCoord, const std::string& where) const {
        const auto found = extensions.find("KHR_texture_transform");
        if (found == extensions.end()) return {};
        const tinygltf::Value& t = found->second;
        if (!t.IsObject()) fail(where, "expected an object");
        const auto pair = [&](const char* key, Vec2 fallback) {
            if (!t.Has(key)) return fallback;
            const tinygltf::Value& v = t.Get(key);
            if (!v.IsArray() || v.ArrayLen() != 2 || !v.Get(0).IsNumber() || !v.Get(1).IsNumber() ||
                !finite(v.Get(0).GetNumberAsDouble()) || !finite(v.Get(1).GetNumberAsDouble()))
                fail(where + "." + key, "expected two numbers" + std::string(kMagnitudeRange));
            return Vec2(float(v.Get(0).GetNumberAsDouble()), float(v.Get(1).GetNumberAsDouble()));
        };
        const Vec2 offset = pair("offset", Vec2(0.0f)), scale = pair("scale", Vec2(1.0f));
        double rotation = 0.0;
        if (t.Has("rotation")) {
            const tinygltf::Value& r = t.Get("rotation");
            if (!r.IsNumber() || !finite(r.GetNumberAsDouble())) fail(where + ".rotation", "expected a number of radians");
            rotation = r.GetNumberAsDouble();
        }
        if (t.Has("texCoord")) {
            const tinygltf::Value& c = t.Get("texCoord");
            if (!c.IsInt()) fail(where + ".texCoord", "expected a set from 0 to " + std::to_string(kMaxUvSet));
            texCoord = c.GetNumberAsInt();
        }
        const float c = float(std::cos(rotation)), s = float(std::sin(rotation));
        const float l00 = c * scale.x, l01 = s * scale.y, l10 = -s * scale.x, l11 = c * scale.y;  // L, by rows
        UvTransform out;
        out.linear = glm::mat2(Vec2(l00, -l10), Vec2(-l01, l11));  // D L D, by columns
        out.offset = Vec2(l01 + offset.x, 1.0f - l11 - offset.y);
        return out;
    }

    static TextureWrap wrap(int mode) {
        if (mode == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE) return TextureWrap::clamp;
        if (mode == TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT) return TextureWrap::mirror;
        return TextureWrap::repeat;  // REPEAT, glTF's default
    }

    // Image `index` opened once per colour space: its URI's bytes, or its bufferView's.
    std::shared_ptr<const Texture> image(int index, TextureColorSpace colorSpace) {
        const auto key = std::make_pair(index, colorSpace);
        if (const auto found = images_.find(key); found != images_.end()) return found->second;
        const tinygltf::Image& img = model_.images[std::size_t(index)];
        const std::string at = "images[" + std::to_string(index) + "]";
        std::vector<unsigned char> bufferViewBytes;
        const std::vector<unsigned char>* bytes = nullptr;
        if (img.bufferView >= 0) {
            if (std::size_t(img.bufferView) >= model_.bufferViews.size())
                fail(at + ".bufferView", "expected a bufferView index below " + std::to_string(model_.bufferViews.size()));
            const std::size_t length = model_.bufferViews[std::size_t(img.bufferView)].byteLength;
            const unsigned char* start = viewBytes(img.bufferView, 0, length, at);
            bufferViewBytes.assign(start, start + length);
            bytes = &bufferViewBytes;
        } else if (std::size_t(index) < imageBytes_.size() && !imageBytes_[std::size_t(index)].empty()) {
            bytes = &imageBytes_[std::size_t(index)];
        }
        std::shared_ptr<const Texture> texture;
        if (bytes == nullptr) {
            warn(at + ": cannot read \"" + printableName(img.uri) + "\"; the material's factor alone is used");
        } else {
            // Named in the cache by the glTF file and the image, so messages say where it came from.
            const std::string name = file_.string() + ":" + at;
            std::string error;
            texture = openTexture({name, bytes, colorSpace}, error);
            if (!texture) warn(at + ": cannot decode the image (" + error + "); the material's factor alone is used");
        }
        images_.emplace(key, texture);
        return texture;
    }

    std::uint32_t defaultMaterial() {
        if (defaultMaterial_ == kNoMeshMaterial) {
            const bool vertexColors = coloredMaterial_.back();
            MaterialSlot material = MicrofacetMaterial(colored(Rgb(1.0f), vertexColors), 1.0f, 1.0f);
            material->vertexColored = vertexColors;
            material->name = label(kDefaultMaterialLabel, kDefaultMaterialLabel, materialLabels_, "the default material");
            defaultMaterial_ = std::uint32_t(out_.materials.size());
            out_.materials.push_back(std::move(material));
            out_.absorption.emplace_back();
        }
        return defaultMaterial_;
    }

    std::vector<int> rootNodes() const {
        if (!model_.scenes.empty()) {
            const int chosen = model_.defaultScene >= 0 ? model_.defaultScene : 0;
            if (std::size_t(chosen) >= model_.scenes.size())
                fail("scene", "expected a scene index below " + std::to_string(model_.scenes.size()) + ", got " +
                                  std::to_string(chosen));
            return model_.scenes[std::size_t(chosen)].nodes;
        }
        // No scene: every node that is no other's child (glTF 2.0, 3.5.1 leaves this to the reader).
        std::vector<bool> child(model_.nodes.size(), false);
        for (const tinygltf::Node& node : model_.nodes)
            for (int c : node.children)
                if (c >= 0 && std::size_t(c) < child.size()) child[std::size_t(c)] = true;
        std::vector<int> roots;
        for (std::size_t i = 0; i < child.size(); ++i)
            if (!child[i]) roots.push_back(int(i));
        return roots;
    }

    // The node's local transform: its matrix, else T R S (glTF 2.0, 3.5.3).
    glm::dmat4 localTransform(const tinygltf::Node& node, const std::string& where) const {
        const double limit = kMaxMagnitude;
        if (!node.matrix.empty()) {
            const std::vector<double> m = factor(node.matrix, 16, -limit, limit, {}, where + ".matrix");
            return glm::make_mat4(m.data());  // column-major, as glTF stores it
        }
        const std::vector<double> t = factor(node.translation, 3, -limit, limit, {0, 0, 0}, where + ".translation");
        const std::vector<double> r = factor(node.rotation, 4, -1.0, 1.0, {0, 0, 0, 1}, where + ".rotation");
        const std::vector<double> s = factor(node.scale, 3, -limit, limit, {1, 1, 1}, where + ".scale");
        const glm::dquat q(r[3], r[0], r[1], r[2]);  // glTF stores x, y, z, w
        if (!(glm::length(q) > 0.0)) fail(where + ".rotation", "expected a unit quaternion, got zero");
        return glm::translate(glm::dmat4(1.0), glm::dvec3(t[0], t[1], t[2])) * glm::mat4_cast(glm::normalize(q)) *
               glm::scale(glm::dmat4(1.0), glm::dvec3(s[0], s[1], s[2]));
    }

    void visit(int index, const glm::dmat4& parent, const std::string& referrer) {
        if (index < 0 || std::size_t(index) >= model_.nodes.size())
            fail(referrer, "expected a node index below " + std::to_string(model_.nodes.size()) + ", got " +
                               std::to_string(index));
        const std::string where = "nodes[" + std::to_string(index) + "]";
        if (visited_[std::size_t(index)])
            fail(referrer, "node " + std::to_string(index) + " is reached twice: glTF nodes form trees (a node has one parent)");
        visited_[std::size_t(index)] = true;
        const tinygltf::Node& node = model_.nodes[std::size_t(index)];
        const glm::dmat4 world = parent * localTransform(node, where);
        if (node.mesh >= 0) addMesh(node, world, where);
        if (node.camera >= 0) addCamera(node, world, where);
        const double light = extensionNumber(node.extensions, "KHR_lights_punctual", "light", -1.0);
        if (light != -1.0) addLight(light, world, where);
        for (int child : node.children) visit(child, world, where + ".children");
    }

    // ---- accessors

    struct View {
        const unsigned char* data = nullptr;
        std::size_t count = 0, stride = 0;
        int componentType = 0;
        // A sparse accessor's elements, made dense: `data` points into them.
        std::shared_ptr<const std::vector<unsigned char>> dense;
    };

    // `length` bytes from `byteOffset` into bufferView `index`, bounds-checked against the view
    // and its buffer.
    const unsigned char* viewBytes(int index, std::size_t byteOffset, std::size_t length, const std::string& at) const {
        if (index < 0 || std::size_t(index) >= model_.bufferViews.size())
            fail(at, "expected a bufferView index below " + std::to_string(model_.bufferViews.size()));
        const tinygltf::BufferView& bv = model_.bufferViews[std::size_t(index)];
        if (bv.buffer < 0 || std::size_t(bv.buffer) >= model_.buffers.size()) fail(at, "its bufferView names no buffer");
        const std::vector<unsigned char>& buffer = model_.buffers[std::size_t(bv.buffer)].data;
        if (bv.byteOffset > buffer.size() || bv.byteLength > buffer.size() - bv.byteOffset)
            fail(at, "its bufferView reaches beyond its buffer of " + std::to_string(buffer.size()) + " bytes");
        if (byteOffset > bv.byteLength || length > bv.byteLength - byteOffset)
            fail(at, std::to_string(length) + " bytes from byte " + std::to_string(byteOffset) +
                         " reach beyond its bufferView of " + std::to_string(bv.byteLength) + " bytes");
        return buffer.data() + bv.byteOffset + byteOffset;
    }

    // The accessor's elements, bounds-checked against its buffer: `components` numbers each.
    View view(int index, int type, const std::string& where) const {
        if (index < 0 || std::size_t(index) >= model_.accessors.size())
            fail(where, "expected an accessor index below " + std::to_string(model_.accessors.size()) + ", got " +
                            std::to_string(index));
        const std::string at = where + ": accessor " + std::to_string(index);
        const tinygltf::Accessor& a = model_.accessors[std::size_t(index)];
        if (a.type != type)
            fail(at, std::string("expected type ") +
                         (type == TINYGLTF_TYPE_VEC4   ? "VEC4"
                          : type == TINYGLTF_TYPE_VEC3 ? "VEC3"
                          : type == TINYGLTF_TYPE_VEC2 ? "VEC2"
                                                       : "SCALAR"));
        const int componentSize = tinygltf::GetComponentSizeInBytes(std::uint32_t(a.componentType));
        const int components = tinygltf::GetNumComponentsInType(std::uint32_t(a.type));
        if (componentSize <= 0 || components <= 0) fail(at, "expected a known componentType");
        const std::size_t element = std::size_t(componentSize) * std::size_t(components);
        View v{nullptr, a.count, element, a.componentType, nullptr};
        // A sparse accessor without a bufferView starts from zeros (glTF 2.0, 3.6.2.3).
        if (a.bufferView >= 0 || !a.sparse.isSparse) {
            if (a.bufferView < 0 || std::size_t(a.bufferView) >= model_.bufferViews.size())
                fail(at, "expected a bufferView index below " + std::to_string(model_.bufferViews.size()));
            const tinygltf::BufferView& bv = model_.bufferViews[std::size_t(a.bufferView)];
            v.stride = bv.byteStride == 0 ? element : bv.byteStride;
            if (v.stride < element) fail(at, "expected a byteStride of at least " + std::to_string(element));
            if (a.count > 0 && (a.count - 1) > (std::numeric_limits<std::size_t>::max() - element) / v.stride)
                fail(at, std::to_string(a.count) + " elements are more than any buffer holds");
            const std::size_t span = a.count == 0 ? 0 : (a.count - 1) * v.stride + element;
            v.data = viewBytes(a.bufferView, a.byteOffset, span, at);
        }
        if (a.sparse.isSparse) v = densified(a, v, element, at);
        return v;
    }

    // glTF 2.0, 3.6.2.3: a sparse accessor is its dense elements (zeros without a bufferView) with
    // `sparse.count` of them replaced, at strictly increasing indices, by tightly packed values.
    View densified(const tinygltf::Accessor& a, const View& base, std::size_t element, const std::string& at) const {
        if (a.sparse.count < 0 || std::size_t(a.sparse.count) > a.count)
            fail(at + ": sparse.count", "expected at most the accessor's " + std::to_string(a.count) + " elements, got " +
                                           std::to_string(a.sparse.count));
        if (a.count > (std::size_t(1) << 31) / element)
            fail(at, std::to_string(a.count) + " sparse elements are more than lightpath makes dense");
        auto dense = std::make_shared<std::vector<unsigned char>>(a.count * element, static_cast<unsigned char>(0));
        if (base.data != nullptr)
            for (std::size_t i = 0; i < a.count; ++i)
                std::memcpy(dense->data() + i * element, base.data + i * base.stride, element);
        const std::size_t count = std::size_t(a.sparse.count);
        const int indexType = a.sparse.indices.componentType;
        const int indexSize = indexType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE    ? 1
                              : indexType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ? 2
                              : indexType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT   ? 4
                                                                                    : 0;
        if (indexSize == 0) fail(at + ": sparse.indices", "expected UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT");
        const auto offset = [](int byteOffset) { return std::size_t(std::max(0, byteOffset)); };
        const unsigned char* indices = viewBytes(a.sparse.indices.bufferView, offset(a.sparse.indices.byteOffset),
                                                 count * std::size_t(indexSize), at + ": sparse.indices");
        const unsigned char* values = viewBytes(a.sparse.values.bufferView, offset(a.sparse.values.byteOffset),
                                                count * element, at + ": sparse.values");
        std::size_t previous = 0;
        for (std::size_t i = 0; i < count; ++i) {
            std::uint32_t target = 0;
            std::memcpy(&target, indices + i * std::size_t(indexSize), std::size_t(indexSize));  // little-endian
            if (target >= a.count || (i > 0 && target <= previous))
                fail(at + ": sparse.indices", "index " + std::to_string(i) + " is " + std::to_string(target) +
                                                 "; expected indices increasing strictly, below " + std::to_string(a.count));
            previous = target;
            std::memcpy(dense->data() + std::size_t(target) * element, values + i * element, element);
        }
        return {dense->data(), a.count, element, a.componentType, std::move(dense)};
    }

    // The FLOAT elements of a VECn accessor, each element's n floats checked finite (else the error
    // `notFinite(i, floats)` says) and turned into lightpath's value by `convert`.
    template <std::size_t N, class Convert, class NotFinite>
    auto floatElements(int index, int type, const std::string& where, std::string_view notFloat, Convert convert,
                       NotFinite notFinite) const {
        const View v = view(index, type, where);
        if (v.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT) fail(where, std::string(notFloat));
        std::vector<decltype(convert(std::array<float, N>{}))> out(v.count);
        for (std::size_t i = 0; i < v.count; ++i) {
            std::array<float, N> element;
            std::memcpy(element.data(), v.data + i * v.stride, sizeof element);
            if (!std::all_of(element.begin(), element.end(), [](float x) { return finite(x); }))
                fail(where, "element " + std::to_string(i) + notFinite(element) + std::string(kMagnitudeRange));
            out[i] = convert(element);
        }
        return out;
    }

    // The elements of a VECn accessor, FLOAT, or of the integer types `integers` allows (a mask of
    // kByte, kUnsignedByte, kShort, kUnsignedShort, each only normalized where `normalizedOnly`), as
    // KHR_mesh_quantization stores positions, normals, tangents and uvs; else a located error
    // saying `expected`. Each element is turned into lightpath's value by `convert`.
    template <std::size_t N, class Convert, class NotFinite>
    auto quantizedElements(int index, int type, const std::string& where, unsigned integers, bool normalizedOnly,
                           std::string_view expected, Convert convert, NotFinite notFinite) const {
        const tinygltf::Accessor* a = index >= 0 && std::size_t(index) < model_.accessors.size()
                                          ? &model_.accessors[std::size_t(index)]
                                          : nullptr;
        const unsigned kind = a == nullptr ? 0u : integerKind(a->componentType);
        if (kind == 0u || (kind & integers) == 0u || (normalizedOnly && !a->normalized))
            return floatElements<N>(index, type, where, expected, convert, notFinite);
        const View v = view(index, type, where);
        std::vector<decltype(convert(std::array<float, N>{}))> out(v.count);
        for (std::size_t i = 0; i < v.count; ++i) {
            std::array<float, N> element;
            for (std::size_t c = 0; c < N; ++c)
                element[c] = component(v.data + i * v.stride, v.componentType, a->normalized, int(c));
            out[i] = convert(element);
        }
        return out;
    }

    // The integer component types, as masks for quantizedElements.
    static constexpr unsigned kByte = 1, kUnsignedByte = 2, kShort = 4, kUnsignedShort = 8;
    static unsigned integerKind(int componentType) {
        switch (componentType) {
            case TINYGLTF_COMPONENT_TYPE_BYTE: return kByte;
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return kUnsignedByte;
            case TINYGLTF_COMPONENT_TYPE_SHORT: return kShort;
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return kUnsignedShort;
            default: return 0u;
        }
    }

    // Component `c` of an integer element at `p` (little-endian, as glTF's buffers are): its value,
    // or normalized as glTF 2.0, 3.11 maps it, x / 255 and x / 65535 unsigned, max(x / 127, -1) and
    // max(x / 32767, -1) signed.
    static float component(const unsigned char* p, int componentType, bool normalized, int c) {
        switch (componentType) {
            case TINYGLTF_COMPONENT_TYPE_BYTE: {
                const auto x = static_cast<std::int8_t>(p[c]);
                return normalized ? std::max(float(x) / 127.0f, -1.0f) : float(x);
            }
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? float(p[c]) * (1.0f / 255.0f) : float(p[c]);
            case TINYGLTF_COMPONENT_TYPE_SHORT: {
                std::int16_t x;
                std::memcpy(&x, p + 2 * c, sizeof x);
                return normalized ? std::max(float(x) / 32767.0f, -1.0f) : float(x);
            }
            default: {
                std::uint16_t x;
                std::memcpy(&x, p + 2 * c, sizeof x);
                return normalized ? float(x) * (1.0f / 65535.0f) : float(x);
            }
        }
    }

    // A VEC3 accessor's elements, FLOAT or of the integer types `integers` allows (quantizedElements).
    std::vector<Vec3> vectors(int index, const std::string& where, unsigned integers, bool normalizedOnly,
                              std::string_view expected) const {
        return quantizedElements<3>(
            index, TINYGLTF_TYPE_VEC3, where, integers, normalizedOnly, expected,
            [](const std::array<float, 3>& e) { return Vec3(e[0], e[1], e[2]); },
            [](const std::array<float, 3>& e) { return " is " + formatVec3(Vec3(e[0], e[1], e[2])) + "; expected numbers "; });
    }

    // POSITION: FLOAT, or (KHR_mesh_quantization) BYTE, UNSIGNED_BYTE, SHORT or UNSIGNED_SHORT,
    // normalized or not, which the node's transform scales back.
    std::vector<Vec3> positions(int index, const std::string& where) const {
        if (!quantized_) return vectors(index, where, 0u, false, "expected FLOAT components");
        return vectors(index, where, kByte | kUnsignedByte | kShort | kUnsignedShort, false,
                       "expected FLOAT, BYTE, UNSIGNED_BYTE, SHORT or UNSIGNED_SHORT components");
    }

    // NORMAL: FLOAT, or (KHR_mesh_quantization) normalized BYTE or SHORT.
    std::vector<Vec3> normals(int index, const std::string& where) const {
        if (!quantized_) return vectors(index, where, 0u, false, "expected FLOAT components");
        return vectors(index, where, kByte | kShort, true, "expected FLOAT, or normalized BYTE or SHORT, components");
    }

    // TANGENT: xyz a unit tangent, w the bitangent's sign, +1 or -1 (glTF 2.0, 3.7.2.1); any other
    // finite w is read by its sign (0 as +1), as viewers do. FLOAT, or (KHR_mesh_quantization)
    // normalized BYTE or SHORT.
    std::vector<Vec4> tangents(int index, const std::string& where) const {
        return quantizedElements<4>(
            index, TINYGLTF_TYPE_VEC4, where, quantized_ ? kByte | kShort : 0u, true,
            quantized_ ? "expected FLOAT, or normalized BYTE or SHORT, components" : "expected FLOAT components",
            [](const std::array<float, 4>& e) { return Vec4(e[0], e[1], e[2], e[3] < 0.0f ? -1.0f : 1.0f); },
            [](const std::array<float, 4>&) { return std::string(" is not 4 numbers "); });
    }

    // A TEXCOORD_n as lightpath's uv: glTF's v runs down the image from its top (glTF 2.0, 3.7.2.1)
    // where lightpath's runs up (OBJ's vt; io/image_texture.cpp reads t = 1 - v), so v' = 1 - v.
    // glTF 2.0, 3.7.2.1 also allows normalized UNSIGNED_BYTE and UNSIGNED_SHORT (x / 255, x / 65535).
    // KHR_mesh_quantization adds BYTE and SHORT, and all four integer types not normalized (the
    // material's KHR_texture_transform scaling them back).
    std::vector<Vec2> textureCoordinates(int index, const std::string& where) const {
        return quantizedElements<2>(
            index, TINYGLTF_TYPE_VEC2, where,
            quantized_ ? kByte | kUnsignedByte | kShort | kUnsignedShort : kUnsignedByte | kUnsignedShort, !quantized_,
            quantized_ ? "expected FLOAT, BYTE, UNSIGNED_BYTE, SHORT or UNSIGNED_SHORT components"
                       : "expected FLOAT, or normalized UNSIGNED_BYTE or UNSIGNED_SHORT, components",
            [](const std::array<float, 2>& e) { return Vec2(e[0], 1.0f - e[1]); },
            [](const std::array<float, 2>&) { return std::string(" is not a pair of numbers "); });
    }

    // COLOR_0: linear RGB or RGBA (alpha 1 for RGB), of FLOAT or of normalized UNSIGNED_BYTE or
    // UNSIGNED_SHORT, each from 0 to 1 (glTF 2.0, 3.7.2.1).
    std::vector<Vec4> vertexColors(int index, const std::string& where) const {
        const bool rgba = index >= 0 && std::size_t(index) < model_.accessors.size() &&
                          model_.accessors[std::size_t(index)].type == TINYGLTF_TYPE_VEC4;
        const View v = view(index, rgba ? TINYGLTF_TYPE_VEC4 : TINYGLTF_TYPE_VEC3, where);
        const std::string at = where + ": accessor " + std::to_string(index);
        const bool normalized = model_.accessors[std::size_t(index)].normalized;
        std::vector<Vec4> out(v.count, Vec4(1.0f));
        for (std::size_t i = 0; i < v.count; ++i) {
            const unsigned char* p = v.data + i * v.stride;
            for (int c = 0; c < (rgba ? 4 : 3); ++c) {
                float x = 0.0f;
                if (v.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT) {
                    std::memcpy(&x, p + 4 * c, sizeof x);
                } else if (normalized && (v.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                                          v.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT)) {
                    x = component(p, v.componentType, true, c);
                } else {
                    fail(at, "expected FLOAT, or normalized UNSIGNED_BYTE or UNSIGNED_SHORT, components");
                }
                if (!(x >= 0.0f && x <= 1.0f))
                    fail(at, "element " + std::to_string(i) + " has a component " + formatNumber(x) +
                                 "; expected numbers from 0 to 1");
                out[i][c] = x;
            }
        }
        return out;
    }

    // A primitive's attribute `name` as `read` reads its accessor, one element per position (else a
    // located error counting `what`); empty when the primitive has none.
    template <class Read>
    auto perVertex(const tinygltf::Primitive& primitive, const std::string& name, std::size_t count,
                   const std::string& at, const char* what, Read read) const {
        const auto found = primitive.attributes.find(name);
        const std::string where = at + ".attributes." + name;
        decltype(read(0, where)) values;
        if (found == primitive.attributes.end()) return values;
        values = read(found->second, where);
        if (values.size() != count)
            fail(where, "expected " + std::to_string(count) + " " + what + ", one per position, got " +
                            std::to_string(values.size()));
        return values;
    }

    std::vector<std::uint32_t> indices(int index, std::size_t vertexCount, const std::string& where) const {
        const View v = view(index, TINYGLTF_TYPE_SCALAR, where);
        std::vector<std::uint32_t> out(v.count);
        for (std::size_t i = 0; i < v.count; ++i) {
            const unsigned char* p = v.data + i * v.stride;
            std::uint32_t value = 0;
            switch (v.componentType) {
                case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: value = *p; break;
                case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
                    std::uint16_t s;
                    std::memcpy(&s, p, sizeof s);
                    value = s;
                    break;
                }
                case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: std::memcpy(&value, p, sizeof value); break;
                default: fail(where, "expected indices of UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT");
            }
            if (value >= vertexCount)
                fail(where, "index " + std::to_string(i) + " is " + std::to_string(value) + ", but there are " +
                                std::to_string(vertexCount) + " vertices");
            out[i] = value;
        }
        return out;
    }

    // ---- nodes

    void addMesh(const tinygltf::Node& node, const glm::dmat4& world, const std::string& where) {
        if (std::size_t(node.mesh) >= model_.meshes.size())
            fail(where + ".mesh", "expected a mesh index below " + std::to_string(model_.meshes.size()) + ", got " +
                                      std::to_string(node.mesh));
        const tinygltf::Mesh& mesh = model_.meshes[std::size_t(node.mesh)];
        const std::size_t nodeIndex = std::size_t(&node - model_.nodes.data());
        const std::string name = !node.name.empty() ? node.name : mesh.name;
        const std::string objectLabel = label(name, "node-" + std::to_string(nodeIndex), objectLabels_, where);
        const glm::dmat3 normalMatrix = glm::transpose(glm::inverse(glm::dmat3(world)));
        std::vector<std::uint32_t> objectOfMaterial(model_.materials.size() + 1, kNoMeshMaterial);
        for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
            const tinygltf::Primitive& primitive = mesh.primitives[p];
            const std::string at = "meshes[" + std::to_string(node.mesh) + "].primitives[" + std::to_string(p) + "]";
            const int mode = primitive.mode < 0 ? TINYGLTF_MODE_TRIANGLES : primitive.mode;
            if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN) {
                warn(at + ": points and lines have no area and are left out");
                continue;
            }
            const auto position = primitive.attributes.find("POSITION");
            if (position == primitive.attributes.end()) fail(at + ".attributes", "expected a POSITION accessor");
            const std::vector<Vec3> positions = this->positions(position->second, at + ".attributes.POSITION");
            const std::size_t count = positions.size();
            const std::vector<Vec3> normals =
                perVertex(primitive, "NORMAL", count, at, "normals", [&](int i, const std::string& w) { return this->normals(i, w); });
            if (primitive.material >= 0 && std::size_t(primitive.material) >= model_.materials.size())
                fail(at + ".material", "expected a material index below " + std::to_string(model_.materials.size()) +
                                           ", got " + std::to_string(primitive.material));
            // The set its material's textures name; TEXCOORD_0, when there, for an untextured one
            // (a [[gltf]] `material` may put a textured material on it).
            const int uvSet = primitive.material >= 0 ? uvSetOfMaterial_[std::size_t(primitive.material)] : kNoUvSet;
            const std::string uvName = "TEXCOORD_" + std::to_string(uvSet == kNoUvSet ? 0 : uvSet);
            if (usesTextures_ && uvSet != kNoUvSet && primitive.attributes.count(uvName) == 0)
                fail(at + ".attributes", "expected a " + uvName + " accessor: material " +
                                             std::to_string(primitive.material) + "'s textures name texCoord " +
                                             std::to_string(uvSet));
            // Texture coordinates, and tangents for a normal map's frame: only textures read them.
            std::vector<Vec2> uvs;
            std::vector<Vec4> tangentsOf;
            if (usesTextures_) {
                uvs = perVertex(primitive, uvName, count, at, "texture coordinates",
                                [&](int i, const std::string& w) { return textureCoordinates(i, w); });
                tangentsOf = perVertex(primitive, "TANGENT", count, at, "tangents",
                                       [&](int i, const std::string& w) { return tangents(i, w); });
            }
            const std::vector<Vec4> colors = perVertex(primitive, "COLOR_0", count, at, "colours",
                                                      [&](int i, const std::string& w) { return vertexColors(i, w); });
            std::vector<std::uint32_t> order;
            if (primitive.indices >= 0) {
                order = indices(primitive.indices, positions.size(), at + ".indices");
            } else {
                order.resize(positions.size());
                for (std::size_t i = 0; i < order.size(); ++i) order[i] = std::uint32_t(i);
            }
            const std::uint32_t material = primitive.material >= 0 ? std::uint32_t(primitive.material) : defaultMaterial();
            const std::size_t slot = primitive.material >= 0 ? material : model_.materials.size();
            if (objectOfMaterial[slot] == kNoMeshMaterial) {
                objectOfMaterial[slot] = std::uint32_t(out_.objects.size());
                out_.objects.push_back({objectLabel, material});
            }
            const std::uint32_t object = objectOfMaterial[slot];
            const auto place = [&](std::uint32_t i) { return Vec3(world * glm::dvec4(glm::dvec3(positions[i]), 1.0)); };
            const auto orient = [&](std::uint32_t i) {
                const glm::dvec3 n = normalMatrix * glm::dvec3(normals[i]);
                const double length = glm::length(n);
                return length > 0.0 && std::isfinite(length) ? Vec3(n / length) : Vec3(0.0f);
            };
            // A tangent turns as the surface does; a mirroring transform flips the bitangent's sign,
            // since cross(normal, tangent) flips while the mirrored bitangent does not.
            const glm::dmat3 linear(world);
            const double handedness = glm::determinant(linear) < 0.0 ? -1.0 : 1.0;
            const auto turn = [&](std::uint32_t i) {
                const glm::dvec3 t = linear * glm::dvec3(Vec3(tangentsOf[i]));
                const double length = glm::length(t);
                if (!(length > 0.0) || !std::isfinite(length)) return Vec4(0.0f);
                return Vec4(Vec3(t / length), float(handedness * double(tangentsOf[i].w)));
            };
            const auto addTriangle = [&](std::uint32_t i, std::uint32_t j, std::uint32_t k) {
                const Triangle t{place(i), place(j), place(k), object};
                if (glm::cross(t.b - t.a, t.c - t.a) == Vec3(0.0f)) {
                    ++out_.degenerateDropped;
                    return;
                }
                // Normals for every triangle once any has them, zero (flat) for the others.
                if (!normals.empty() && out_.normals.size() < out_.triangles.size()) out_.normals.resize(out_.triangles.size());
                out_.triangles.push_back(t);
                if (usesTextures_)
                    out_.uvs.push_back(uvs.empty() ? TriangleUvs{} : TriangleUvs{uvs[i], uvs[j], uvs[k], true});
                // Tangents for every triangle once any has them, zero (the uvs' frame) for the others.
                if (!tangentsOf.empty() && out_.tangents.size() + 1 < out_.triangles.size())
                    out_.tangents.resize(out_.triangles.size() - 1);
                if (!tangentsOf.empty()) out_.tangents.push_back({turn(i), turn(j), turn(k)});
                else if (!out_.tangents.empty()) out_.tangents.push_back({});
                if (!normals.empty()) out_.normals.push_back({orient(i), orient(j), orient(k)});
                else if (!out_.normals.empty()) out_.normals.push_back({});
                // Colours for every triangle once any has them, white for the others.
                if (!colors.empty() && out_.colors.size() + 1 < out_.triangles.size())
                    out_.colors.resize(out_.triangles.size() - 1);
                if (!colors.empty())
                    out_.colors.push_back({Rgb(colors[i]), Rgb(colors[j]), Rgb(colors[k]),
                                           Vec3(colors[i].w, colors[j].w, colors[k].w)});
                else if (!out_.colors.empty()) out_.colors.push_back({});
            };
            if (mode == TINYGLTF_MODE_TRIANGLES) {
                for (std::size_t i = 0; i + 2 < order.size(); i += 3) addTriangle(order[i], order[i + 1], order[i + 2]);
            } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
                for (std::size_t i = 0; i + 2 < order.size(); ++i)
                    i % 2 == 0 ? addTriangle(order[i], order[i + 1], order[i + 2])
                               : addTriangle(order[i + 1], order[i], order[i + 2]);
            } else {
                for (std::size_t i = 1; i + 1 < order.size(); ++i) addTriangle(order[0], order[i], order[i + 1]);
            }
        }
    }

    void addCamera(const tinygltf::Node& node, const glm::dmat4& world, const std::string& where) {
        if (std::size_t(node.camera) >= model_.cameras.size())
            fail(where + ".camera", "expected a camera index below " + std::to_string(model_.cameras.size()) + ", got " +
                                        std::to_string(node.camera));
        const tinygltf::Camera& c = model_.cameras[std::size_t(node.camera)];
        const std::string at = "cameras[" + std::to_string(node.camera) + "]";
        if (c.type != "perspective" && c.type != "orthographic") {
            warn(at + ": only perspective and orthographic cameras are read; this " + printableName(c.type) +
                 " camera is left out");
            return;
        }
        GltfCamera camera;
        camera.label = label(c.name, "camera-" + std::to_string(node.camera), cameraLabels_, at);
        // The camera looks down its node's -z with +y up (glTF 2.0, 3.10.1).
        const Vec3 eye(world * glm::dvec4(0, 0, 0, 1));
        const glm::dvec3 forward(world * glm::dvec4(0, 0, -1, 0)), up(world * glm::dvec4(0, 1, 0, 0));
        if (!(glm::length(forward) > 0.0) || !(glm::length(glm::cross(forward, up)) > 0.0))
            fail(where, "its transform leaves the camera no viewing direction");
        camera.camera.eye = eye;
        camera.camera.lookAt = eye + Vec3(glm::normalize(forward));
        camera.camera.up = Vec3(glm::normalize(up));
        double aspectRatio = 0.0;
        if (c.type == "orthographic") {
            // glTF 2.0, 3.10.3: xmag and ymag are half the view's width and height (Blender writes
            // its Orthographic Scale over the image's longer side so).
            const double xmag = number(c.orthographic.xmag, 1e-9, kMaxMagnitude, at + ".orthographic.xmag");
            const double ymag = number(c.orthographic.ymag, 1e-9, kMaxMagnitude, at + ".orthographic.ymag");
            camera.camera.projection = Projection::Orthographic;
            camera.camera.orthographicHeight = float(2.0 * ymag);
            aspectRatio = xmag / ymag;
        } else {
            const double fov = number(c.perspective.yfov, 1e-6, kPi - 1e-6, at + ".perspective.yfov");
            camera.camera.verticalFovDegrees = float(glm::degrees(fov));
            aspectRatio = c.perspective.aspectRatio;
        }
        if (aspectRatio > 0.0 && std::isfinite(aspectRatio)) {
            const double width = std::clamp(std::round(camera.camera.height * aspectRatio), 1.0, 16384.0);
            camera.camera.width = int(width);
        }
        out_.cameras.push_back(camera);
    }

    void addLight(double index, const glm::dmat4& world, const std::string& where) {
        const std::string ref = where + ".extensions.KHR_lights_punctual.light";
        if (!(index >= 0.0 && index < double(model_.lights.size())) || index != std::floor(index))
            fail(ref, "expected a light index below " + std::to_string(model_.lights.size()));
        const tinygltf::Light& l = model_.lights[std::size_t(index)];
        const std::string at = "extensions.KHR_lights_punctual.lights[" + std::to_string(std::size_t(index)) + "]";
        GltfLight light;
        if (l.type == "point") light.kind = GltfLightKind::point;
        else if (l.type == "spot") light.kind = GltfLightKind::spot;
        else if (l.type == "directional") light.kind = GltfLightKind::directional;
        else fail(at + ".type", "expected \"point\", \"spot\" or \"directional\", got \"" + printableName(l.type) + "\"");
        const std::vector<double> colour = factor(l.color, 3, 0.0, 1.0, {1, 1, 1}, at + ".color");
        const double intensity = number(l.intensity, 0.0, kMaxMagnitude, at + ".intensity");
        light.intensity = float(intensity) * Rgb(float(colour[0]), float(colour[1]), float(colour[2]));
        light.position = Vec3(world * glm::dvec4(0, 0, 0, 1));
        const glm::dvec3 direction(world * glm::dvec4(0, 0, -1, 0));
        if (!(glm::length(direction) > 0.0)) fail(where, "its transform leaves the light no direction");
        light.direction = Vec3(glm::normalize(direction));
        if (light.kind == GltfLightKind::spot) {
            light.outerConeRadians = float(number(l.spot.outerConeAngle, 0.0, kPi / 2, at + ".spot.outerConeAngle"));
            light.innerConeRadians = float(number(l.spot.innerConeAngle, 0.0, l.spot.outerConeAngle, at + ".spot.innerConeAngle"));
        }
        if (l.range > 0.0) warn(at + ": range " + formatNumber(l.range) + " is ignored: the light falls off as 1/d^2 everywhere");
        light.label = label(l.name, "light-" + std::to_string(std::size_t(index)), lightLabels_, at);
        out_.lights.push_back(light);
    }

    const tinygltf::Model& model_;
    std::filesystem::path file_;
    GltfModel out_;
    std::vector<bool> visited_;
    std::vector<std::string> materialLabels_, objectLabels_, cameraLabels_;
    // The file uses KHR_mesh_quantization: integer positions, normals, tangents and uvs are read.
    bool quantized_ = false;
    std::vector<std::string> lightLabels_{"ambient"};  // the ambient term's label (scene/light_type.h)
    std::uint32_t defaultMaterial_ = kNoMeshMaterial;
    const ImageBytes& imageBytes_;
    std::map<std::pair<int, TextureColorSpace>, std::shared_ptr<const Texture>> images_;
    bool usesTextures_ = false;  // some material is textured: triangles carry their material's uv set
    // The TEXCOORD set each material's textures name (kNoUvSet: none), and the material's being read.
    static constexpr int kNoUvSet = -1;
    static constexpr int kMaxUvSet = 31;  // far above any exporter's; keeps the attribute's name short
    std::vector<int> uvSetOfMaterial_;
    std::vector<bool> coloredMaterial_;  // per material (and, last, none): some primitive has COLOR_0
    std::vector<bool> vertexAlphaMaterial_;  // per material: MASK or BLEND, and some COLOR_0 alpha is below 1
    int uvSet_ = kNoUvSet;
};

// Images are not decoded here: their bytes are kept for the texture opener (OpenImageIO), and an
// image that cannot be read is a warning when a material uses it. A bufferView image's pointer is
// not bounds-checked by tinygltf, so its bytes are not touched here (Reader::image checks them).
bool keepImageBytes(tinygltf::Image* image, const int index, std::string*, std::string*, int, int, const unsigned char* bytes,
                    int size, void* userData) {
    auto& images = *static_cast<ImageBytes*>(userData);
    if (index < 0 || image->bufferView >= 0 || bytes == nullptr || size <= 0) return true;
    if (images.size() <= std::size_t(index)) images.resize(std::size_t(index) + 1);
    images[std::size_t(index)].assign(bytes, bytes + size);
    return true;
}

std::string firstLine(std::string text) {
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
    return text;
}

GltfModel parse(const std::string& bytes, const std::filesystem::path& file) {
    tinygltf::TinyGLTF loader;
    ImageBytes images;
    loader.SetImageLoader(keepImageBytes, &images);
    tinygltf::Model model;
    std::string error, warning;
    const std::string base = file.parent_path().string();
    const bool binary = bytes.size() >= 4 && bytes.compare(0, 4, "glTF") == 0;
    const bool ok = binary
                        ? loader.LoadBinaryFromMemory(&model, &error, &warning,
                                                      reinterpret_cast<const unsigned char*>(bytes.data()),
                                                      unsigned(bytes.size()), base)
                        : loader.LoadASCIIFromString(&model, &error, &warning, bytes.data(), unsigned(bytes.size()), base);
    if (!ok) throw SceneError(file.string() + ": cannot read glTF file: " + firstLine(error.empty() ? warning : error));
    return Reader(model, file, images).read();
}

}  // namespace

GltfModel loadGltf(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in || std::filesystem::is_directory(file)) throw SceneError(file.string() + ": cannot open glTF file");
    std::ostringstream text;
    text << in.rdbuf();
    return parse(text.str(), file);
}

GltfModel loadGltfFromMemory(const std::string& bytes, const std::filesystem::path& file) { return parse(bytes, file); }

}  // namespace lightpath
