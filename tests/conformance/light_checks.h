#pragma once
// The standard checks every light gets (docs/extending.md), each light of a case's scene as
// LightSet makes it: pdf() integrates to 1 over the light's solid angle and sample() draws with
// that density (the Monte Carlo integral of 1/pdf over its samples is the solid angle rays see),
// every sample's weight is the radiance a ray finds there over its pdf, power() is the flux
// sampleEmission() estimates, and every value is finite. Statistical checks use fixed seeds and
// reject a correct light with probability `kLightAlpha` each.
#include <vector>

#include "cases.h"
#include "check_result.h"
#include "accel/scene_geometry.h"
#include "lights/light.h"
#include "lights/light_set.h"

namespace lightpath::conformance {

inline constexpr double kLightAlpha = 1e-4;

// Everything the checks need from one case's scene: its geometry and its lights.
struct LightWorld {
    explicit LightWorld(const Scene& scene);
    LightWorld(const LightWorld&) = delete;
    LightWorld& operator=(const LightWorld&) = delete;

    const Scene& scene;
    SceneGeometry geometry;
    LightSet lights;
};

// From `receiver`: the mean over uniform directions of pdf(receiver, hit) 4 pi where a ray meets
// the light (0 elsewhere) is 1, and the mean of 1 / pdf over sample()'s points is the solid angle
// 4 pi P(a uniform ray meets the light). Area lights only (a delta light has no density).
CheckResult checkLightDensity(const Light& light, const LightWorld& world, const Vec3& receiver);
// Every sample towards `receiver`: pdf() of its point is its pdf, wi and distance point at it, a
// ray along wi meets the light there, and its weight is radiance() there over the pdf.
CheckResult checkLightSamples(const Light& light, const LightWorld& world, const Vec3& receiver);
// A delta light: the weight over falloff(d), averaged over receivers in every direction at one
// distance, times 4 pi, is power() (the radiant intensity integrated over the sphere).
CheckResult checkDeltaLightIntensity(const Light& light);
// power() against the Monte Carlo estimate of the flux from sampleEmission():
// E[Le |cos| / (pdfPosition pdfDirection)], and sampleEmission()'s densities against
// pdfEmissionPosition() and pdfEmissionDirection().
CheckResult checkLightPower(const Light& light);
// The same flux through light walks aimed at three targets around the light (EmissionGuide, which
// leaves by emitAlong()), each ray's density against EmissionGuide::pdfDirection.
CheckResult checkAimedEmission(const Light& light);

// Points that receive the light, found from the light alone: along three of its emitted rays, near
// it and a few times its size away (1 / sqrt(pdfEmissionPosition()) is the square root of its area).
std::vector<Vec3> receiversOf(const Light& light);

// Every check above for every light of the case.
CheckResult checkLightCase(const LightCase& c);

}  // namespace lightpath::conformance
