#include "materials/bsdf.h"

namespace lightpath {

const std::array<float, kLobeCount>& Bsdf::lobeProbabilities(const Vec3& wo) const {
    if (wo == probabilitiesWo_) return probabilities_;  // a zero wo never reaches here twice: it is not unit
    probabilitiesWo_ = wo;
    std::array<float, kLobeCount>& weights = probabilities_;
    weights = {0.0f, 0.0f, 0.0f, 0.0f};
    for (Lobe lobe : kSmoothLobes)
        if (material_.has(lobe)) weights[static_cast<int>(lobe)] = material_.albedo(lobe, side_, wo);
    SpecularBranches branches;
    const int count = material_.specularBranches(side_, wo, branches);
    for (int b = 0; b < count; ++b) weights[static_cast<int>(branches[b].lobe)] = branches[b].albedo;
    float total = 0.0f;
    for (float w : weights) total += w;
    if (total > 0.0f)
        for (float& w : weights) w /= total;
    return weights;
}

float Bsdf::pdf(Lobe lobe, const Vec3& wo, const Vec3& wi) const {
    if (isDelta(lobe)) return 0.0f;
    const float probability = lobeProbabilities(wo)[static_cast<int>(lobe)];
    return probability == 0.0f ? 0.0f : probability * material_.pdf(lobe, side_, wo, wi);
}

std::optional<BsdfSample> Bsdf::sample(const Vec3& wo, float uLobe, Vec2 u) const {
    const auto& probabilities = lobeProbabilities(wo);
    int chosen = 0;
    float cumulative = probabilities[0];
    while (chosen < kLobeCount - 1 && uLobe >= cumulative) cumulative += probabilities[++chosen];
    const float probability = probabilities[chosen];
    if (probability == 0.0f) return std::nullopt;

    const Lobe lobe = static_cast<Lobe>(chosen);
    if (isDelta(lobe)) {
        SpecularBranches branches;
        const int count = material_.specularBranches(side_, wo, branches);
        for (int b = 0; b < count; ++b)
            if (branches[b].lobe == lobe) return BsdfSample{branches[b].wi, branches[b].weight / probability, 0.0f, lobe};
        return std::nullopt;
    }
    const std::optional<LobeSample> s = material_.sample(lobe, side_, wo, u);
    if (!s) return std::nullopt;
    return BsdfSample{s->wi, s->weight / probability, s->pdf * probability, lobe};
}

}  // namespace lightpath
