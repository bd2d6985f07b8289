#include "materials/alpha.h"

#include <string>
#include <utility>

namespace lightpath {

Alpha::Alpha(std::shared_ptr<const Texture> texture, float factor, std::optional<float> cutoff,
             const TextureSampling& sampling)
    : texture_(std::move(texture)), factor_(factor), cutoff_(cutoff), sampling_(sampling) {
    sampling_.filtered = false;
    channel_ = texture_ && texture_->alphaChannel() >= 0 ? texture_->alphaChannel() : 0;
}

float Alpha::at(Vec2 uv) const {
    if (!texture_) return factor_;
    TextureFootprint footprint;
    footprint.uv = uv;
    return factor_ * texture_->lookupChannel(transformedFootprint(footprint, sampling_.transform), sampling_, channel_);
}
std::shared_ptr<const Alpha> alphaParameter(const ParameterValues& values, std::string_view name) {
    const TextureReference* reference = values.texture(name);
    if (reference == nullptr) {
        const float constant = values.number(name);
        return constant >= 1.0f ? nullptr : std::make_shared<const Alpha>(constant, std::nullopt);
    }
    std::string error;
    std::shared_ptr<const Texture> texture = openTexture({reference->file, nullptr, reference->colorSpace}, error);
    if (!texture) values.fail(name, "cannot read the texture \"" + reference->file + "\": " + error);
    return std::make_shared<const Alpha>(std::move(texture), reference->tint.r, reference->cutoff,
                                         TextureSampling{UvTransform::scaled(reference->uvScale), reference->filtered});
}

}  // namespace lightpath
