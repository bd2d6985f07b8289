#pragma once
// The scene's mirrors and glass as targets to aim rays at. A caustic (a path that leaves a light
// or a diffuse surface and meets a delta lobe: L S+ D, D S+ L) is found only by a ray that happens
// to hit the specular object, and a ball of radius r at distance d catches r^2 / (4 d^2) of the
// rays sent every way. Light walks (lights/emission_guide.h) send a share of theirs into the
// targets' cones instead (Jensen 1996's projection maps, as a one-sample mixture: Veach 1997 ch. 9).
#include <array>
#include <span>
#include <vector>

#include "scene/scene.h"
#include "shapes/sphere.h"

namespace lightpath {

// A bounding sphere of one bounded object whose material has a delta lobe.
struct SpecularTarget {
    Vec3 centre{0.0f};
    float radius = 0.0f;
};

// Aiming costs a cone per target at every ray it may aim, and many targets' cones cover much of
// the sphere of directions, where aiming gains nothing: the largest this many are kept.
inline constexpr std::size_t kMaxSpecularTargets = 16;

// The bounding spheres of the scene's bounded objects whose material has a delta lobe (a mirror,
// glass), the largest kMaxSpecularTargets of them. Planes, unbounded, are none; nor are media's
// interfaces.
std::vector<SpecularTarget> specularTargets(const Scene& scene);

// The cones of the targets seen from one point: those it lies outside, each computed once.
class TargetCones {
public:
    TargetCones(std::span<const SpecularTarget> targets, const Vec3& point);

    int count() const { return count_; }
    // A direction towards a target chosen uniformly among the cones, uniform within its cone
    // (pbrt-v4 6.2.4), both from u; count() > 0.
    Vec3 sample(Vec2 u) const;
    // The density per steradian of sample() returning `direction`: the mean of the cones' densities
    // over the cones that hold it. Zero when count() is 0.
    double density(const Vec3& direction) const;

private:
    std::array<SphereCone, kMaxSpecularTargets> cones_;
    int count_ = 0;
};

}  // namespace lightpath
