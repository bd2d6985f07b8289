#pragma once
// Light walks aimed at specular objects (bidirectional path tracing's light subpaths). A caustic,
// E D S+ L, is made only by a light walk through the S vertices (no join passes a delta vertex),
// and a ball of radius r at distance d from a point light catches r^2 / (4 d^2) of its rays: 0.5%
// for the lecture's glass ball. So a share of the walks leaves into the cone of a mirror's or a
// glass's bounding sphere, the rest as the light emits (Jensen 1996's projection maps, here as a
// one-sample mixture, Veach 1997 ch. 9): the walk's weight and every strategy's MIS weight read
// the mixture's density, so the estimate stays unbiased whatever the share.
#include <span>
#include <vector>

#include "lights/light.h"
#include "scene/scene.h"

namespace lightpath {

class EmissionGuide {
public:
    struct Target {
        Vec3 centre{0.0f};
        float radius = 0.0f;
    };
    // Of the walks leaving a point outside some target: half are aimed, half as the light emits.
    static constexpr float kAimedShare = 0.5f;

    EmissionGuide() = default;
    explicit EmissionGuide(std::vector<Target> targets, float aimedShare = kAimedShare);

    // A ray leaving `light`: its point by uPoint as Light::sampleEmission picks it; with the
    // aimed share of uDirection.x, a direction uniform in the cone of one target (chosen
    // uniformly among those the point lies outside), else the light's own direction.
    // pdfDirection is the mixture's density. A light at infinity is never aimed.
    EmittedRay sample(const Light& light, Vec2 uPoint, Vec2 uDirection) const;
    // The mixture's density per steradian of leaving `point` (outward normal `normal`, zero for
    // a point light) along unit `direction`: what light tracing's strategies are weighed by.
    float pdfDirection(const Light& light, const Vec3& point, const Vec3& normal, const Vec3& direction) const;

    std::span<const Target> targets() const { return targets_; }
    float aimedShare() const { return aimedShare_; }

private:
    // How many targets `point` lies outside, and the sum of their cones' densities along
    // `direction` (the cones holding it).
    int conesFrom(const Vec3& point, const Vec3& direction, double& density) const;

    std::vector<Target> targets_;
    float aimedShare_ = 0.0f;
};

// The bounding spheres of the scene's bounded objects whose material has a delta lobe (a mirror,
// glass): where light walks are aimed. Planes, unbounded, are none; nor are media's interfaces.
std::vector<EmissionGuide::Target> specularTargets(const Scene& scene);

}  // namespace lightpath
