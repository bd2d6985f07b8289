#include "bench/ray_sets.h"

#include <algorithm>
#include <cmath>

#include "bench/height_field.h"
#include "lights/point_light.h"
#include "math/random.h"
#include "scene/camera.h"

namespace lightpath {

Scene heightFieldScene(std::size_t side) {
    Scene scene;
    std::vector<Vec3> vertices;
    vertices.reserve((side + 1) * (side + 1));
    for (std::size_t row = 0; row <= side; ++row) {
        for (std::size_t column = 0; column <= side; ++column) {
            const float x = height_field::coordinate(column, side), z = height_field::coordinate(row, side);
            vertices.emplace_back(x, height_field::height(x, z), z);
        }
    }
    scene.triangles.reserve(2 * side * side);
    height_field::forEachTriangle(side, [&](std::size_t a, std::size_t b, std::size_t c) {
        scene.triangles.push_back({vertices[a], vertices[b], vertices[c], 0});
    });
    scene.camera.eye = Vec3(0.0f, 1.2f, 2.2f);
    scene.camera.lookAt = Vec3(0.0f, -0.1f, 0.0f);
    scene.camera.verticalFovDegrees = 50.0f;
    PointLight light;
    light.location = Vec3(-2.0f, 1.5f, 1.0f);
    scene.lights.push_back(light);
    return scene;
}

Bounds triangleBox(const std::vector<Triangle>& triangles) {
    Bounds box;
    for (const Triangle& t : triangles) {
        box.grow(t.a);
        box.grow(t.b);
        box.grow(t.c);
    }
    return box;
}

std::vector<Ray> primaryRays(const Scene& scene, int side) {
    CameraDescription description = scene.camera;
    description.width = side;
    description.height = side;
    const Camera camera(description);
    std::vector<Ray> rays;
    rays.reserve(static_cast<std::size_t>(side) * static_cast<std::size_t>(side));
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x)
            rays.push_back(camera.generateRay(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f));
    return rays;
}

// z = 1 - 2u, phi = 2 pi v.
std::vector<Ray> randomRays(const Bounds& box, int count) {
    Pcg32 rng(0x5eed, 7);
    std::vector<Ray> rays(static_cast<std::size_t>(count));
    for (Ray& ray : rays) {
        ray.origin = box.lo + (box.hi - box.lo) * Vec3(rng.nextFloat(), rng.nextFloat(), rng.nextFloat());
        const float z = 1.0f - 2.0f * rng.nextFloat();
        const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
        const float phi = 2.0f * kPi * rng.nextFloat();
        ray.direction = Vec3(r * std::cos(phi), r * std::sin(phi), z);
    }
    return rays;
}

// Callers lift by a small fraction of the scene size, so every accelerator answers the same
// question without an own-primitive filter.
std::vector<Ray> shadowRays(const SceneGeometry& geometry, const std::vector<Ray>& primary, const Vec3& light,
                            float lift) {
    std::vector<Ray> rays;
    for (const Ray& ray : primary) {
        const auto hit = geometry.intersect(ray);
        if (!hit) continue;
        const Vec3 side = glm::dot(hit->normal, light - hit->point) >= 0.0f ? hit->normal : -hit->normal;
        Ray shadow;
        shadow.origin = hit->point + lift * side;
        const Vec3 toLight = light - shadow.origin;
        const float distance = glm::length(toLight);
        shadow.direction = toLight / distance;
        shadow.tMax = distance;
        rays.push_back(shadow);
    }
    return rays;
}

}  // namespace lightpath
