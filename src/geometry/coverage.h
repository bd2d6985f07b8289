#pragma once
// Where a surface is there at all: alpha cut-outs (a leaf's outline, a fence, glTF's alphaMode,
// MTL's map_d). A ray meets such a surface only where it is covered and passes through elsewhere
// as if nothing were there: no hit, so no event in its light path. SceneGeometry asks at every hit
// on an object that has one; geometry knows no textures, so the material side implements it.
#include <bit>
#include <cstdint>

#include "math/random.h"
#include "math/ray.h"
#include "math/types.h"

namespace lightpath {

class SurfaceCoverage {
public:
    virtual ~SurfaceCoverage() = default;
    // Whether a ray meets the surface at texture coordinates `uv`, where the mesh's own alpha
    // (glTF's COLOR_0 alpha; 1 without) is `vertexAlpha`. `u` in [0, 1) is the ray's own uniform
    // number there (coverageSample): a fractional coverage of 0.3 stops the rays whose u is below
    // 0.3, a stochastic transparency that averages to the blend over a pixel's samples (Enderton
    // et al. 2010; pbrt-v4's alpha test).
    virtual bool covers(Vec2 uv, float vertexAlpha, float u) const = 0;
};

// The uniform number of `ray` where it meets primitive `primitive` from its front (`front`) or
// back: a hash of the ray's origin and direction and of the two, so a ray cast again decides again
// alike (a shadow ray, a rasterised fragment and a traced one agree, whatever their t's rounding),
// and the layers along one ray (two triangles, a sphere's front and back) decide independently.
inline float coverageSample(const Ray& ray, std::uint32_t primitive, bool front) {
    const auto bits = [](float x) { return static_cast<std::uint64_t>(std::bit_cast<std::uint32_t>(x)); };
    std::uint64_t h = mixBits(bits(ray.origin.x) | bits(ray.origin.y) << 32);
    h = mixBits(h ^ (bits(ray.origin.z) | bits(ray.direction.x) << 32));
    h = mixBits(h ^ (bits(ray.direction.y) | bits(ray.direction.z) << 32));
    h = mixBits(h ^ (std::uint64_t{primitive} << 1 | std::uint64_t{front}));
    return static_cast<float>(h >> 40) * 0x1p-24f;
}

}  // namespace lightpath
