#pragma once
// The standard checks every material gets (docs/extending.md): its sampling against its densities
// (Pearson's chi-square per smooth lobe, as Nori's chi2test), every sample's weight against
// eval / pdf, Helmholtz reciprocity where claimed, a white furnace where energy conservation is
// claimed and the lobe-choice albedo() against the lobe's reflectance, no NaN, infinity or
// negative value, and the delta branches' directions and weights. Directions are in the frame of
// the shading normal +z. Statistical checks use fixed seeds and reject a correct material with
// probability `alpha` each.
#include <vector>

#include "cases.h"
#include "check_result.h"
#include "materials/material.h"

namespace lightpath::conformance {

// Rejection threshold of one statistical test: with about 120 of them over the shipped cases, a
// correct material set fails one with probability about 1% (with the fixed seeds, a run that
// passes passes every time).
inline constexpr double kMaterialAlpha = 1e-4;

// Outgoing directions the checks look from: near the normal, oblique, grazing (wo.z = cos theta_o).
std::vector<Vec3> outgoingDirections();

// Pearson's chi-square of sample(lobe) against pdf(lobe), one smooth lobe, from wo.
CheckResult checkSamplingMatchesPdf(const Material& material, int lobe, const Vec3& wo, bool entering = true);
// For every sampled direction, of each smooth lobe and of the per-hit Bsdf: the returned pdf is
// pdf(wi) and the weight is eval(wi) / pdf(wi) (eval is f |cos theta_i|); from below the shading
// normal, where eval is 0, sampling returns nothing or weight 0.
CheckResult checkSampleWeights(const Material& material, const Vec3& wo);
// f(wo, wi) == f(wi, wo), i.e. eval(wo, wi) / cos theta_i == eval(wi, wo) / cos theta_o.
CheckResult checkReciprocity(const Material& material, int lobe);
// White furnace: the mean weight of the Bsdf's samples (everything it reflects and transmits of
// unit incident light, importance transport: no radiance compression) stays <= 1 per channel.
CheckResult checkEnergyConservation(const Material& material);
// albedo(lobe) at normal incidence within a factor 1.5 of the lobe's reflectance there: the Bsdf
// chooses lobes in proportion to it (a lobe it underrates is sampled too rarely, one it calls 0
// never). Phong's highlight albedo, 8 ks / (n + 1), is 28% above the lobe's reflectance at n = 5.
CheckResult checkLobeAlbedo(const Material& material, int lobe);
// The material declares 1 to kMaxLobes lobes, each scattering by an event in `events` (an LPE over
// one event, the schema's).
CheckResult checkDeclaredLobes(const Material& material, const std::string& events);
// The Bsdf's one-sample estimate, E[weight], equals the integral of every smooth lobe's eval (by
// a defensive mixture of uniform directions and lobes about the Bsdf's samples, whose density
// alone weighs them: not the material's own pdf) plus the delta branches' weights.
CheckResult checkBsdfUnbiased(const Material& material, const Vec3& wo, bool entering);
// eval, pdf, albedo, sample and the branches are finite and non-negative for any directions, on
// either side, in either transport mode; sampled directions are unit vectors.
CheckResult checkFiniteNonNegative(const Material& material);
// Delta branches: the mirror ray is the mirror direction of wo; the refracted ray is on the other
// side, in the plane of wo and the normal, and refracting it back gives wo (Snell's law both ways);
// a branch's albedo is its weight's largest channel under importance transport; no branch comes
// from a material none of whose delta lobes is present (Bsdf does not ask it).
CheckResult checkSpecularBranches(const Material& material);

// Every check above, over outgoingDirections() and the case's claims.
CheckResult checkMaterial(const MaterialCase& c);

}  // namespace lightpath::conformance
