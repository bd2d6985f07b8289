#pragma once
// Embree 3 as a reference backend for triangle meshes: the production path for huge meshes, and
// the yardstick of the ray benchmark. Compiled only with the CMake option LIGHTPATH_EMBREE.
// Embree applies its own triangle test, so on shared edges and exact ties its answer may differ
// from ours in the last ulp or the primitive chosen.
#include <cstdint>
#include <memory>
#include <span>

#include "geometry/shapes.h"
#include "math/ray.h"

namespace lightpath {

class EmbreeScene {
public:
    explicit EmbreeScene(std::span<const Triangle> triangles);
    ~EmbreeScene();
    EmbreeScene(const EmbreeScene&) = delete;
    EmbreeScene& operator=(const EmbreeScene&) = delete;

    // The nearest triangle in (ray.tMin, tFar) other than `ignored` (an index into the triangles,
    // or kNoPrimitive): its index and t.
    bool intersect(const Ray& ray, float tFar, std::uint32_t ignored, float& t, std::uint32_t& index) const;
    bool occluded(const Ray& ray, std::uint32_t ignored) const;

    // Copying the triangles in and building Embree's BVH, without creating the device.
    double buildSeconds() const { return buildSeconds_; }

private:
    struct Handles;
    std::unique_ptr<Handles> handles_;
    double buildSeconds_ = 0.0;
};

}  // namespace lightpath
