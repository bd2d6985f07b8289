// The [[lights]] types that are emissive shapes (scenes/README.md, "Area lights"): an object whose
// material only emits, and its geometry. LightSet samples them like any emitting surface.
#include <glm/geometric.hpp>

#include "materials/texture.h"

#include "scene/light_type.h"

namespace lightpath {
namespace {

// A parallelogram corner + s edge1 + t edge2 (s, t in [0, 1]) emitting on the side of
// edge1 x edge2, as two triangles; a textured radiance is read at uv = (s, t).
void addQuadLight(const ParameterValues& values, SceneBuilder& scene) {
    const Vec3 corner = values.vec3("corner"), edge1 = values.vec3("edge1"), edge2 = values.vec3("edge2");
    if (glm::length(glm::cross(edge1, edge2)) == 0.0f) {
        values.fail("edge2", "expected an edge not parallel to edge1 (the quad has no area), got " + formatVec3(edge2));
    }
    checkLightName(values);
    const ColorParameter radiance = colorParameter(values, "radiance");
    const std::uint32_t object = scene.addEmitterObject(values.has("name") ? values.text("name") : std::string(), radiance);
    const double area = glm::length(glm::cross(glm::dvec3(edge1), glm::dvec3(edge2)));
    if (auto warning = tooSmallToSampleWarning("quad", area, radiance.mean())) scene.warn(values.located("edge2", *warning));
    scene.addTriangle({corner, corner + edge1, corner + edge1 + edge2, object});
    if (radiance.textured()) scene.setTriangleUvs({{0.0f, 0.0f}, {1.0f, 0.0f}, {1.0f, 1.0f}, true});
    scene.addTriangle({corner, corner + edge1 + edge2, corner + edge2, object});
    if (radiance.textured()) scene.setTriangleUvs({{0.0f, 0.0f}, {1.0f, 1.0f}, {0.0f, 1.0f}, true});
}

// A sphere emitting on both sides of its surface.
void addSphereLight(const ParameterValues& values, SceneBuilder& scene) {
    checkLightName(values);
    Sphere sphere;
    sphere.center = values.vec3("center");
    sphere.radius = values.number("radius");
    const ColorParameter radiance = colorParameter(values, "radiance");
    sphere.object = scene.addEmitterObject(values.has("name") ? values.text("name") : std::string(), radiance);
    if (auto warning = tooSmallToSampleWarning("sphere", surfaceArea(sphere), radiance.mean()))
        scene.warn(values.located("radius", *warning));
    scene.addSphere(sphere);
}

constexpr std::string_view kRadianceDoc =
    "emitted radiance, or a texture of it (`{ texture = ... }`); the light's material only emits";

}  // namespace
}  // namespace lightpath

LIGHTPATH_REGISTER_LIGHT(lightpath::LightType{
    {"light", "quad", "an area light: a parallelogram emitting on the side of edge1 × edge2",
     {lightpath::kLightNameParameter,
      {"corner", lightpath::ParameterType::Point, "m", "", {}, "one corner", true},
      {"edge1", lightpath::ParameterType::Point, "m", "", {}, "the quad is `corner + s edge1 + t edge2`, s, t in [0, 1]",
       true},
      {"edge2", lightpath::ParameterType::Point, "m", "", {}, "not parallel to `edge1`", true},
      {"radiance", lightpath::ParameterType::Colour, "W/(m² sr)", "", lightpath::kNonNegative,
       lightpath::kRadianceDoc, true}},
     "<L.>"},
    1, lightpath::addQuadLight})

LIGHTPATH_REGISTER_LIGHT(lightpath::LightType{
    {"light", "sphere", "an area light: a sphere emitting on both sides of its surface",
     {lightpath::kLightNameParameter,
      {"center", lightpath::ParameterType::Point, "m", "", {}, "its centre", true},
      {"radius", lightpath::ParameterType::Number, "m", "", lightpath::kPositive, "its radius", true},
      {"radiance", lightpath::ParameterType::Colour, "W/(m² sr)", "", lightpath::kNonNegative,
       lightpath::kRadianceDoc, true}},
     "<L.>"},
    2, lightpath::addSphereLight})
