#pragma once
// The single-scattering albedo of GGX with height-correlated Smith G2 and a Fresnel factor given
// as a function of wo.m, written out in double from Walter et al. 2007 and Heitz 2014 (eq. 99),
// integrated over microfacet normals m rather than sampled as the code under test does:
// E(wo) = integral F(wo.m) D(m) G2(wo, wi) (wo.m) / cos theta_o dm, wi the mirror of wo about m
// (dwi = 4 (wo.m) dm), by the midpoint rule in theta_m and phi_m.
#include <cmath>

namespace lightpath::test {

template <class Fresnel>
double ggxAlbedoWithFresnel(double cosOut, double alpha, Fresnel fresnel, int thetaSteps = 4000, int phiSteps = 360) {
    const double a2 = alpha * alpha, pi = 3.14159265358979323846;
    const double sinOut = std::sqrt(1.0 - cosOut * cosOut);
    const double ox = sinOut, oz = cosOut;
    auto lambda = [&](double cz) {
        const double tan2 = (1.0 - cz * cz) / (cz * cz);
        return 0.5 * (std::sqrt(1.0 + a2 * tan2) - 1.0);
    };
    const double dTheta = 0.5 * pi / thetaSteps, dPhi = 2.0 * pi / phiSteps;
    double sum = 0.0;
    for (int t = 0; t < thetaSteps; ++t) {
        const double theta = (t + 0.5) * dTheta, cm = std::cos(theta), sm = std::sin(theta);
        const double d = a2 / (pi * std::pow((a2 - 1.0) * cm * cm + 1.0, 2.0));
        for (int p = 0; p < phiSteps; ++p) {
            const double phi = (p + 0.5) * dPhi;
            const double mx = sm * std::cos(phi), mz = cm;
            const double om = ox * mx + oz * mz;
            if (om <= 0.0) continue;
            const double iz = 2.0 * om * mz - oz;  // the mirror of wo about m
            if (iz <= 0.0) continue;
            const double g2 = 1.0 / (1.0 + lambda(oz) + lambda(iz));
            sum += fresnel(om) * d * g2 * om / oz * sm * dTheta * dPhi;
        }
    }
    return sum;
}

// With Schlick's Fresnel of reflectance f0 at normal incidence (1: F = 1).
inline double ggxAlbedoReference(double cosOut, double alpha, double f0 = 1.0) {
    return ggxAlbedoWithFresnel(cosOut, alpha, [f0](double om) { return f0 + (1.0 - f0) * std::pow(1.0 - om, 5.0); });
}

}  // namespace lightpath::test
