#pragma once
// The Henyey-Greenstein phase function (Henyey and Greenstein 1941), as pbrt-v4 11.3.1 writes it:
//
//   p(wo, wi) = (1 - g²) / (4 pi (1 + g² + 2 g cos theta)^(3/2)),  cos theta = wo . wi
//
// with wo and wi both pointing away from the scattering point (wo back towards the eye), so g > 0
// scatters forward (wi near -wo) and g < 0 backward. It integrates to 1 over the sphere; sample()
// draws wi with exactly density p, so a sample's weight p / pdf is 1.
#include "math/types.h"

namespace lightpath {

struct PhaseSample {
    Vec3 wi;
    float pdf = 0.0f;  // per steradian, equal to p(wo, wi)
};

class HenyeyGreensteinPhase {
public:
    // g in (-1, 1): the mean cosine of the scattering angle; 0 is isotropic.
    explicit HenyeyGreensteinPhase(float g = 0.0f) : g_(g) {}

    float g() const { return g_; }
    // p(wo, wi), per steradian; wo and wi unit, both pointing away from the scattering point.
    float eval(const Vec3& wo, const Vec3& wi) const;
    float pdf(const Vec3& wo, const Vec3& wi) const { return eval(wo, wi); }
    // wi with density eval(wo, wi), by inverting the distribution of cos theta (pbrt-v4 11.3.1).
    PhaseSample sample(const Vec3& wo, Vec2 u) const;

private:
    float g_;
};

}  // namespace lightpath
