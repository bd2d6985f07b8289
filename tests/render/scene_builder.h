#pragma once
// Small scenes built in code for closed-form tests: every number the test checks is visible here.
#include <string>

#include "lights/point_light.h"
#include "materials/phong_material.h"
#include "scene/scene.h"

namespace lightpath::test {

inline std::uint32_t addMaterial(Scene& scene, PhongMaterial material) {
    scene.materials.push_back(std::move(material));
    return static_cast<std::uint32_t>(scene.materials.size() - 1);
}

inline std::uint32_t addObject(Scene& scene, const std::string& name, std::uint32_t material) {
    scene.objects.push_back({name, material});
    return static_cast<std::uint32_t>(scene.objects.size() - 1);
}

inline void addPlane(Scene& scene, const std::string& name, std::uint32_t material, Vec3 point, Vec3 normal) {
    scene.planes.push_back({point, glm::normalize(normal), addObject(scene, name, material)});
}

inline void addSphere(Scene& scene, const std::string& name, std::uint32_t material, Vec3 center, float radius) {
    scene.spheres.push_back({center, radius, addObject(scene, name, material)});
    scene.objects.back().enclosesVolume = true;  // as the loader marks every sphere: it has an inside
}

// A camera whose centre pixel (odd width and height) looks exactly along eye -> lookAt.
inline CameraDescription centredCamera(Vec3 eye, Vec3 lookAt, Vec3 up, int size = 9) {
    CameraDescription camera;
    camera.eye = eye;
    camera.lookAt = lookAt;
    camera.up = up;
    camera.verticalFovDegrees = 30.0f;
    camera.width = camera.height = size;
    return camera;
}

}  // namespace lightpath::test
