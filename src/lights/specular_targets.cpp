#include "lights/specular_targets.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include <glm/geometric.hpp>

#include "geometry/bounds.h"
#include "sampling/sampler.h"
#include "sampling/warp.h"

namespace lightpath {

std::vector<SpecularTarget> specularTargets(const Scene& scene) {
    std::vector<bool> specular(scene.objects.size(), false);
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const Material& material = *scene.materials[scene.objects[i].material];
        if (material.isInterface()) continue;
        const Lobes lobes = material.lobes();
        for (int lobe = 0; lobe < int(lobes.size()); ++lobe)
            if (lobes[std::size_t(lobe)].delta() && material.has(lobe)) specular[i] = true;
    }
    // Each object's box, and whether it is one sphere (then its own sphere bounds it exactly).
    std::vector<Bounds> box(scene.objects.size());
    std::vector<int> spheres(scene.objects.size(), 0), others(scene.objects.size(), 0);
    std::vector<Sphere> sphereOfObject(scene.objects.size());
    for (const Sphere& s : scene.spheres) {
        if (s.object >= specular.size() || !specular[s.object]) continue;
        box[s.object].grow(s.center - Vec3(s.radius));
        box[s.object].grow(s.center + Vec3(s.radius));
        ++spheres[s.object];
        sphereOfObject[s.object] = s;
    }
    for (const ShapeRecord& record : scene.shapes) {
        if (record.object >= specular.size() || !specular[record.object]) continue;
        if (!record.ops->bounded) {
            specular[record.object] = false;  // a plane: no cone holds it
            continue;
        }
        box[record.object].grow(record.ops->bounds(record));
        ++others[record.object];
    }
    for (const Triangle& t : scene.triangles) {
        if (t.object >= specular.size() || !specular[t.object]) continue;
        box[t.object].grow(t.a);
        box[t.object].grow(t.b);
        box[t.object].grow(t.c);
        ++others[t.object];
    }
    std::vector<SpecularTarget> targets;
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        if (!specular[i] || box[i].empty()) continue;
        if (spheres[i] == 1 && others[i] == 0)
            targets.push_back({sphereOfObject[i].center, sphereOfObject[i].radius});
        else
            targets.push_back({box[i].centroid(), 0.5f * glm::length(box[i].hi - box[i].lo)});
    }
    if (targets.size() > kMaxSpecularTargets) {
        // The largest, in scene order among equals, so the choice is the same on every run.
        std::stable_sort(targets.begin(), targets.end(),
                         [](const SpecularTarget& a, const SpecularTarget& b) { return a.radius > b.radius; });
        targets.resize(kMaxSpecularTargets);
    }
    return targets;
}

TargetCones::TargetCones(std::span<const SpecularTarget> targets, const Vec3& point) {
    for (const SpecularTarget& target : targets.first(std::min(targets.size(), kMaxSpecularTargets))) {
        const std::optional<SphereCone> cone = sphereCone(Sphere{target.centre, target.radius}, point);
        if (cone) cones_[std::size_t(count_++)] = *cone;
    }
}

Vec3 TargetCones::sample(Vec2 u) const {
    // The k-th cone, then a direction in it from what is left of u.x.
    const float scaled = u.x * float(count_);
    const int k = std::min(int(scaled), count_ - 1);
    const float uCone = std::min(scaled - float(k), kBelowOne);
    const SphereCone& cone = cones_[std::size_t(k)];
    const double oneMinusCos = double(uCone) * cone.oneMinusCosThetaMax;
    const double sin2Theta = oneMinusCos * (2.0 - oneMinusCos);
    const float cosTheta = float(1.0 - oneMinusCos), sinTheta = float(std::sqrt(sin2Theta));
    const float phi = 2.0f * kPi * u.y;
    return glm::normalize(Frame(-cone.axis).toWorld({sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta}));
}

double TargetCones::density(const Vec3& direction) const {
    if (count_ == 0) return 0.0;
    double sum = 0.0;
    for (int k = 0; k < count_; ++k) {
        const SphereCone& cone = cones_[std::size_t(k)];
        // In the cone: at an angle to its axis (towards the centre) whose sin^2 is within the
        // cone's, tested on the cross product so that a narrow cone keeps its precision.
        const Vec3 towards = -cone.axis;
        const Vec3 across = glm::cross(direction, towards);
        if (glm::dot(direction, towards) > 0.0f && double(glm::dot(across, across)) <= cone.sin2ThetaMax)
            sum += cone.pdf;
    }
    return sum / double(count_);
}

}  // namespace lightpath
