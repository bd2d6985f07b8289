#pragma once
// Light walks aimed at specular objects (bidirectional path tracing's light subpaths). A caustic,
// E D S+ L, is made only by a light walk through the S vertices (no join passes a delta vertex),
// and a ball of radius r at distance d from a point light catches r^2 / (4 d^2) of its rays: 0.5%
// for the lecture's glass ball. So a share of the walks leaves into the cone of a mirror's or a
// glass's bounding sphere (lights/specular_targets.h), the rest as the light emits: the walk's
// weight and every strategy's MIS weight read the mixture's density, so the estimate stays
// unbiased whatever the share.
#include <span>
#include <vector>

#include "lights/light.h"
#include "lights/specular_targets.h"

namespace lightpath {

class EmissionGuide {
public:
    // Of the walks leaving a point outside some target: half are aimed, half as the light emits.
    static constexpr float kAimedShare = 0.5f;

    EmissionGuide() = default;
    explicit EmissionGuide(std::vector<SpecularTarget> targets, float aimedShare = kAimedShare);

    // A ray leaving `light`: its point by uPoint as Light::sampleEmission picks it; with the
    // aimed share of uDirection.x, a direction uniform in the cone of one target (chosen
    // uniformly among those the point lies outside), else the light's own direction.
    // pdfDirection is the mixture's density. A light at infinity is never aimed.
    EmittedRay sample(const Light& light, Vec2 uPoint, Vec2 uDirection) const;
    // The mixture's density per steradian of leaving `point` (outward normal `normal`, zero for
    // a point light) along unit `direction`: what light tracing's strategies are weighed by.
    float pdfDirection(const Light& light, const Vec3& point, const Vec3& normal, const Vec3& direction) const;

    std::span<const SpecularTarget> targets() const { return targets_; }
    float aimedShare() const { return aimedShare_; }

private:
    // The mixture's density from the light's own and the cones seen from the point.
    float mixture(float own, const TargetCones& cones, const Vec3& direction) const;

    std::vector<SpecularTarget> targets_;
    float aimedShare_ = 0.0f;
};

}  // namespace lightpath
