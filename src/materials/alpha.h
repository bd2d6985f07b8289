#pragma once
// A surface's alpha (its coverage, geometry/coverage.h): 1 where it is, 0 where it is cut out,
// and in between the fraction of rays it stops. A constant, or one channel of a texture (its
// alpha, else a grey mask's one channel) times a factor. With a cutoff (glTF's alphaMode MASK) the
// surface is wherever alpha reaches the cutoff and nowhere else; without one (glTF's BLEND, MTL's
// dissolve map) alpha is a probability.
#include <memory>
#include <optional>
#include <string_view>

#include "geometry/coverage.h"
#include "materials/texture.h"

namespace lightpath {

class Alpha final : public SurfaceCoverage {
public:
    Alpha(float constant, std::optional<float> cutoff) : factor_(constant), cutoff_(cutoff) {}
    // `texture`'s alpha channel, or its first when it has none, times `factor`.
    Alpha(std::shared_ptr<const Texture> texture, float factor, std::optional<float> cutoff,
          const TextureSampling& sampling);

    // alpha at `uv`: the texture read at its finest level (bilinear), so the mask's outline stays
    // sharp however far away the surface is.
    float at(Vec2 uv) const;
    // glTF 2.0, 3.9.4: the vertex colour's alpha multiplies the material's before the cutoff.
    bool covers(Vec2 uv, float vertexAlpha, float u) const override {
        const float alpha = at(uv) * vertexAlpha;
        return cutoff_ ? alpha >= *cutoff_ : u < alpha;
    }
    // Covered everywhere, by itself: a constant that every ray meets (unless a vertex alpha below
    // 1 multiplies it).
    bool opaque() const { return !texture_ && (cutoff_ ? factor_ >= *cutoff_ : factor_ >= 1.0f); }

private:
    std::shared_ptr<const Texture> texture_;
    int channel_ = 0;
    float factor_ = 1.0f;
    std::optional<float> cutoff_;
    TextureSampling sampling_;
};

// Parameter `name` of `values` (a NumberOrTexture) as an Alpha: null when every ray meets the
// surface, else its constant or the texture it names opened (a file that cannot be read is a
// located error at the key), with the texture's `cutoff`.
std::shared_ptr<const Alpha> alphaParameter(const ParameterValues& values, std::string_view name);

}  // namespace lightpath
