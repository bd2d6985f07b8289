#include "light_checks.h"

#include <cmath>
#include <random>
#include <tuple>
#include <vector>

#include "monte_carlo.h"
#include "statistics.h"
#include "uniform_real.h"

namespace lightpath::conformance {
namespace {

constexpr int kSamples = 100000;
constexpr float kGrazingCosine = 1e-3f;

bool finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
bool finiteNonNegative(const Rgb& v) { return finite(v) && v.r >= 0.0f && v.g >= 0.0f && v.b >= 0.0f; }
bool close(float a, float b, float relative) { return std::fabs(a - b) <= relative * std::fabs(b) + 1e-6f; }
bool close(const Rgb& a, const Rgb& b, float relative) {
    return close(a.r, b.r, relative) && close(a.g, b.g, relative) && close(a.b, b.b, relative);
}
double sum(const Rgb& v) { return double(v.r) + v.g + v.b; }

using test::Moments;
using test::momentsOf;

// The hit of a ray from `receiver` along `direction` when it is on `light`.
std::optional<SurfaceHit> hitOnLight(const Light& light, const LightWorld& world, const Vec3& receiver, const Vec3& direction) {
    Ray ray;
    ray.origin = receiver;
    ray.direction = direction;
    const std::optional<SurfaceHit> hit = world.geometry.intersect(ray);
    if (!hit || world.lights.lightOfObject(hit->object) != &light) return std::nullopt;
    return hit;
}

// Whether `samples` estimate `expected`: Student's t-test, or within float rounding of it (1e-4
// relative) for an estimator with (almost) no variance, which the test would judge on its last bits.
bool estimates(const std::vector<double>& samples, double expected, double& p) {
    p = test::studentTTest(samples, expected);
    return p > kLightAlpha || std::fabs(momentsOf(samples).mean - expected) <= 1e-4 * std::fabs(expected);
}

}  // namespace

LightWorld::LightWorld(const Scene& s)
    : scene(s),
      geometry(s.spheres, s.planes, s.triangles, {}, Accelerator::Bvh, s.triangleNormals, 0, s.shapes),
      lights(s, geometry) {}

CheckResult checkLightDensity(const Light& light, const LightWorld& world, const Vec3& receiver) {
    CheckResult result;
    std::mt19937_64 rng(61);
    test::UniformReal<float> uniform(0.0f, 1.0f);
    // pdf() over uniform directions: its integral over the solid angle where the receiver sees
    // the light's emitting side (radiance() towards it; the back of an open emitter, e.g. a
    // cylinder's inside seen through its end, is no part of what sample() draws from).
    std::vector<double> normalisation, seen;
    for (int i = 0; i < kSamples; ++i) {
        const Vec3 w = test::uniformSphereDirection(rng);
        auto hit = hitOnLight(light, world, receiver, w);
        if (hit && isBlack(light.radiance(*hit, -w))) hit.reset();
        normalisation.push_back(hit ? 4.0 * M_PI * light.pdf(receiver, hit->point, hit->normal) : 0.0);
        seen.push_back(hit ? 4.0 * M_PI : 0.0);
    }
    // 1 / pdf over sample()'s points: the solid angle it samples. And the share of its draws the
    // receiver sees (a ray along wi meets the light at that distance), which pdf() integrates to:
    // 1 for a flat or convex light; less for one that turns part of its emitting side away from
    // the receiver (an open cylinder), whose draws there have pdf 0.
    std::vector<double> inverse, reached;
    for (int i = 0; i < kSamples; ++i) {
        const LightSample s = light.sample(receiver, {uniform(rng), uniform(rng)});
        inverse.push_back(s.pdf > 0.0f ? 1.0 / s.pdf : 0.0);
        const auto hit = s.pdf > 0.0f ? hitOnLight(light, world, receiver, s.wi) : std::nullopt;
        reached.push_back(hit && std::fabs(hit->t - s.distance) <= 1e-3f * s.distance ? 1.0 : 0.0);
    }
    const Moments share = momentsOf(reached), integral = momentsOf(normalisation);
    double pNormalised = 0.0;
    const bool normalised = share.mean == 1.0
                                ? estimates(normalisation, 1.0, pNormalised)
                                : (pNormalised = test::welchTTest(integral.mean, integral.variance, integral.count,
                                                                  share.mean, share.variance, share.count)) > kLightAlpha;
    if (!normalised)
        result.fail("from ", receiver.x, " ", receiver.y, " ", receiver.z, ": pdf() integrates to ", integral.mean,
                    " over the light's solid angle, not ", share.mean, ", the share of sample()'s draws seen (p = ",
                    pNormalised, ")");
    const Moments a = momentsOf(inverse), b = momentsOf(seen);
    const double pSolidAngle = test::welchTTest(a.mean, a.variance, a.count, b.mean, b.variance, b.count);
    if (!(pSolidAngle > kLightAlpha))
        result.fail("from ", receiver.x, " ", receiver.y, " ", receiver.z, ": sample()'s 1/pdf averages ", a.mean,
                    " sr, but rays see ", b.mean, " sr of the light (p = ", pSolidAngle, ")");
    return result;
}

CheckResult checkLightSamples(const Light& light, const LightWorld& world, const Vec3& receiver) {
    CheckResult result;
    std::mt19937_64 rng(67);
    test::UniformReal<float> uniform(0.0f, 1.0f);
    for (int i = 0; i < 4000; ++i) {
        const LightSample s = light.sample(receiver, {uniform(rng), uniform(rng)});
        if (!(finiteNonNegative(s.weight) && std::isfinite(s.pdf) && s.pdf >= 0.0f && finite(s.point) &&
              std::isfinite(s.distance))) {
            result.fail("a sample has weight ", s.weight.g, ", pdf ", s.pdf, ", distance ", s.distance);
            continue;
        }
        if (light.isDelta()) {
            if (s.pdf != 0.0f) result.fail("a delta light's sample has pdf ", s.pdf, ", not 0");
        } else if (s.pdf == 0.0f) {
            continue;  // nothing sampled (a receiver behind a one-sided emitter); its weight is unused
        }
        if (std::fabs(glm::length(s.wi) - 1.0f) > 1e-4f || !close(s.distance, glm::length(s.point - receiver), 1e-4f) ||
            glm::length(receiver + s.distance * s.wi - s.point) > 1e-3f * (1.0f + s.distance))
            result.fail("wi and distance do not lead from the receiver to the sampled point");
        if (light.isDelta()) continue;
        const float pdf = light.pdf(receiver, s.point, s.normal);
        if (!close(pdf, s.pdf, 1e-3f)) result.fail("a sample's pdf is ", s.pdf, " but pdf() of its point says ", pdf);
        // A draw on a curved light's silhouette (an open cylinder's) is a line that all but touches
        // it: the exact line passes r cos^2 / 2 inside the wall (5e-7 r at |cos| = 1e-3), less than
        // the float rounding of the point and of wi from a few metres, which may carry it off the
        // wall or onto the far side of its tangent point, where the normal turns from the receiver.
        // Only its pdf is held to; its weight goes as |cos|, nothing.
        if (std::fabs(glm::dot(s.normal, s.wi)) < kGrazingCosine) continue;
        const auto hit = hitOnLight(light, world, receiver, s.wi);
        if (!hit || !close(hit->t, s.distance, 1e-3f)) {
            result.fail("a ray along a sample's wi does not meet the light at its distance ", s.distance);
            continue;
        }
        const Rgb expected = light.radiance(*hit, -s.wi) / s.pdf;
        if (!close(s.weight, expected, 1e-3f))
            result.fail("a sample's weight is ", s.weight.g, " but radiance / pdf is ", expected.g);
    }
    return result;
}

CheckResult checkDeltaLightIntensity(const Light& light) {
    CheckResult result;
    std::mt19937_64 rng(71);
    if (light.atInfinity()) {
        // Parallel rays: the irradiance at any receiver, across the emission disk's area (the
        // inverse of its density), is the flux; every receiver sees the same along the rays.
        const EmittedRay e = light.sampleEmission({0.5f, 0.5f}, {0.5f, 0.5f});
        for (int i = 0; i < 10; ++i) {
            const Vec3 receiver = e.ray.at(1.0f) + 0.1f * test::uniformSphereDirection(rng);
            const LightSample s = light.sample(receiver, {0.5f, 0.5f});
            const double flux = sum(s.weight) / e.pdfDirection;
            if (!close(float(flux), float(sum(light.power())), 1e-3f))
                result.fail("irradiance over the emission disk is ", flux, " W but power() says ", sum(light.power()));
            if (!close(glm::dot(s.wi, -e.ray.direction), 1.0f, 1e-5f))
                result.fail("a light at infinity's sample() comes from ", s.wi.x, ", ", s.wi.y, ", ", s.wi.z,
                            ", not against its rays");
        }
        return result;
    }
    const Vec3 position = light.sample(Vec3{0.0f}, {0.5f, 0.5f}).point;
    constexpr float kDistance = 2.0f;
    std::vector<double> flux;
    for (int i = 0; i < kSamples / 10; ++i) {
        const LightSample s = light.sample(position + kDistance * test::uniformSphereDirection(rng), {0.5f, 0.5f});
        flux.push_back(4.0 * M_PI * sum(s.weight) / light.falloff(kDistance));
    }
    const double expected = sum(light.power());
    double p = 0.0;
    if (!estimates(flux, expected, p))
        result.fail("radiant intensity over the sphere is ", momentsOf(flux).mean, " W but power() says ", expected,
                    " (p = ", p, ")");
    return result;
}

namespace {

// power() against the flux that emitted rays estimate, E[Le |cos| / (pdfPosition pdfDirection)],
// and each ray's densities against `pdfDirection` and pdfEmissionPosition().
template <typename Emit, typename DirectionDensity>
CheckResult checkEmittedFlux(const Light& light, const char* emitter, Emit emit, DirectionDensity pdfDirection) {
    CheckResult result;
    std::mt19937_64 rng(73);
    test::UniformReal<float> uniform(0.0f, 1.0f);
    std::vector<double> flux;
    for (int i = 0; i < kSamples; ++i) {
        const EmittedRay e = emit(Vec2{uniform(rng), uniform(rng)}, Vec2{uniform(rng), uniform(rng)});
        if (!(finiteNonNegative(e.radiance) && std::isfinite(e.pdfPosition) && std::isfinite(e.pdfDirection) &&
              finite(e.ray.origin) && std::fabs(glm::length(e.ray.direction) - 1.0f) < 1e-4f)) {
            result.fail(emitter, ": an emitted ray has radiance ", e.radiance.g, ", densities ", e.pdfPosition, " and ",
                        e.pdfDirection, ", |direction| ", glm::length(e.ray.direction));
            flux.push_back(0.0);
            continue;
        }
        const float expectedDensity = pdfDirection(e);
        if (!close(e.pdfDirection, expectedDensity, 1e-3f))
            result.fail(emitter, ": an emitted ray's direction density is ", e.pdfDirection, " but its density function says ",
                        expectedDensity);
        if (!close(e.pdfPosition, light.pdfEmissionPosition(), 1e-4f))
            result.fail(emitter, ": an emitted ray's position density is ", e.pdfPosition, " but pdfEmissionPosition says ",
                        light.pdfEmissionPosition());
        if (!(e.pdfPosition > 0.0f && e.pdfDirection > 0.0f)) {
            flux.push_back(0.0);
            continue;
        }
        // A point light has no normal: its radiance field is an intensity, no cosine.
        const double cosine = e.normal == Vec3{0.0f} ? 1.0 : std::fabs(glm::dot(e.normal, e.ray.direction));
        flux.push_back(sum(e.radiance) * cosine / (double(e.pdfPosition) * e.pdfDirection));
    }
    const double expected = sum(light.power());
    double p = 0.0;
    if (!(finiteNonNegative(light.power()) && estimates(flux, expected, p)))
        result.fail("power() is ", expected, " W but ", emitter, " estimates ", momentsOf(flux).mean, " W (p = ", p, ")");
    return result;
}

}  // namespace

CheckResult checkLightPower(const Light& light) {
    return checkEmittedFlux(light, "sampleEmission()",
                            [&](Vec2 uPoint, Vec2 uDirection) { return light.sampleEmission(uPoint, uDirection); },
                            [&](const EmittedRay& e) { return light.pdfEmissionDirection(e.normal, e.ray.direction); });
}

CheckResult checkAimedEmission(const Light& light) {
    // Two targets in the light's own field, one near and one a few times its size away, and one
    // behind it (against an emitted ray), so that aimed rays leave where the light sends little.
    const float size = 1.0f / std::sqrt(light.pdfEmissionPosition());
    std::vector<SpecularTarget> targets;
    for (const auto& [u, distance, radius] : {std::tuple{Vec2{0.3f, 0.7f}, 1.5f, 0.4f}, std::tuple{Vec2{0.8f, 0.25f}, 4.0f, 0.5f},
                                               std::tuple{Vec2{0.55f, 0.45f}, -3.0f, 1.0f}}) {
        const EmittedRay e = light.sampleEmission(u, Vec2{u.y, u.x});
        targets.push_back({e.ray.at(distance * size), radius * size});
    }
    const EmissionGuide guide(targets);
    return checkEmittedFlux(light, "EmissionGuide::sample (emitAlong)",
                            [&](Vec2 uPoint, Vec2 uDirection) { return guide.sample(light, uPoint, uDirection); },
                            [&](const EmittedRay& e) { return guide.pdfDirection(light, e.ray.origin, e.normal, e.ray.direction); });
}

std::vector<Vec3> receiversOf(const Light& light) {
    const float size = 1.0f / std::sqrt(light.pdfEmissionPosition());
    std::vector<Vec3> receivers;
    for (const Vec2 u : {Vec2{0.3f, 0.7f}, Vec2{0.8f, 0.2f}, Vec2{0.55f, 0.45f}}) {
        const EmittedRay e = light.sampleEmission(u, Vec2{u.y, u.x});
        for (const float distance : {0.1f, 2.0f}) receivers.push_back(e.ray.at(distance * size));
    }
    return receivers;
}

CheckResult checkLightCase(const LightCase& c) {
    const LightWorld world(c.scene);
    CheckResult result;
    if (world.lights.all().empty()) result.fail("the case's scene has no light");
    for (const auto& light : world.lights.all()) {
        result.merge(checkLightPower(*light));
        result.merge(checkAimedEmission(*light));
        if (light->isDelta()) result.merge(checkDeltaLightIntensity(*light));
        for (const Vec3& receiver : receiversOf(*light)) {
            result.merge(checkLightSamples(*light, world, receiver));
            if (!light->isDelta()) result.merge(checkLightDensity(*light, world, receiver));
        }
    }
    return result;
}

}  // namespace lightpath::conformance
