#pragma once
// The rays `bench rays` and the `ray_cost` driver cast: one source, so instruction counts and
// throughputs are measured on the same kinds of rays.
#include <cstddef>
#include <vector>

#include "accel/bvh.h"
#include "accel/scene_geometry.h"
#include "math/ray.h"
#include "scene/scene.h"

namespace lightpath {

// The memory test's height field (src/bench/height_field.h), 2 * side^2 triangles, seen from
// above at an angle and lit from one side.
Scene heightFieldScene(std::size_t side);

Bounds triangleBox(const std::vector<Triangle>& triangles);

// One ray through the centre of each pixel of a side x side image of the scene's camera.
std::vector<Ray> primaryRays(const Scene& scene, int side);

// Origins uniform in the box, directions uniform on the sphere.
std::vector<Ray> randomRays(const Bounds& box, int count);

// From every primary hit towards the light, the origin lifted `lift` off the surface.
std::vector<Ray> shadowRays(const SceneGeometry& geometry, const std::vector<Ray>& primary, const Vec3& light,
                            float lift);

}  // namespace lightpath
