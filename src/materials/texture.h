#pragma once
// Textures: any RGB parameter of any material may be an image (`kd = { texture = "wood.png" }`),
// read through OpenImageIO's TextureSystem (filtered, MIP-mapped, cached) in the image module.
// Materials hold ColorParameters and evaluate them at the shading point's texture coordinates and
// footprint, which the Bsdf passes in SurfaceSide; an untextured parameter is its constant.
#include <cmath>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <glm/mat2x2.hpp>

#include "materials/lobe.h"
#include "math/types.h"
#include "schema/parameter_values.h"

namespace lightpath {

// Texture coordinates outside [0, 1]: repeat, the edge texel, or repeat mirrored (glTF's samplers).
enum class TextureWrap { repeat, clamp, mirror };

// An image to open: a file, or an encoded image in memory (a glTF data URI or bufferView).
struct TextureSource {
    std::string file;                                   // the file, or the in-memory image's name
    const std::vector<unsigned char>* bytes = nullptr;  // read while opening only; null: read `file`
    TextureColorSpace colorSpace = TextureColorSpace::automatic;
};

// An affine map of texture coordinates, uv' = linear uv + offset: the TOML key's uv_scale, or
// glTF's KHR_texture_transform (offset, rotation, scale).
struct UvTransform {
    glm::mat2 linear{1.0f};
    Vec2 offset{0.0f};

    static UvTransform scaled(float scale) { return {glm::mat2(scale), Vec2(0.0f)}; }
};

// How a parameter reads its texture.
struct TextureSampling {
    UvTransform transform;  // applied to the texture coordinates and their derivatives
    bool filtered = true;   // false: point sampled (the finest level's texels, bilinearly)
    TextureWrap wrapS = TextureWrap::repeat, wrapT = TextureWrap::repeat;
};

// An image texture (OpenImageIO caches its file once for all who open it). Immutable; thread-safe.
class Texture {
public:
    virtual ~Texture() = default;
    // The RGB over the footprint (uv and its change across a pixel, transformed already), filtered
    // and wrapped as `sampling` says.
    virtual Rgb lookup(const TextureFootprint& footprint, const TextureSampling& sampling) const = 0;
    // One channel alone over the footprint (an alpha mask's), filtered as lookup() filters.
    virtual float lookupChannel(const TextureFootprint& footprint, const TextureSampling& sampling, int channel) const = 0;
    // The mean RGB over the whole image (radiosity's constant reflectance of a textured kd).
    virtual Rgb average() const = 0;
    // The index of its alpha channel, or -1 when it has none.
    virtual int alphaChannel() const = 0;
};

// What opens a texture: the image module's (io/image_texture.cpp registers it; src/ layers keep
// OpenImageIO above the materials). Returns nullptr and sets `error` when it cannot.
using TextureOpener = std::shared_ptr<const Texture> (*)(const TextureSource& source, std::string& error);
void registerTextureOpener(TextureOpener opener);
std::shared_ptr<const Texture> openTexture(const TextureSource& source, std::string& error);

// A footprint in a parameter's texture coordinates: its uv mapped, its derivatives turned alike.
inline TextureFootprint transformedFootprint(TextureFootprint f, const UvTransform& t) {
    f.uv = t.linear * f.uv + t.offset;
    f.dUVdx = t.linear * f.dUVdx;
    f.dUVdy = t.linear * f.dUVdy;
    return f;
}

// One RGB parameter: a constant, or a texture times a tint, with its sampling.
class ColorParameter {
public:
    ColorParameter() = default;
    ColorParameter(const Rgb& constant) : value_(constant) {}  // NOLINT: a constant is a parameter
    ColorParameter& operator=(const Rgb& constant) { return *this = ColorParameter(constant); }
    ColorParameter(std::shared_ptr<const Texture> texture, const Rgb& tint, float uvScale, bool filtered)
        : ColorParameter(std::move(texture), tint, TextureSampling{UvTransform::scaled(uvScale), filtered}) {}
    ColorParameter(std::shared_ptr<const Texture> texture, const Rgb& tint, const TextureSampling& sampling)
        : value_(tint), texture_(std::move(texture)), sampling_(sampling), varies_(texture_ != nullptr) {}

