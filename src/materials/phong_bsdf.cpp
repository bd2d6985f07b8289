#include "materials/phong_bsdf.h"

#include <cmath>

#include "sampling/warp.h"

namespace lightpath {
namespace {

Vec3 reflect(const Vec3& wo, const Vec3& n) { return 2.0f * glm::dot(wo, n) * n - wo; }

}  // namespace

float fresnelDielectric(float cosIncident, float eta) {
    const float sin2Transmitted = eta * eta * (1.0f - cosIncident * cosIncident);
    if (sin2Transmitted >= 1.0f) return 1.0f;
    const float cosTransmitted = std::sqrt(1.0f - sin2Transmitted);
    // Fresnel's equations with relative index eta (n_i / n_t).
    const float parallel = (cosIncident - eta * cosTransmitted) / (cosIncident + eta * cosTransmitted);
    const float perpendicular = (eta * cosIncident - cosTransmitted) / (eta * cosIncident + cosTransmitted);
    return 0.5f * (parallel * parallel + perpendicular * perpendicular);
}

PhongBsdf::PhongBsdf(const PhongMaterial& material, const Vec3& normal, bool entering)
    : material_(material), normal_(normal), eta_(entering ? 1.0f / material.ior : material.ior) {
    const float weights[kLobeCount] = {maxComponent(material.kd), maxComponent(material.ks),
                                       maxComponent(material.kr), maxComponent(material.kt)};
    const float total = weights[0] + weights[1] + weights[2] + weights[3];
    if (total > 0.0f)
        for (int i = 0; i < kLobeCount; ++i) lobeProbability_[i] = weights[i] / total;
}

Rgb PhongBsdf::evaluate(Lobe lobe, const Vec3& wo, const Vec3& wi) const {
    if (glm::dot(wi, normal_) <= 0.0f || glm::dot(wo, normal_) <= 0.0f) return Rgb{0.0f};
    if (lobe == Lobe::Diffuse) return material_.kd / kPi;
    if (lobe == Lobe::Glossy) {
        const float cosAlpha = glm::dot(wi, reflect(wo, normal_));
        if (cosAlpha <= 0.0f) return Rgb{0.0f};
        const float n = material_.n;
        return material_.ks * ((n + 2.0f) / (2.0f * kPi) * std::pow(cosAlpha, n));
    }
    return Rgb{0.0f};  // delta lobes have no density to evaluate
}

float PhongBsdf::pdf(Lobe lobe, const Vec3& wo, const Vec3& wi) const {
    const float cosTheta = glm::dot(wi, normal_);
    if (cosTheta <= 0.0f) return 0.0f;
    if (lobe == Lobe::Diffuse) return lobeProbability(Lobe::Diffuse) * cosineHemispherePdf(cosTheta);
    if (lobe == Lobe::Glossy)
        return lobeProbability(Lobe::Glossy) * phongLobePdf(glm::dot(wi, reflect(wo, normal_)), material_.n);
    return 0.0f;
}

std::optional<BsdfSample> PhongBsdf::sample(const Vec3& wo, float uLobe, Vec2 u) const {
    int chosen = 0;
    float cumulative = lobeProbability_[0];
    while (chosen < kLobeCount - 1 && uLobe >= cumulative) cumulative += lobeProbability_[++chosen];
    const float probability = lobeProbability_[chosen];
    if (probability == 0.0f) return std::nullopt;

    BsdfSample s;
    s.lobe = static_cast<Lobe>(chosen);
    const float cosOut = glm::dot(wo, normal_);
    switch (s.lobe) {
        case Lobe::Diffuse: {
            s.direction = Frame(normal_).toWorld(sampleCosineHemisphere(u));
            const float cosTheta = glm::dot(s.direction, normal_);
            if (cosTheta <= 0.0f) return std::nullopt;
            s.pdf = pdf(Lobe::Diffuse, wo, s.direction);
            s.weight = material_.kd / probability;  // (kd/pi) cos / (p cos/pi)
            return s;
        }
        case Lobe::Glossy: {
            const Vec3 mirror = reflect(wo, normal_);
            s.direction = Frame(mirror).toWorld(samplePhongLobe(u, material_.n));
            const float cosTheta = glm::dot(s.direction, normal_);
            if (cosTheta <= 0.0f) return std::nullopt;
            s.pdf = pdf(Lobe::Glossy, wo, s.direction);
            s.weight = material_.ks * ((material_.n + 2.0f) / (material_.n + 1.0f) * cosTheta / probability);
            return s;
        }
        case Lobe::Mirror:
            s.direction = reflect(wo, normal_);
            s.weight = material_.kr / probability;
            return s;
        case Lobe::Dielectric: {
            // Reflect with probability F, refract otherwise: the Fresnel factors cancel against
            // the choice. Refracted radiance is compressed by 1/eta'^2 (pbrt-v4 9.5.2).
            const float reflectance = fresnelDielectric(cosOut, eta_);
            const float uSplit = (uLobe - (cumulative - probability)) / probability;
            if (uSplit < reflectance) {
                s.direction = reflect(wo, normal_);
                s.weight = material_.kt / probability;
                return s;
            }
            const float sin2Transmitted = eta_ * eta_ * (1.0f - cosOut * cosOut);
            const float cosTransmitted = std::sqrt(std::max(0.0f, 1.0f - sin2Transmitted));
            s.direction = glm::normalize(-eta_ * wo + (eta_ * cosOut - cosTransmitted) * normal_);
            s.transmitted = true;
            s.weight = material_.kt * (eta_ * eta_) / probability;
            return s;
        }
    }
    return std::nullopt;
}

}  // namespace lightpath
