#include "materials/bsdf.h"

#include "util/hot_path.h"

namespace lightpath {

LIGHTPATH_HOT_PATH
const std::array<float, kMaxLobes>& Bsdf::lobeProbabilities(const Vec3& wo) const {
    if (wo == first_.wo) return first_.probabilities;
    if (wo == last_.wo) return last_.probabilities;
    if (first_.wo != Vec3{0.0f}) {
        if (woDependence_ == WoDependence::Unknown)
            woDependence_ = material_.lobeAlbedosIgnoreWo(side_) ? WoDependence::Ignored : WoDependence::Used;
        if (woDependence_ == WoDependence::Ignored) return first_.probabilities;
    }
    LobeChoice& choice = first_.wo == Vec3{0.0f} ? first_ : last_;
    choice.wo = wo;
    computeLobeProbabilities(choice);
    return choice.probabilities;
}

LIGHTPATH_HOT_PATH
void Bsdf::computeLobeProbabilities(LobeChoice& choice) const {
    std::array<float, kMaxLobes>& weights = choice.probabilities;
    weights.fill(0.0f);
    bool anyDelta = false;
    for (int l = 0; l < int(lobes_.size()); ++l) {
        if (!has(l)) continue;
        if (lobes_[l].delta()) anyDelta = true;
        else weights[l] = material_.albedo(l, side_, choice.wo);
    }
    // Without a delta lobe present a material has no specular branch (Material::specularBranches):
    // a diffuse or glossy hit does not ask.
    if (anyDelta) {
        SpecularBranches branches;
        const int count = material_.specularBranches(side_, choice.wo, branches);
        for (int b = 0; b < count; ++b) weights[branches[b].lobe] = branches[b].albedo;
    }
    float total = 0.0f;
    for (float w : weights) total += w;
    if (total > 0.0f)
        for (float& w : weights) w /= total;
}

LIGHTPATH_HOT_PATH
float Bsdf::pdf(int lobe, const Vec3& wo, const Vec3& wi) const {
    if (this->lobe(lobe).delta()) return 0.0f;
    if (material_.choosesLobe()) return material_.chosenLobePdf(lobe, side_, wo, wi);
    const float probability = lobeProbabilities(wo)[lobe];
    return probability == 0.0f ? 0.0f : probability * material_.pdf(lobe, side_, wo, wi);
}

LIGHTPATH_HOT_PATH
std::optional<BsdfSample> Bsdf::sample(const Vec3& wo, float uLobe, Vec2 u) const {
    if (material_.choosesLobe()) {
        const std::optional<ChosenLobeSample> s = material_.sampleChosenLobe(side_, wo, uLobe, u);
        if (!s) return std::nullopt;
        return BsdfSample{s->sample.wi, s->sample.weight, s->sample.pdf, s->lobe};
    }
    const auto& probabilities = lobeProbabilities(wo);
    // Over every slot, not only the material's lobes: a uLobe past the rounded total lands on an
    // empty slot and scatters nothing, as it always has.
    int chosen = 0;
    float cumulative = probabilities[0];
    while (chosen < kMaxLobes - 1 && uLobe >= cumulative) cumulative += probabilities[++chosen];
    const float probability = probabilities[chosen];
    if (probability == 0.0f) return std::nullopt;

    if (lobe(chosen).delta()) {
        SpecularBranches branches;
        const int count = material_.specularBranches(side_, wo, branches);
        for (int b = 0; b < count; ++b)
            if (branches[b].lobe == chosen)
                return BsdfSample{branches[b].wi, branches[b].weight / probability, 0.0f, chosen};
        return std::nullopt;
    }
    const std::optional<LobeSample> s = material_.sample(chosen, side_, wo, u);
    if (!s) return std::nullopt;
    return BsdfSample{s->wi, s->weight / probability, s->pdf * probability, chosen};
}

}  // namespace lightpath
