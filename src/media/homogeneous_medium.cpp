#include "media/homogeneous_medium.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "media/medium_type.h"

namespace lightpath {
namespace {

// exp(-sigma d) per channel, with a channel of sigma = 0 fully transmitting even over an infinite
// distance (0 · inf would be NaN).
// A grey sigma (every channel the same, as most fog is) takes one exp for all three: the same
// operation on the same operands, so the same bits (docs/performance.md, Shading share, sixth pass).
Rgb beerLambert(const Rgb& sigma, float distance) {
    if (sigma.r == sigma.g && sigma.g == sigma.b) return Rgb{sigma.r == 0.0f ? 1.0f : std::exp(-sigma.r * distance)};
    Rgb t;
    for (int c = 0; c < 3; ++c) t[c] = sigma[c] == 0.0f ? 1.0f : std::exp(-sigma[c] * distance);
    return t;
}

float mean(const Rgb& v) { return (v.r + v.g + v.b) / 3.0f; }

}  // namespace

MediumSample HomogeneousMedium::sampleDistance(const Ray&, float tMax, float uChannel, float uDistance) const {
    const Rgb sigma = sigmaT();
    // A medium that only absorbs scatters nothing in: its transmittance is the whole estimate, exactly.
    if (isBlack(sigmaS)) return {false, tMax, beerLambert(sigma, tMax)};
    const int channel = std::min(static_cast<int>(uChannel * 3.0f), 2);
    const float t = sigma[channel] > 0.0f ? -std::log1p(-uDistance) / sigma[channel]
                                          : std::numeric_limits<float>::infinity();
    if (t < tMax) {
        // One-sample MIS over channels: the density is the mean of sigma_t,i T_i(t).
        const Rgb transmitted = beerLambert(sigma, t);
        const float pdf = mean(sigma * transmitted);
        if (!(pdf > 0.0f)) return {true, t, Rgb{0.0f}};
        return {true, t, transmitted * sigmaS / pdf};
    }
    // Passing: the probability is the mean of the channels' T(tMax).
    const Rgb transmitted = beerLambert(sigma, tMax);
    const float probability = mean(transmitted);
    if (!(probability > 0.0f)) return {false, tMax, Rgb{0.0f}};
    return {false, tMax, transmitted / probability};
}

bool HomogeneousMedium::choosesChannel() const {
    const Rgb sigma = sigmaT();
    return !isBlack(sigmaS) && !(sigma.r == sigma.g && sigma.g == sigma.b);
}

Rgb HomogeneousMedium::transmittance(const Ray&, float t0, float t1) const {
    return beerLambert(sigmaT(), t1 - t0);
}

namespace {

MediumSlot makeHomogeneous(const ParameterValues& values) {
    HomogeneousMedium medium;
    medium.sigmaA = values.colour("sigma_a");
    medium.sigmaS = values.colour("sigma_s");
    medium.g = values.number("g");
    return medium;
}

// g = ±1 is a delta phase function (and the density's normalisation divides by zero there).
constexpr Range kOpenUnitInterval{-1.0, 1.0, true, true};

}  // namespace
}  // namespace lightpath

LIGHTPATH_REGISTER_MEDIUM(lightpath::MediumType{
    {"medium", "homogeneous", "the same absorption and scattering everywhere: fog, smoke (Beer-Lambert)",
     {{"sigma_a", lightpath::ParameterType::Colour, "1/unit", "0", lightpath::kNonNegative,
       "absorption coefficient: the fraction absorbed per unit length"},
      {"sigma_s", lightpath::ParameterType::Colour, "1/unit", "0", lightpath::kNonNegative,
       "scattering coefficient: the fraction scattered per unit length"},
      {"g", lightpath::ParameterType::Number, "", "0", lightpath::kOpenUnitInterval,
       "Henyey-Greenstein asymmetry: mean cosine of the scattering angle, > 0 forward, 0 isotropic"}},
     "<V.>"},
    0, lightpath::makeHomogeneous})
