// `[[planes]]`: an infinite plane, declared, read and registered here like every shape kind
// (docs/extending.md). Its geometry stays in SceneGeometry's own array of planes: unbounded, it is
// tested beside the accelerator, never in it.
#include "scene/shape_type.h"

namespace lightpath {
namespace {

void addPlane(const ParameterValues& values, SceneBuilder& scene) {
    Plane plane;
    plane.point = values.vec3("point");
    // In double: the squared length of a tiny float vector (1e-30) underflows to 0 in float.
    plane.normal = Vec3(glm::normalize(glm::dvec3(values.vec3("normal"))));
    plane.object = scene.addShapeObject(values);
    scene.addPlane(plane);
}

}  // namespace
}  // namespace lightpath

// Rank 1: planes are numbered after the spheres, before every other kind.
LIGHTPATH_REGISTER_SHAPE(lightpath::ShapeType{
    {"shape", "plane", "an infinite plane, seen from both sides",
     {lightpath::kShapeNameParameter,
      {"point", lightpath::ParameterType::Point, "m", "", {}, "a point on the plane", true},
      {"normal", lightpath::ParameterType::Vector, "", "", {}, "the side it faces (normalised)", true},
      lightpath::kShapeMaterialParameter},
     ""},
    1, "planes", lightpath::addPlane})