    // Its value at the surface point `side` describes. The constant case is one branch, inlined
    // where it is read; the rest out of line.
    Rgb at(const SurfaceSide& side) const { return varies_ ? varying(side) : value_; }
    // The same parameter times the surface's vertex colour (glTF's COLOR_0 on the base colour).
    ColorParameter timesVertexColor() const {
        ColorParameter multiplied = *this;
        multiplied.vertexColored_ = multiplied.varies_ = true;
        return multiplied;
    }
    bool textured() const { return texture_ != nullptr; }
    // Whether it differs from point to point: a texture, or a vertex colour that multiplies it.
    bool varies() const { return varies_; }
    // The constant, or a texture's tint.
    const Rgb& constant() const { return value_; }
    // Nothing anywhere: a zero constant or a zero tint (lobes test it to drop themselves).
    bool black() const { return isBlack(value_); }
    // The mean over the surface: the constant, or the tint times the image's mean (a vertex
    // colour, which the parameter does not hold, left out).
    Rgb mean() const { return texture_ ? value_ * texture_->average() : value_; }
    // Its largest channel at this point (a lobe's albedo, for choosing lobes).
    float maxAt(const SurfaceSide& side) const { return maxComponent(at(side)); }

private:
    Rgb value_{0.0f};
    std::shared_ptr<const Texture> texture_;
    TextureSampling sampling_;
    bool vertexColored_ = false;
    bool varies_ = false;  // a texture or a vertex colour
    Rgb varying(const SurfaceSide& side) const;
};

// One scalar parameter: a constant, or one channel of a texture times a factor (glTF's metallic
// and roughness: the B and G channels of metallicRoughnessTexture times their factors).
class ScalarParameter {
public:
    ScalarParameter() = default;
    ScalarParameter(float constant) : value_(constant) {}  // NOLINT: a constant is a parameter
    ScalarParameter(std::shared_ptr<const Texture> texture, int channel, float factor, const TextureSampling& sampling)
        : value_(factor), texture_(std::move(texture)), channel_(channel), sampling_(sampling) {}

    float at(const SurfaceSide& side) const {
        if (!texture_) return value_;
        return value_ * texture_->lookup(transformedFootprint(side.texture, sampling_.transform), sampling_)[channel_];
    }
    bool textured() const { return texture_ != nullptr; }
    // The constant, or a texture's factor.
    float constant() const { return value_; }
    // The mean over the surface: the constant, or the factor times the channel's image mean.
    float mean() const { return texture_ ? value_ * texture_->average()[channel_] : value_; }

private:
    float value_ = 0.0f;
    std::shared_ptr<const Texture> texture_;
    int channel_ = 0;
    TextureSampling sampling_;
};

// A tangent-space normal map (glTF's normalTexture: linear RGB n = 2 texel - 1, +X along u, +Y
// along v up, OpenGL style, +Z the surface normal; x and y times `scale`, glTF 2.0, 3.9.3).
struct NormalMap {
    std::shared_ptr<const Texture> texture;  // none: the mesh's shading normal alone
    float scale = 1.0f;
    TextureSampling sampling;

    // The unit normal `normal` turned by the map at `footprint`, in the tangent frame of the
    // surface's dp/du and dp/dv (Gram-Schmidt against the normal; the bitangent on dp/dv's side,
    // so a mirrored uv mapping flips it). `normal` itself where the frame is degenerate.
    Vec3 perturb(const Vec3& normal, const Vec3& dpdu, const Vec3& dpdv, const TextureFootprint& footprint) const {
        const Vec3 along = dpdu - normal * glm::dot(normal, dpdu);
        const float length = glm::length(along);
        if (!(length > 0.0f) || !std::isfinite(length)) return normal;
        const Vec3 tangent = along / length;
        Vec3 bitangent = glm::cross(normal, tangent);
        if (glm::dot(bitangent, dpdv) < 0.0f) bitangent = -bitangent;
        const Rgb texel = texture->lookup(transformedFootprint(footprint, sampling.transform), sampling);
        const Vec3 local{(2.0f * texel.r - 1.0f) * scale, (2.0f * texel.g - 1.0f) * scale, 2.0f * texel.b - 1.0f};
        const Vec3 turned = local.x * tangent + local.y * bitangent + local.z * normal;
        const float turnedLength = glm::length(turned);
        return turnedLength > 0.0f && std::isfinite(turnedLength) ? turned / turnedLength : normal;
    }
};

// Parameter `name` of `values` (a Colour) as a ColorParameter: its constant, or the texture it
// names opened (a file that cannot be read is a located error at the key).
ColorParameter colorParameter(const ParameterValues& values, std::string_view name);

}  // namespace lightpath
