// `[[triangles]]`: one triangle, declared by its three corners, read and registered here like
// every shape kind (docs/extending.md). Triangles are not records of a ShapeOps table: they go to
// SceneGeometry's triangle array, with its own fast paths (packs, SIMD, Embree).
#include <array>

#include "scene/shape_type.h"

namespace lightpath {
namespace {

void addTriangleShape(const ParameterValues& values, SceneBuilder& scene) {
    const std::array<Vec3, 3> corners = values.points("vertices");
    Triangle triangle{corners[0], corners[1], corners[2], 0};
    // Legal but invisible: a triangle without area is never hit (its determinant is zero), so it
    // is kept and only worth a warning.
    const bool onOneLine = areParallel(triangle.b - triangle.a, triangle.c - triangle.a);
    if (onOneLine) scene.warn(values.located("vertices", "the 3 points lie on one line: the triangle has no area and is never seen"));
    triangle.object = scene.addShapeObject(values);
    if (!onOneLine) {
        if (auto warning = tooSmallToSampleWarning("triangle", surfaceArea(triangle), scene.emissionOf(triangle.object)))
            scene.warn(values.located("vertices", *warning));
    }
    scene.addTriangle(triangle);
}

}  // namespace
}  // namespace lightpath

// Rank 1000: triangles are numbered after the spheres, planes and every other kind, before the
// meshes (a new kind takes a rank below 1000).
LIGHTPATH_REGISTER_SHAPE(lightpath::ShapeType{
    {"shape", "triangle", "a triangle [a, b, c], seen from both sides, emitting on the side of (b − a) × (c − a)",
     {lightpath::kShapeNameParameter,
      {"vertices", lightpath::ParameterType::ThreePoints, "m", "", {},
       "its corners `[a, b, c]`; on one line it has no area and is never seen (a warning)", true},
      lightpath::kShapeMaterialParameter},
     ""},
    1000, "triangles", lightpath::addTriangleShape, lightpath::ShapeStorage::triangles})
