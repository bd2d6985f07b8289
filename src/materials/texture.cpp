#include "materials/texture.h"

#include <atomic>

#include "schema/parameter_values.h"

namespace lightpath {
namespace {

std::atomic<TextureOpener>& opener() {
    static std::atomic<TextureOpener> registered{nullptr};
    return registered;
}

}  // namespace

void registerTextureOpener(TextureOpener textureOpener) { opener().store(textureOpener); }

std::shared_ptr<const Texture> openTexture(const TextureSource& source, std::string& error) {
    const TextureOpener open = opener().load();
    if (open == nullptr) {
        error = "this program reads no textures (the image module's texture opener is not linked in)";
        return nullptr;
    }
    return open(source, error);
}

Rgb ColorParameter::varying(const SurfaceSide& side) const {
    Rgb value = value_;
    if (texture_) value *= texture_->lookup(transformedFootprint(side.texture, sampling_.transform), sampling_);
    return vertexColored_ ? value * side.vertexColor : value;
}

ColorParameter colorParameter(const ParameterValues& values, std::string_view name) {
    const TextureReference* reference = values.texture(name);
    if (reference == nullptr) return values.colour(name);
    std::string error;
    std::shared_ptr<const Texture> texture = openTexture({reference->file, nullptr, reference->colorSpace}, error);
    if (!texture) values.fail(name, "cannot read the texture \"" + reference->file + "\": " + error);
    return ColorParameter(std::move(texture), reference->tint, reference->uvScale, reference->filtered);
}

}  // namespace lightpath
