#include "integrators/bdpt_vertex.h"

#include <algorithm>
#include <cmath>

#include "integrators/integrator.h"

namespace lightpath {

ScatterStep prescribedStep(const ShadingPoint& vertex, int lobe, const Vec3& wi) {
    ScatterStep step;
    step.wi = wi;
    step.lobe = lobe;
    step.delta = vertex.bsdf.lobe(lobe).delta();
    if (step.delta) {
        step.pdf = 1.0f;
        return step;
    }
    step.pdf = vertex.bsdf.pdf(lobe, vertex.wo, wi);
    if (step.pdf > 0.0f) step.weight = vertex.bsdf.eval(lobe, vertex.wo, wi) / step.pdf;
    return step;
}

std::optional<ScatterStep> sampledStep(const ShadingPoint& vertex, float uLobe, Vec2 u) {
    const auto sample = vertex.bsdf.sample(vertex.wo, uLobe, u);
    if (!sample) return std::nullopt;
    ScatterStep step;
    step.wi = sample->wi;
    step.lobe = sample->lobe;
    step.weight = sample->weight;
    step.delta = vertex.bsdf.lobe(sample->lobe).delta();
    // A delta lobe's Dirac is common to every strategy that can make the path (those that do not
    // join at this vertex), so its densities count as 1 (pbrt-v4's remap0 of the same).
    step.pdf = step.delta ? 1.0f : sample->pdf;
    return step;
}

BdptVertex cameraVertex(const Vec3& origin, bool directionDelta) {
    BdptVertex v;
    v.kind = VertexKind::Camera;
    v.point = origin;
    v.beta = Rgb{1.0f};
    // A pinhole: every strategy shares the eye's position. An orthographic camera's ray leaves
    // along one direction, a Dirac no join can meet (and its first step's density counts as 1).
    v.pdfFwd = 1.0f;
    v.delta = directionDelta;
    return v;
}

BdptVertex lightVertex(const Light& light, const Vec3& point, const Vec3& normal, float pdfPosition, float pdfEmission) {
    BdptVertex v;
    v.kind = VertexKind::Light;
    v.point = point;
    v.normal = normal;
    v.light = &light;
    v.delta = light.isDelta();
    v.pdfPosition = pdfPosition;
    v.pdfEmission = pdfEmission;
    return v;
}

float lightSamplingAreaDensity(const Light& light, const Vec3& receiver, const Vec3& point, const Vec3& normal) {
    // Light::pdf is light sampling's solid-angle density; times cos / d^2 it is per unit area.
    const Vec3 back = receiver - point;
    const float distance2 = glm::dot(back, back);
    return distance2 > 0.0f ? light.pdf(receiver, point, normal) * std::fabs(glm::dot(normal, back)) /
                                  (std::sqrt(distance2) * distance2)
                            : 0.0f;
}

void setSurfaceVertex(BdptVertex& v, const SurfaceHit& hit, const Ray& ray, const Rgb& beta, const BdptVertex& previous,
                      float pdfSolidAngle, bool delta, const RenderContext& context, TransportMode mode) {
    v = BdptVertex{};  // every other field as a new vertex has it (no shading point to copy)
    v.kind = VertexKind::Surface;
    v.point = hit.point;
    v.normal = hit.normal;
    v.beta = beta;
    v.surface.emplace(makeShadingPoint(hit, ray, context, mode));
    const Bsdf& bsdf = v.surface->bsdf;
    for (int l = 0; l < int(bsdf.lobes().size()); ++l)
        if (!bsdf.lobe(l).delta() && bsdf.has(l)) v.smoothLobes |= 1u << l;
    v.pdfFwd = delta ? 1.0f : toAreaDensity(pdfSolidAngle, previous, v);
}

void markEmitter(BdptVertex& z, const Light& emitter, const BdptVertex& previous) {
    z.light = &emitter;
    z.pdfPosition = lightSamplingAreaDensity(emitter, previous.point, z.point, z.normal);
    // Where light sampling picks points by area, emission's density is the same number.
    z.pdfEmission = emitter.samplesByArea(previous.point) ? z.pdfPosition : emitter.pdfEmissionPosition();
}

namespace {

Vec3 directionTo(const BdptVertex& from, const BdptVertex& to) { return glm::normalize(to.point - from.point); }

}  // namespace

void linkThrough(BdptVertex& before, const BdptVertex& at, BdptVertex& here) {
    if (at.delta) {
        here.pdfFwd = before.pdfRev = 1.0f;  // the Dirac's, as sampledStep counts it
        return;
    }
    const Bsdf& bsdf = at.surface->bsdf;
    const Vec3 back = directionTo(at, before), ahead = directionTo(at, here);
    here.pdfFwd = toAreaDensity(bsdf.pdf(at.lobe, back, ahead), at, here);
    before.pdfRev = toAreaDensity(bsdf.pdf(at.lobe, ahead, back), at, before);
}

PathDensities joinedDensities(std::span<const BdptVertex> light, int lightLobe, std::span<const BdptVertex> eye,
                              int eyeLobe, const RenderContext& context) {
    PathDensities p;
    const int s = static_cast<int>(light.size()), t = static_cast<int>(eye.size());
    p.n = s + t;
    p.cameraJoinable = context.camera.connectible();
    for (int i = 0; i < s; ++i) {
        p.fromLight[i] = light[i].pdfFwd;
        p.fromEye[i] = light[i].pdfRev;
        p.connectible[i] = !light[i].delta || light[i].kind == VertexKind::Light;
    }
    for (int j = 0; j < t; ++j) {
        const int i = p.n - 1 - j;
        p.fromEye[i] = eye[j].pdfFwd;
        p.fromLight[i] = eye[j].pdfRev;
        p.connectible[i] = !eye[j].delta;
    }

    if (s >= 1 && t >= 1) {
        // The joined ends, each as the other side's walk would have sampled it.
        const BdptVertex& y = light[s - 1];
        const BdptVertex& z = eye[t - 1];
        const Vec3 yz = directionTo(y, z);
        p.connectible[s - 1] = p.connectible[s] = true;
        if (s == 1) {
            p.fromLight[s] = toAreaDensity(context.lights.emissionGuide().pdfDirection(*y.light, y.point, y.normal, yz), y, z);
        } else {
            // Directions between the points, as linkThrough takes them (not the traced rays').
            const Vec3 back = directionTo(y, light[s - 2]);
            p.fromLight[s] = toAreaDensity(y.surface->bsdf.pdf(lightLobe, back, yz), y, z);
            p.fromEye[s - 2] = toAreaDensity(y.surface->bsdf.pdf(lightLobe, yz, back), y, light[s - 2]);
        }
        if (t == 1) {
            p.fromEye[s - 1] = toAreaDensity(context.camera.pdfDirection(-yz), z, y);
        } else {
            const Vec3 back = directionTo(z, eye[t - 2]);
            p.fromEye[s - 1] = toAreaDensity(z.surface->bsdf.pdf(eyeLobe, back, -yz), z, y);
            p.fromLight[s + 1] = toAreaDensity(z.surface->bsdf.pdf(eyeLobe, -yz, back), z, eye[t - 2]);
        }
    } else if (s == 0 && t >= 2) {
        // An eye walk that hit a light: the light's first step as a light walk would take it.
        const BdptVertex& x0 = eye[t - 1];
        const Vec3 leaving = directionTo(x0, eye[t - 2]);
        p.fromLight[1] = toAreaDensity(context.lights.emissionGuide().pdfDirection(*x0.light, x0.point, x0.normal, leaving),
                                       x0, eye[t - 2]);
    }

    const BdptVertex& origin = s >= 1 ? light[0] : eye[t - 1];
    if (origin.light != nullptr) {
        p.originByNextEvent = double(context.lights.nextEventProbability(*origin.light)) * origin.pdfPosition;
        p.originByEmission = double(context.lights.emitterProbability(*origin.light)) * origin.pdfEmission;
        p.originHittable = !origin.light->isDelta();
    }
    return p;
}

namespace {

bool available(const PathDensities& p, int s, double lightWalks) {
    const int t = p.n - s;
    if (t < 1) return false;  // a pinhole cannot be hit by chance
    if (s == 0) return p.originHittable;
    if (s >= 2 && !(lightWalks > 0.0)) return false;
    // The light seen straight by the camera (s = 1, t = 1) is left to the eye's walk (s = 0).
    if (t == 1) return p.cameraJoinable && s >= 2 && p.connectible[s - 1];
    return p.connectible[s - 1] && p.connectible[s];
}

// The factor x0's choice contributes to strategy s's density, times its samples per camera sample:
// light tracing (t = 1) takes every light walk, a join (s, t >= 2) the first walk only, which a
// camera sample has with probability min(lightWalks, 1) (bdpt_allocation.h says why).
double originFactor(const PathDensities& p, int s, double lightWalks) {
    if (s == 0) return 1.0;
    if (s == 1) return p.originByNextEvent;
    return p.originByEmission * (s == p.n - 1 ? lightWalks : std::min(lightWalks, 1.0));
}

}  // namespace

float misWeight(const PathDensities& p, int s, double lightWalks) {
    if (!available(p, s, lightWalks)) return 0.0f;
    // Without light walks their strategies are out (available), but the ratios still pass through them.
    const double count = lightWalks > 0.0 ? lightWalks : 1.0;
    // p_k / p_(k-1) = O(k) / O(k-1) * fromLight[k-1] (but for x0, in O) / fromEye[k-1]: vertex k-1
    // moves from the eye's walk to the light's (Veach 1997, eq. 10.9).
    auto numerator = [&](int k) { return originFactor(p, k, count) * (k - 1 >= 1 ? p.fromLight[k - 1] : 1.0); };
    auto denominator = [&](int k) { return originFactor(p, k - 1, count) * p.fromEye[k - 1]; };
    double sum = 1.0;
    double r = 1.0;
    for (int k = s + 1; k < p.n; ++k) {
        const double den = denominator(k);
        if (!(den > 0.0)) return 0.0f;  // a factor of p_s: strategy s could not have made this path
        r *= numerator(k) / den;
        if (available(p, k, lightWalks)) sum += r * r;
    }
    r = 1.0;
    for (int k = s - 1; k >= 0; --k) {
        const double num = numerator(k + 1);
        if (!(num > 0.0)) return 0.0f;
        r *= denominator(k + 1) / num;
        if (available(p, k, lightWalks)) sum += r * r;
    }
    return std::isfinite(sum) ? static_cast<float>(1.0 / sum) : 0.0f;
}

}  // namespace lightpath
