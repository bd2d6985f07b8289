#pragma once
#include <optional>
#include <vector>

#include "geometry/shapes.h"
#include "geometry/surface_hit.h"
#include "math/ray.h"

namespace lightpath {

// All primitives of a scene and the two queries a tracer asks of them: the closest hit along a
// ray, and whether anything blocks a segment (any hit, for shadow rays).
class SceneGeometry {
public:
    SceneGeometry(std::vector<Sphere> spheres, std::vector<Plane> planes,
                  std::vector<Triangle> triangles);

    std::optional<SurfaceHit> intersect(const Ray& ray) const;
    bool occluded(const Ray& ray) const;

    const std::vector<Sphere>& spheres() const { return spheres_; }
    const std::vector<Plane>& planes() const { return planes_; }
    const std::vector<Triangle>& triangles() const { return triangles_; }

private:
    std::vector<Sphere> spheres_;
    std::vector<Plane> planes_;
    std::vector<Triangle> triangles_;
};

}  // namespace lightpath
