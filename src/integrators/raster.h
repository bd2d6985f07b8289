#pragma once
// Rasterisation, the lecture's other visibility algorithm: "ray casting is just rasterisation with
// a different order of the for loops". Ray casting loops over pixels, then over primitives for
// the closest hit; the z-buffer (Catmull 1974) loops over primitives, then over the pixels each
// one covers, keeping per pixel the nearest fragment. Both sample the centres of the same camera's
// pixels, and the surface each finds is shaded by the same function (shadeFirstHit, raycast.h),
// so the images differ only where visibility does: at silhouettes.
//
// - Triangles: 2D homogeneous rasterisation (Olano and Greer 1997). The edge function of an edge
//   is the plane through the eye and that edge, evaluated at the pixel's film direction D; a
//   pixel is covered where all three agree in sign with the triangle's orientation seen from the
//   eye. Normalised, they are the perspective-correct barycentrics, and the depth along D is
//   det / (sum of the three), so no vertex is ever divided by its depth and triangles reaching
//   behind the eye need no clipping.
// - Every other primitive is a record of the shape table (geometry/shape.h), asked, never named:
//   a bounded kind covers the pixels of its bounding box's 12 triangles, an unbounded kind every
//   pixel, and each covered pixel centre takes the shape's depth there (a ray-cast impostor, Sigg
//   et al. 2006): `intersect` along the pixel's ray, ray casting's hit exactly, or the kind's
//   closed form `depthAlong`. An infinite plane's is n.(p - eye) / n.D: its image is the part of
//   the film on one side of its horizon n.D = 0 (one edge function), 1/depth linear on the film as
//   for a triangle. A sphere's image loses no silhouette pixel to facets.
//
// The rasteriser casts no rays, so it has no shadows; it samples each pixel once, at its centre.
#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "accel/scene_geometry.h"
#include "geometry/surface_hit.h"
#include "integrators/integrator.h"
#include "scene/camera.h"

namespace lightpath {

// The nearest fragment a pixel has received so far.
struct RasterFragment {
    float t = std::numeric_limits<float>::infinity();  // distance along the pixel's unit ray
    std::uint32_t primitive = kNoPrimitive;            // scene-wide id (SceneGeometry's codec)
    Vec3 barycentrics{0.0f};                           // weights of a triangle's a, b, c
};

class ZBuffer {
public:
    // Rasterises every primitive of `geometry` as `camera` sees it, in primitive id order: equal
    // depths keep the smaller id, as the ray caster's closest hit does.
    ZBuffer(const SceneGeometry& geometry, const Camera& camera);
    // One fragment per pixel: the constructor allocates fragmentCount, and `bytes` is what a
    // render is checked against before the z-buffer exists.
    static std::size_t fragmentCount(int width, int height) {
        return static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    }
    static std::size_t bytes(int width, int height) { return fragmentCount(width, height) * sizeof(RasterFragment); }

    int width() const { return width_; }
    int height() const { return height_; }
    const RasterFragment& at(int x, int y) const { return fragments_[index(x, y)]; }
    // The surface pixel (x, y) sees, described as the ray caster describes its hits, or nullopt
    // (the background).
    std::optional<SurfaceHit> surfaceAt(int x, int y) const;

    // How many pixel centres the rasterisation tested against a primitive's coverage: its cost,
    // which a primitive the camera cannot see must not add to.
    std::uint64_t pixelsTested() const { return pixelsTested_; }

private:
    std::size_t index(int x, int y) const { return static_cast<std::size_t>(y) * width_ + x; }
    Vec3 pixelDirection(int x, int y) const;  // unnormalised, through the pixel centre
    // Calls fragment(x, y, t, barycentrics) for every pixel centre the triangle abc covers.
    template <typename Fragment>
    void coverTriangle(const Vec3& a, const Vec3& b, const Vec3& c, Fragment fragment) const;
    // The same for an orthographic camera's parallel rays.
    template <typename Fragment>
    void coverTriangleOrthographic(const Vec3& a, const Vec3& b, const Vec3& c, Fragment fragment) const;
    // The pixels whose centres a triangle's projection may cover: its box on the film with one
    // pixel of slack, or the whole film when a corner is not in front of the camera.
    std::array<int, 4> pixelBox(const Vec3& a, const Vec3& b, const Vec3& c) const;
    void rasteriseUnbounded(std::uint32_t index);
    void rasteriseShape(std::uint32_t index);
    // Distance along the unit ray through pixel (x, y)'s centre to record `shape` (primitive `id`),
    // or kNoHit.
    float depthUnder(const ShapeRecord& shape, std::uint32_t id, int x, int y) const;
    void rasteriseTriangle(std::uint32_t index);
    // The depth test: keeps the fragment if it is nearer than what the pixel holds.
    void test(int x, int y, float t, std::uint32_t primitive, const Vec3& barycentrics);

    const SceneGeometry& geometry_;
    const Camera& camera_;
    int width_, height_;
    std::vector<RasterFragment> fragments_;
    mutable std::uint64_t pixelsTested_ = 0;
};

// The rasteriser as an integrator: its preprocess fills the z-buffer, and each camera ray (one
// per pixel, through its centre) is shaded from the fragment its pixel kept.
class RasterIntegrator final : public Integrator {
public:
    void preprocess(const RenderContext& context) override;
    void traceCameraRay(const Ray& ray, PathState& path) const override;
    bool samplesPixelCentres() const override { return true; }
    std::size_t preprocessBytes(int width, int height) const override { return ZBuffer::bytes(width, height); }

private:
    std::optional<ZBuffer> zBuffer_;
};

}  // namespace lightpath
