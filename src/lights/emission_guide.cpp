#include "lights/emission_guide.h"

#include <algorithm>

#include "sampling/sampler.h"

namespace lightpath {

EmissionGuide::EmissionGuide(std::vector<SpecularTarget> targets, float aimedShare)
    : targets_(std::move(targets)), aimedShare_(targets_.empty() ? 0.0f : aimedShare) {}

EmittedRay EmissionGuide::sample(const Light& light, Vec2 uPoint, Vec2 uDirection) const {
    if (!(aimedShare_ > 0.0f) || light.atInfinity()) return light.sampleEmission(uPoint, uDirection);
    // uDirection.x picks the branch and, rescaled to [0, 1), serves within it. The light picks its
    // point from uPoint alone, so one call gives the point (which targets it lies outside) and the
    // light's own direction.
    const bool aimed = uDirection.x < aimedShare_;
    Vec2 u = uDirection;
    u.x = std::min(aimed ? u.x / aimedShare_ : (u.x - aimedShare_) / (1.0f - aimedShare_), kBelowOne);
    EmittedRay e = light.sampleEmission(uPoint, u);
    const TargetCones cones(targets_, e.ray.origin);
    if (cones.count() == 0) return e;  // no target to aim at from here: the mixture is the light's own
    if (aimed) e = light.emitAlong(e, cones.sample(u));
    e.pdfDirection = mixture(light.pdfEmissionDirection(e.normal, e.ray.direction), cones, e.ray.direction);
    return e;
}

float EmissionGuide::pdfDirection(const Light& light, const Vec3& point, const Vec3& normal,
                                  const Vec3& direction) const {
    const float own = light.pdfEmissionDirection(normal, direction);
    if (!(aimedShare_ > 0.0f) || light.atInfinity()) return own;
    return mixture(own, TargetCones(targets_, point), direction);
}

float EmissionGuide::mixture(float own, const TargetCones& cones, const Vec3& direction) const {
    if (cones.count() == 0) return own;
    return float((1.0 - double(aimedShare_)) * double(own) + double(aimedShare_) * cones.density(direction));
}

}  // namespace lightpath
