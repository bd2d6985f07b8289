#include "lights/emission_guide.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include <glm/geometric.hpp>

#include "geometry/bounds.h"
#include "sampling/warp.h"
#include "shapes/sphere.h"

namespace lightpath {
namespace {

// The largest float below 1: a remapped sample stays in [0, 1) as the sampler's do.
constexpr float kBelowOne = 0x1.fffffep-1f;

}  // namespace

EmissionGuide::EmissionGuide(std::vector<Target> targets, float aimedShare)
    : targets_(std::move(targets)), aimedShare_(targets_.empty() ? 0.0f : aimedShare) {}

int EmissionGuide::conesFrom(const Vec3& point, const Vec3& direction, double& density) const {
    int outside = 0;
    density = 0.0;
    for (const Target& target : targets_) {
        const std::optional<SphereCone> cone = sphereCone(Sphere{target.centre, target.radius}, point);
        if (!cone) continue;
        ++outside;
        // In the cone: at an angle to its axis (towards the centre) whose sin^2 is within the
        // cone's, tested on the cross product so that a narrow cone keeps its precision.
        const Vec3 towards = -cone->axis;
        const float along = glm::dot(direction, towards);
        const Vec3 across = glm::cross(direction, towards);
        if (along > 0.0f && double(glm::dot(across, across)) <= cone->sin2ThetaMax) density += cone->pdf;
    }
    return outside;
}

EmittedRay EmissionGuide::sample(const Light& light, Vec2 uPoint, Vec2 uDirection) const {
    if (!(aimedShare_ > 0.0f) || light.atInfinity()) return light.sampleEmission(uPoint, uDirection);
    // uDirection.x picks the branch and, rescaled to [0, 1), serves within it. The light picks its
    // point from uPoint alone, so one call gives the point (which targets it lies outside) and the
    // light's own direction.
    const bool aimed = uDirection.x < aimedShare_;
    Vec2 u = uDirection;
    u.x = std::min(aimed ? u.x / aimedShare_ : (u.x - aimedShare_) / (1.0f - aimedShare_), kBelowOne);
    EmittedRay e = light.sampleEmission(uPoint, u);
    double unused = 0.0;
    const int count = conesFrom(e.ray.origin, Vec3{0.0f, 0.0f, 1.0f}, unused);
    if (count == 0) return e;  // no target to aim at from here: the mixture is the light's own
    if (aimed) {
        // The k-th target the point lies outside, then a direction uniform in its cone (pbrt-v4
        // 6.2.4), both from u.x.
        const float scaled = u.x * float(count);
        const int k = std::min(int(scaled), count - 1);
        const float uCone = std::min(scaled - float(k), kBelowOne);
        std::optional<SphereCone> cone;
        for (int i = 0, seen = 0; i < int(targets_.size()); ++i) {
            cone = sphereCone(Sphere{targets_[i].centre, targets_[i].radius}, e.ray.origin);
            if (cone && seen++ == k) break;
        }
        const double oneMinusCos = double(uCone) * cone->oneMinusCosThetaMax;
        const double sin2Theta = oneMinusCos * (2.0 - oneMinusCos);
        const float cosTheta = float(1.0 - oneMinusCos), sinTheta = float(std::sqrt(sin2Theta));
        const float phi = 2.0f * kPi * u.y;
        const Vec3 direction = glm::normalize(
            Frame(-cone->axis).toWorld({sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta}));
        e = light.emitAlong(e, direction);
    }
    e.pdfDirection = pdfDirection(light, e.ray.origin, e.normal, e.ray.direction);
    return e;
}

float EmissionGuide::pdfDirection(const Light& light, const Vec3& point, const Vec3& normal,
                                  const Vec3& direction) const {
    const float own = light.pdfEmissionDirection(normal, direction);
    if (!(aimedShare_ > 0.0f) || light.atInfinity()) return own;
    double cones = 0.0;
    const int count = conesFrom(point, direction, cones);
    if (count == 0) return own;
    return float((1.0 - double(aimedShare_)) * double(own) + double(aimedShare_) * cones / double(count));
}

std::vector<EmissionGuide::Target> specularTargets(const Scene& scene) {
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
    std::vector<EmissionGuide::Target> targets;
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        if (!specular[i] || box[i].empty()) continue;
        if (spheres[i] == 1 && others[i] == 0)
            targets.push_back({sphereOfObject[i].center, sphereOfObject[i].radius});
        else
            targets.push_back({box[i].centroid(), 0.5f * glm::length(box[i].hi - box[i].lo)});
    }
    return targets;
}

}  // namespace lightpath
