#include "materials/bsdf.h"

#include <algorithm>
#include <cmath>

#include "materials/optics.h"
#include "sampling/warp.h"

namespace lightpath {
namespace {

// The halfway vector's cosine with the normal, raised to n: Blinn's form of Phong's highlight.
float blinnTerm(const Vec3& n, const Vec3& wo, const Vec3& wi, float exponent, Vec3& halfway) {
    halfway = wo + wi;
    const float length = glm::length(halfway);
    if (length == 0.0f) return 0.0f;
    halfway /= length;
    return std::pow(std::max(0.0f, glm::dot(n, halfway)), exponent);
}

// A rough albedo of the highlight lobe, only to choose lobes in proportion to what they reflect:
// ks (H.N)^n / pi integrates to 2 ks for n = 0 and to about 8 ks / (n + 1) for a sharp lobe.
float highlightAlbedo(float exponent) { return std::min(2.0f, 8.0f / (exponent + 1.0f)); }

}  // namespace

Bsdf::Bsdf(const PhongMaterial& material, const Vec3& normal, bool entering, TransportMode mode)
    : material_(material), normal_(normal), eta_(entering ? 1.0f / material.ior : material.ior), mode_(mode) {}

bool Bsdf::has(Lobe lobe) const {
    switch (lobe) {
        case Lobe::Diffuse: return !isBlack(material_.kd);
        case Lobe::Highlight: return !isBlack(material_.ks);
        case Lobe::Mirror: return !isBlack(material_.kr) || !isBlack(material_.kt);  // kt: total internal reflection
        case Lobe::Refraction: return !isBlack(material_.kt);
    }
    return false;
}

Rgb Bsdf::eval(Lobe lobe, const Vec3& wo, const Vec3& wi) const {
    const float cosIn = glm::dot(wi, normal_);
    if (cosIn <= 0.0f || glm::dot(wo, normal_) <= 0.0f) return Rgb{0.0f};
    if (lobe == Lobe::Diffuse) return material_.kd * (cosIn / kPi);
    if (lobe == Lobe::Highlight) {
        Vec3 halfway;
        return material_.ks * (blinnTerm(normal_, wo, wi, material_.n, halfway) / kPi);
    }
    return Rgb{0.0f};  // a delta lobe has no value to evaluate
}

float Bsdf::pdf(Lobe lobe, const Vec3& wo, const Vec3& wi) const {
    if (glm::dot(wi, normal_) <= 0.0f || glm::dot(wo, normal_) <= 0.0f) return 0.0f;
    const float probability = lobeProbabilities(wo)[static_cast<int>(lobe)];
    if (probability == 0.0f) return 0.0f;
    if (lobe == Lobe::Diffuse) return probability * cosineHemispherePdf(glm::dot(wi, normal_));
    if (lobe == Lobe::Highlight) {
        Vec3 halfway;
        blinnTerm(normal_, wo, wi, 0.0f, halfway);
        const float cosHalf = glm::dot(halfway, normal_), woDotHalf = glm::dot(wo, halfway);
        if (cosHalf <= 0.0f || woDotHalf <= 0.0f) return 0.0f;
        // The half vector's density, (n+1)/(2 pi) cos^n, times the Jacobian dH/dwi = 1/(4 wo.H).
        return probability * phongLobePdf(cosHalf, material_.n) / (4.0f * woDotHalf);
    }
    return 0.0f;
}

std::array<float, kLobeCount> Bsdf::lobeProbabilities(const Vec3& wo) const {
    std::array<SpecularBranch, 2> branches;
    const int count = specularBranches(wo, branches);
    std::array<float, kLobeCount> weights{maxComponent(material_.kd),
                                          maxComponent(material_.ks) * highlightAlbedo(material_.n), 0.0f, 0.0f};
    for (int b = 0; b < count; ++b) weights[static_cast<int>(branches[b].lobe)] = branches[b].albedo;
    float total = 0.0f;
    for (float w : weights) total += w;
    if (total > 0.0f)
        for (float& w : weights) w /= total;
    return weights;
}

int Bsdf::specularBranches(const Vec3& wo, std::array<SpecularBranch, 2>& branches) const {
    if (isBlack(material_.kr) && isBlack(material_.kt)) return 0;
    const float cosOut = glm::dot(wo, normal_);
    if (cosOut <= 0.0f) return 0;
    const Vec3 mirror = reflectAbout(wo, normal_);
    const std::optional<Vec3> refracted = isBlack(material_.kt) ? std::nullopt : refractThrough(wo, normal_, eta_);
    if (!refracted) {
        // Total internal reflection: the transmitted share is reflected too.
        const Rgb weight = material_.kr + material_.kt;
        branches[0] = {mirror, weight, Lobe::Mirror, maxComponent(weight)};
        return isBlack(weight) ? 0 : 1;
    }
    Rgb reflected = material_.kr, transmitted = material_.kt;
    float compression = 1.0f;
    if (material_.fresnel) {
        const float reflectance = fresnelDielectric(cosOut, eta_);
        reflected += material_.kt * reflectance;
        transmitted *= 1.0f - reflectance;
        // Radiance is compressed by (n_i / n_t)^2 as it crosses (pbrt-v4 9.5.2); importance is not.
        if (mode_ == TransportMode::Radiance) compression = eta_ * eta_;
    }
    int count = 0;
    if (!isBlack(reflected)) branches[count++] = {mirror, reflected, Lobe::Mirror, maxComponent(reflected)};
    branches[count++] = {*refracted, transmitted * compression, Lobe::Refraction, maxComponent(transmitted)};
    return count;
}

std::optional<BsdfSample> Bsdf::sample(const Vec3& wo, float uLobe, Vec2 u) const {
    const auto probabilities = lobeProbabilities(wo);
    int chosen = 0;
    float cumulative = probabilities[0];
    while (chosen < kLobeCount - 1 && uLobe >= cumulative) cumulative += probabilities[++chosen];
    const float probability = probabilities[chosen];
    if (probability == 0.0f) return std::nullopt;

    BsdfSample s;
    s.lobe = static_cast<Lobe>(chosen);
    switch (s.lobe) {
        case Lobe::Diffuse: {
            s.wi = Frame(normal_).toWorld(sampleCosineHemisphere(u));
            if (glm::dot(s.wi, normal_) <= 0.0f) return std::nullopt;
            s.pdf = probability * cosineHemispherePdf(glm::dot(s.wi, normal_));
            s.weight = material_.kd / probability;  // (kd/pi) cos / (p cos/pi)
            return s;
        }
        case Lobe::Highlight: {
            const Vec3 halfway = Frame(normal_).toWorld(samplePhongLobe(u, material_.n));
            const float woDotHalf = glm::dot(wo, halfway);
            if (woDotHalf <= 0.0f) return std::nullopt;
            s.wi = reflectAbout(wo, halfway);
            if (glm::dot(s.wi, normal_) <= 0.0f) return std::nullopt;
            // (ks (H.N)^n / pi) / ((n+1)/(2 pi) (H.N)^n / (4 wo.H)): the lobe's power cancels.
            s.pdf = pdf(Lobe::Highlight, wo, s.wi);
            s.weight = material_.ks * (8.0f * woDotHalf / ((material_.n + 1.0f) * probability));
            return s;
        }
        case Lobe::Mirror:
        case Lobe::Refraction: {
            std::array<SpecularBranch, 2> branches;
            const int count = specularBranches(wo, branches);
            for (int b = 0; b < count; ++b) {
                if (branches[b].lobe != s.lobe) continue;
                s.wi = branches[b].wi;
                s.weight = branches[b].weight / probability;
                return s;
            }
            return std::nullopt;
        }
    }
    return std::nullopt;
}

}  // namespace lightpath
