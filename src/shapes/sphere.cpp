// `[[spheres]]`: a sphere, declared, read and registered here like every shape kind
// (docs/extending.md). Its geometry stays in SceneGeometry's own array of spheres (the
// accelerator's fast path and the robust/naive intersection variants, geometry/intersect.h).
#include "scene/shape_type.h"

namespace lightpath {
namespace {

void addSphere(const ParameterValues& values, SceneBuilder& scene) {
    Sphere sphere;
    sphere.center = values.vec3("center");
    sphere.radius = values.number("radius");
    sphere.object = scene.addShapeObject(values);
    if (auto warning = tooSmallToSampleWarning("sphere", surfaceArea(sphere), scene.emissionOf(sphere.object)))
        scene.warn(values.located("radius", *warning));
    scene.addSphere(sphere);
}

}  // namespace
}  // namespace lightpath

// Rank 0: spheres are numbered first among the scene's objects.
LIGHTPATH_REGISTER_SHAPE(lightpath::ShapeType{
    {"shape", "sphere", "a sphere, seen from outside and inside, emitting from its whole surface",
     {lightpath::kShapeNameParameter,
      {"center", lightpath::ParameterType::Point, "m", "", {}, "its centre", true},
      {"radius", lightpath::ParameterType::Number, "m", "", lightpath::kPositive, "its radius", true},
      lightpath::kShapeMaterialParameter},
     ""},
    0, "spheres", lightpath::addSphere})
