#include "lights/emitters.h"

#include <algorithm>

#include "sampling/warp.h"

namespace lightpath {

EmitterSet::EmitterSet(const Scene& scene, const SceneGeometry& geometry)
    : scene_(scene), geometry_(geometry), pdfArea_(geometry.primitiveCount(), 0.0f) {
    const auto& spheres = geometry.spheres();
    const auto& triangles = geometry.triangles();
    const auto triangleBase = static_cast<std::uint32_t>(spheres.size() + geometry.planes().size());
    std::vector<float> power;
    auto consider = [&](std::uint32_t object, std::uint32_t primitive, float area) {
        const Rgb& emission = scene.materials[scene.objects[object].material].emission;
        if (isBlack(emission) || !(area > 0.0f)) return;
        emitters_.push_back({primitive, area, 0.0f});
        power.push_back(area * maxComponent(emission));
    };
    for (std::uint32_t i = 0; i < spheres.size(); ++i)
        consider(spheres[i].object, i, 4.0f * kPi * spheres[i].radius * spheres[i].radius);
    for (std::uint32_t i = 0; i < triangles.size(); ++i) {
        const Triangle& t = triangles[i];
        consider(t.object, triangleBase + i, 0.5f * glm::length(glm::cross(t.b - t.a, t.c - t.a)));
    }
    float total = 0.0f;
    for (float p : power) total += p;
    float cumulative = 0.0f;
    for (std::size_t i = 0; i < emitters_.size(); ++i) {
        const float probability = power[i] / total;
        cumulative += probability;
        emitters_[i].cumulative = cumulative;
        pdfArea_[emitters_[i].primitive] = probability / emitters_[i].area;
    }
    if (!emitters_.empty()) emitters_.back().cumulative = 1.0f;
}

EmitterSample EmitterSet::sample(const Vec3& receiver, float uPick, Vec2 u) const {
    const auto it = std::upper_bound(emitters_.begin(), emitters_.end(), uPick,
                                     [](float value, const Emitter& e) { return value < e.cumulative; });
    const Emitter& emitter = it == emitters_.end() ? emitters_.back() : *it;
    EmitterSample s;
    s.primitive = emitter.primitive;
    s.pdfArea = pdfArea_[emitter.primitive];
    const auto& spheres = geometry_.spheres();
    if (emitter.primitive < spheres.size()) {
        const Sphere& sphere = spheres[emitter.primitive];
        s.normal = sampleUniformSphere(u);
        s.point = sphere.center + sphere.radius * s.normal;
        s.object = sphere.object;
    } else {
        const Triangle& t = geometry_.triangles()[emitter.primitive - spheres.size() - geometry_.planes().size()];
        const Vec3 b = sampleUniformTriangle(u);
        s.point = b.x * t.a + b.y * t.b + b.z * t.c;
        s.normal = glm::normalize(glm::cross(t.b - t.a, t.c - t.a));
        s.object = t.object;
        if (glm::dot(s.normal, receiver - s.point) <= 0.0f) return s;  // behind: no radiance
    }
    s.radiance = scene_.materials[scene_.objects[s.object].material].emission;
    return s;
}

Rgb EmitterSet::radiance(const SurfaceHit& hit, const Vec3& towardViewer) const {
    // Spheres emit on both sides; triangles on the side their winding's normal faces.
    if (glm::dot(hit.normal, towardViewer) <= 0.0f && hit.shape != ShapeKind::Sphere) return Rgb{0.0f};
    return scene_.materials[scene_.objects[hit.object].material].emission;
}

float areaToSolidAngle(float pdfArea, const Vec3& receiver, const Vec3& point, const Vec3& normal) {
    const Vec3 toPoint = point - receiver;
    const float distance2 = glm::dot(toPoint, toPoint);
    const float cosEmitter = std::fabs(glm::dot(normal, toPoint)) / std::sqrt(distance2);
    return cosEmitter > 0.0f ? pdfArea * distance2 / cosEmitter : 0.0f;
}

}  // namespace lightpath
