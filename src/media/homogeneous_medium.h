#pragma once
// A medium with the same absorption sigma_a and scattering sigma_s everywhere (per unit length of
// the scene, per RGB channel) and a Henyey-Greenstein phase function: fog, smoke, milk. Its
// transmittance is Beer-Lambert's T(d) = exp(-sigma_t d), sigma_t = sigma_a + sigma_s.
//
// Free flights with a coloured sigma_t are sampled spectrally (pbrt-v4 14.2.2, "hero" channel):
// one channel, chosen uniformly, draws t with density sigma_t,c exp(-sigma_t,c t); the sample is
// weighted by the one-sample MIS density over channels (balance heuristic), the mean of the three
// channels' densities, so every channel's estimate is unbiased and none divides by a density
// near zero.
#include "media/medium.h"

namespace lightpath {

class HomogeneousMedium final : public Medium {
public:
    Rgb sigmaA{0.0f};  // absorption coefficient, per unit length, >= 0
    Rgb sigmaS{0.0f};  // scattering coefficient, per unit length, >= 0
    float g = 0.0f;    // Henyey-Greenstein asymmetry, in (-1, 1)

    std::unique_ptr<Medium> clone() const override { return std::make_unique<HomogeneousMedium>(*this); }

    Rgb sigmaT() const { return sigmaA + sigmaS; }
    MediumSample sampleDistance(const Ray& ray, float tMax, float uChannel, float uDistance) const override;
    Rgb transmittance(const Ray& ray, float t0, float t1) const override;
    // False for a grey sigma_t (every channel drives the same distance) and for a medium that
    // scatters nothing (no distance is drawn).
    bool choosesChannel() const override;
    bool scatters() const override { return !isBlack(sigmaS); }
    HenyeyGreensteinPhase phase(const Vec3&) const override { return HenyeyGreensteinPhase(g); }
};

}  // namespace lightpath
