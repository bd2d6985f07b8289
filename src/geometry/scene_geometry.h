#pragma once
#include <optional>
#include <vector>

#include "geometry/numerics.h"
#include "geometry/shapes.h"
#include "geometry/surface_hit.h"
#include "math/ray.h"

namespace lightpath {

// All primitives of a scene and the two queries a tracer asks of them: the closest hit along a
// ray, and whether anything blocks a segment (any hit, for shadow rays). Primitives have one
// scene-wide id: spheres first, then planes, then triangles.
// How closest-hit and any-hit queries find their candidates.
enum class Accelerator {
    BruteForce,  // the lecture's loop over every primitive
};

class SceneGeometry {
public:
    SceneGeometry(std::vector<Sphere> spheres, std::vector<Plane> planes, std::vector<Triangle> triangles,
                  NumericsOptions numerics = {}, Accelerator accelerator = Accelerator::BruteForce);

    std::optional<SurfaceHit> intersect(const Ray& ray) const;
    bool occluded(const Ray& ray) const;

    const NumericsOptions& numerics() const { return numerics_; }
    Accelerator accelerator() const { return accelerator_; }
    const std::vector<Sphere>& spheres() const { return spheres_; }
    const std::vector<Plane>& planes() const { return planes_; }
    const std::vector<Triangle>& triangles() const { return triangles_; }
    std::size_t primitiveCount() const { return spheres_.size() + planes_.size() + triangles_.size(); }

private:
    // t of the nearest hit of primitive `id` in (ray.tMin, ray.tMax), or kNoHit.
    float intersectPrimitive(const Ray& ray, std::uint32_t id) const;
    SurfaceHit describeHit(const Ray& ray, float t, std::uint32_t id) const;

    std::vector<Sphere> spheres_;
    std::vector<Plane> planes_;
    std::vector<Triangle> triangles_;
    NumericsOptions numerics_;
    Accelerator accelerator_;
};

}  // namespace lightpath
