#pragma once
// Textures: any RGB parameter of any material may be an image (`kd = { texture = "wood.png" }`),
// read through OpenImageIO's TextureSystem (filtered, MIP-mapped, cached) in the image module.
// Materials hold ColorParameters and evaluate them at the shading point's texture coordinates and
// footprint, which the Bsdf passes in SurfaceSide; an untextured parameter is its constant.
#include <memory>
#include <string>
#include <string_view>

#include "materials/lobe.h"
#include "math/types.h"

namespace lightpath {

class ParameterValues;

// An image texture (OpenImageIO caches its file once for all who open it). Immutable; thread-safe.
class Texture {
public:
    virtual ~Texture() = default;
    // The filtered RGB over the footprint (uv and its change across a pixel, uv scaled already);
    // point sampled (the finest level's texels, bilinearly) when `filtered` is false.
    virtual Rgb lookup(const TextureFootprint& footprint, bool filtered) const = 0;
    // The mean RGB over the whole image (radiosity's constant reflectance of a textured kd).
    virtual Rgb average() const = 0;
};

// What opens a texture file: the image module's (io/image_texture.cpp registers it; src/ layers
// keep OpenImageIO above the materials). Returns nullptr and sets `error` when it cannot.
using TextureOpener = std::shared_ptr<const Texture> (*)(const std::string& file, std::string& error);
void registerTextureOpener(TextureOpener opener);
std::shared_ptr<const Texture> openTexture(const std::string& file, std::string& error);

// One RGB parameter: a constant, or a texture times a tint, with its uv scale.
class ColorParameter {
public:
    ColorParameter() = default;
    ColorParameter(const Rgb& constant) : value_(constant) {}  // NOLINT: a constant is a parameter
    ColorParameter& operator=(const Rgb& constant) { return *this = ColorParameter(constant); }
    ColorParameter(std::shared_ptr<const Texture> texture, const Rgb& tint, float uvScale, bool filtered)
        : value_(tint), texture_(std::move(texture)), uvScale_(uvScale), filtered_(filtered) {}

    // Its value at the surface point `side` describes. The untextured case is one branch.
    Rgb at(const SurfaceSide& side) const {
        if (!texture_) return value_;
        return value_ * texture_->lookup(scaled(side.texture), filtered_);
    }
    bool textured() const { return texture_ != nullptr; }
    // The constant, or a texture's tint.
    const Rgb& constant() const { return value_; }
    // Nothing anywhere: a zero constant or a zero tint (lobes test it to drop themselves).
    bool black() const { return isBlack(value_); }
    // The mean over the surface: the constant, or the tint times the image's mean.
    Rgb mean() const { return texture_ ? value_ * texture_->average() : value_; }
    // Its largest channel at this point (a lobe's albedo, for choosing lobes).
    float maxAt(const SurfaceSide& side) const { return maxComponent(at(side)); }

private:
    TextureFootprint scaled(TextureFootprint f) const {
        f.uv *= uvScale_;
        f.dUVdx *= uvScale_;
        f.dUVdy *= uvScale_;
        return f;
    }
    Rgb value_{0.0f};
    std::shared_ptr<const Texture> texture_;
    float uvScale_ = 1.0f;
    bool filtered_ = true;
};

// Parameter `name` of `values` (a Colour) as a ColorParameter: its constant, or the texture it
// names opened (a file that cannot be read is a located error at the key).
ColorParameter colorParameter(const ParameterValues& values, std::string_view name);

}  // namespace lightpath
