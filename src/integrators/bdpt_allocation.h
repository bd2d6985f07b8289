#pragma once
// How many light walks bidirectional path tracing traces per camera sample, q on average. Below 1,
// a fraction q of the samples walk from a light, the others trace the eye's strategies alone; above
// 1, every sample traces floor(q) walks and a fraction q - floor(q) of them one more. Light tracing
// (t = 1) uses every walk, counts q samples in the power heuristic (Veach 1997, eq. 9.13) and its
// splats are divided by q; the joins (s, t >= 2) use the first walk only, which a sample has with
// probability min(q, 1), so they count and are divided by min(q, 1). Every q > 0 is unbiased.
// Why joins take one walk: a join costs a shadow ray per eye vertex and light vertex, a splat one
// per light vertex, and q > 1 pays only where splats carry the variance (caustics, which no join
// makes: E D S+ L has no two adjacent smooth vertices on the light's side), so joining the extra
// walks would multiply the dearer work for the variance that does not need it. q trades the light
// walk's cost against the variance of what only it finds. This chooses q from a pilot: per camera
// sample of the pilot, every strategy's contribution with its densities, from which the variance
// per sample at each candidate q follows in closed form (below), and the work of each walk.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "integrators/bdpt_vertex.h"

namespace lightpath {

// The light walks per camera sample a pilot compares, largest first. None below 1/16: the Cornell
// box's pilot gains 4% from 1/8 to 1/16 (variance x work 9.57 -> 8.63) and would gain little more,
// while a caustic the pilot missed would get 32x fewer light walks instead of 16x. None above 8:
// the glass ball's caustic, all splats, takes 4 (docs/performance.md).
inline constexpr std::array<double, 8> kLightWalkFractions = {8.0, 4.0, 2.0, 1.0, 0.5, 0.25, 0.125, 0.0625};

// A pilot's rays and joins costed in units of one ray cast: a join (its four densities, the BSDF
// at both ends, the automaton's steps) counts half a ray. Checked against CPU time on the Cornell
// box under its lamp (64 x 64, 16 spp, q = 1 against 1/8): this model puts the light walk's work at
// 2.1x the eye walk's, the CPU time at 1.8x, so it errs towards fewer light walks by ~15%.
inline constexpr double kJoinCost = 0.5;

// How far, in standard errors of the pilot's comparison, a candidate with fewer light walks may
// be above the least variance x work and still be chosen: the one-standard-error rule (Breiman et
// al. 1984, Classification and Regression Trees, 3.4.3; Hastie, Tibshirani and Friedman 2009,
// 7.10): among the candidates the pilot cannot tell from the best, the cheapest. The pilot's
// pixel variance is carried by a few fireflies (the taxonomy scene, 4,080 samples: 84-98% of it
// in 5 of 2,040 pixels), so its choice swung between 2 and 1/16 with the seed while a 32x pilot
// chose 1/16 at every seed and the render agreed (docs/integrators.md); light walks are the
// technique that must earn its work, as in Grittmann et al. 2022, which starts from the eye's
// strategies alone and adds light subpaths where their estimated efficiency pays.
inline constexpr double kChoiceStandardErrors = 1.0;

// Where one contribution of a camera sample lands.
enum class PilotTerm : std::uint8_t {
    Eye,    // s = 0, 1: the camera sample's own pixel, from the eye's walk alone
    Join,   // s, t >= 2: its own pixel, through the first light walk
    Splat,  // t = 1: another pixel, through the light walk
};

// One camera sample of the pilot, at every candidate fraction.
struct PilotSample {
    std::array<double, kLightWalkFractions.size()> eye{}, join{}, splatSquares{};
    // In rays (kJoinCost): the eye's walk and its light samples, the light walk and its splats (per
    // walk), the joins of the first walk with the eye's.
    double eyeWork = 0.0, lightWalkWork = 0.0, joinWork = 0.0;

    // A contribution `value` (luminance, before its MIS weight) of strategy s for `path`;
    // `shareSquares`: a splat's filter weights squared, summed over the pixels it lands in.
    void add(PilotTerm term, double value, const PathDensities& path, int s, double shareSquares = 1.0);
    // A contribution no other strategy can make (the background): weight 1 at every fraction.
    void addUnweighted(double value);
    // One join evaluated (its densities and weight), whether or not it contributed.
    void countJoin(PilotTerm term) {
        (term == PilotTerm::Eye ? eyeWork : term == PilotTerm::Join ? joinWork : lightWalkWork) += kJoinCost;
    }
};

// The pilot's samples, a pixel's samples in a row, and what they say about each fraction.
class LightWalkPilot {
public:
    explicit LightWalkPilot(int samplesPerPixel) : samplesPerPixel_(samplesPerPixel) {}
    // The next sample of the current pixel; a pixel's samplesPerPixel samples come in a row.
    void add(const PilotSample& sample);

    struct Estimate {
        double variance = 0.0;  // per camera sample: its own pixel's and its splats', summed
        double work = 0.0;      // per camera sample, in rays
    };
    Estimate estimate(std::size_t fraction) const;
    // The candidate of least variance x work (Veach 1997, 9.2: a technique's efficiency); on a tie
    // the nearest to one light walk per sample (a scene without variance keeps q = 1).
    std::size_t best() const;
    // The render's choice: the fewest light walks whose variance x work exceeds best()'s by less
    // than kChoiceStandardErrors standard errors of the difference (below); best() where none does.
    std::size_t choice() const;
    // The standard error of candidate k's variance x work minus best()'s, from the spread of that
    // difference over the pilot's pixels (the same samples at every candidate: a paired comparison).
    double differenceError(std::size_t k) const;
    std::uint64_t samples() const { return samples_; }

private:
    int samplesPerPixel_;
    std::uint64_t samples_ = 0, pixels_ = 0;
    // The current pixel's sums per fraction: X = eye + join (its own estimate), Y = E[X^2] over the
    // walk's coin (below).
    std::array<double, kLightWalkFractions.size()> sumX_{}, sumX2_{}, sumY_{};
    // Over finished pixels: their variance estimates; over all samples: splats' second moments.
    std::array<double, kLightWalkFractions.size()> pixelVariance_{}, splatMoment_{};
    // Per finished pixel, its share of the variance at each candidate: its own estimate plus its
    // samples' splat moments / n (their mean over the pixels is estimate()'s variance), for
    // differenceError; the current pixel's splat moments.
    std::vector<std::array<double, kLightWalkFractions.size()>> pixelShares_;
    std::array<double, kLightWalkFractions.size()> pixelSplat_{};
    double eyeWork_ = 0.0, lightWalkWork_ = 0.0, joinWork_ = 0.0;
};

}  // namespace lightpath
