#include "integrators/bdpt_allocation.h"

#include <algorithm>
#include <cmath>

namespace lightpath {

void PilotSample::add(PilotTerm term, double value, const PathDensities& path, int s, double shareSquares) {
    for (std::size_t k = 0; k < kLightWalkFractions.size(); ++k) {
        const double weighted = value * misWeight(path, s, kLightWalkFractions[k]);
        switch (term) {
            case PilotTerm::Eye: eye[k] += weighted; break;
            case PilotTerm::Join: join[k] += weighted; break;
            case PilotTerm::Splat: splatSquares[k] += weighted * weighted * shareSquares; break;
        }
    }
}

void PilotSample::addUnweighted(double value) {
    for (double& e : eye) e += value;
}

void LightWalkPilot::add(const PilotSample& sample) {
    // A camera sample's own pixel gets X = eye + B join / p, B = 1 when it has a first light walk
    // (probability p = min(q, 1)): E_B[X] = eye + join whatever q, E_B[X^2] = eye^2 + 2 eye join +
    // join^2 / p. Its splats, each on a pixel it reaches with a small probability, add their second
    // moment to the image's variance (their means squared are a pixel's share of the image's pixels
    // smaller): N walks, E[N] = q, each splatting S / q, give E[N] S^2 / q^2 = S^2 / q.
    for (std::size_t k = 0; k < kLightWalkFractions.size(); ++k) {
        const double q = kLightWalkFractions[k], p = std::min(q, 1.0);
        const double x = sample.eye[k] + sample.join[k];
        sumX_[k] += x;
        sumX2_[k] += x * x;
        sumY_[k] += sample.eye[k] * sample.eye[k] + 2.0 * sample.eye[k] * sample.join[k] + sample.join[k] * sample.join[k] / p;
        splatMoment_[k] += sample.splatSquares[k] / q;
        pixelSplat_[k] += sample.splatSquares[k] / q;
    }
    eyeWork_ += sample.eyeWork;
    lightWalkWork_ += sample.lightWalkWork;
    joinWork_ += sample.joinWork;
    ++samples_;
    if (samples_ % static_cast<std::uint64_t>(samplesPerPixel_) != 0) return;
    // The pixel's variance per sample, E[Y] - E[X]^2, with E[X]^2 estimated without bias from
    // its n samples: ((sum X)^2 - sum X^2) / (n (n - 1)).
    const double n = samplesPerPixel_;
    std::array<double, kLightWalkFractions.size()> share{};
    for (std::size_t k = 0; k < kLightWalkFractions.size(); ++k) {
        const double variance = sumY_[k] / n - (sumX_[k] * sumX_[k] - sumX2_[k]) / (n * (n - 1.0));
        pixelVariance_[k] += variance;
        share[k] = variance + pixelSplat_[k] / n;
        sumX_[k] = sumX2_[k] = sumY_[k] = pixelSplat_[k] = 0.0;
    }
    pixelShares_.push_back(share);
    ++pixels_;
}

LightWalkPilot::Estimate LightWalkPilot::estimate(std::size_t fraction) const {
    if (pixels_ == 0) return {};
    const double samples = static_cast<double>(pixels_) * samplesPerPixel_;
    const double q = kLightWalkFractions[fraction];
    return {pixelVariance_[fraction] / static_cast<double>(pixels_) + splatMoment_[fraction] / samples,
            (eyeWork_ + q * lightWalkWork_ + std::min(q, 1.0) * joinWork_) / samples};
}

std::size_t LightWalkPilot::best() const {
    std::size_t best = 0;
    double bestCost = 0.0;
    for (std::size_t k = 0; k < kLightWalkFractions.size(); ++k) {
        const Estimate e = estimate(k);
        const double cost = e.variance * e.work;
        const bool nearerOne = std::fabs(std::log(kLightWalkFractions[k])) < std::fabs(std::log(kLightWalkFractions[best]));
        if (k == 0 || cost < bestCost || (cost == bestCost && nearerOne)) best = k, bestCost = cost;
    }
    return best;
}

double LightWalkPilot::differenceError(std::size_t k) const {
    const std::size_t b = best();
    const double pixels = static_cast<double>(pixelShares_.size());
    if (pixels < 2.0) return 0.0;
    // Per pixel d = W_k v_k - W_b v_b, its variance shares weighed by each candidate's work per
    // sample (the work, summed over every sample, is known far better than the variance).
    const double wk = estimate(k).work, wb = estimate(b).work;
    double sum = 0.0, sum2 = 0.0;
    for (const auto& share : pixelShares_) {
        const double d = wk * share[k] - wb * share[b];
        sum += d;
        sum2 += d * d;
    }
    const double variance = std::max(0.0, (sum2 - sum * sum / pixels) / (pixels - 1.0));
    return std::sqrt(variance / pixels);
}

std::size_t LightWalkPilot::choice() const {
    const std::size_t b = best();
    const Estimate least = estimate(b);
    // Candidates are ordered by fewer walks last, and work falls with q: the last within reach.
    // Strictly within: where the difference has no spread (a scene without variance: every cost 0)
    // best()'s choice stands.
    for (std::size_t k = kLightWalkFractions.size(); k-- > b + 1;) {
        const Estimate e = estimate(k);
        if (e.variance * e.work - least.variance * least.work < kChoiceStandardErrors * differenceError(k)) return k;
    }
    return b;
}

}  // namespace lightpath
