#include "stress/emitter_rows.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <numbers>
#include <string>

#include "lights/area_light.h"
#include "sampling/warp.h"
#include "stress/sampling.h"

namespace lightpath {
namespace {

constexpr float kRadiance = 1.0f;
constexpr double kTargetPercent = 0.1;

// One receiver: a point and the unit normal it faces with.
struct Receiver {
    Vec3 point, normal;
};

// An estimate of irradiance from one light sample u.
using Estimator = std::function<double(Vec2 u)>;

// Jittered n x n strata: both methods see the same well-spread samples, so the error left is the
// estimator's, not the pattern's. A non-finite sample makes the estimate non-finite.
double estimate(const Estimator& f, int n, std::uint64_t seed) {
    stress::Rng rng(seed);
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
            const Vec2 u{static_cast<float>(std::min((i + stress::uniform(rng)) / n, 0.99999994)),
                         static_cast<float>(std::min((j + stress::uniform(rng)) / n, 0.99999994))};
            sum += f(u);
        }
    }
    return sum / (double(n) * n);
}

// The former area-light density in float: d^2 / (A |cos|), which overflows for tiny lights.
float naiveSolidAngleDensity(float area, const Vec3& receiver, const Vec3& point, const Vec3& normal) {
    const Vec3 toPoint = point - receiver;
    const float distance2 = glm::dot(toPoint, toPoint);
    const float cosEmitter = std::fabs(glm::dot(normal, toPoint)) / std::sqrt(distance2);
    return cosEmitter > 0.0f ? (1.0f / area) * distance2 / cosEmitter : 0.0f;
}

// The light's own sample: its weight times the receiver's cosine.
double robustSample(const Light& light, const Receiver& r, Vec2 u) {
    const LightSample s = light.sample(r.point, u);
    if (!(s.pdf > 0.0f)) return 0.0;
    return double(s.weight.g) * std::max(0.0f, glm::dot(r.normal, s.wi));
}

// The former sphere light sampling: a point uniform by area, in float.
double naiveSphereSample(const Sphere& sphere, const Receiver& r, Vec2 u) {
    const float area = 4.0f * kPi * sphere.radius * sphere.radius;
    const Vec3 n = sampleUniformSphere(u);
    const Vec3 p = sphere.center + sphere.radius * n;
    const Vec3 toLight = p - r.point;
    const Vec3 wi = toLight / std::sqrt(glm::dot(toLight, toLight));
    if (glm::dot(n, wi) >= 0.0f) return 0.0;  // the far side, which the sphere itself hides
    const float pdf = naiveSolidAngleDensity(area, r.point, p, n);
    if (!(pdf > 0.0f)) return 0.0;
    return double(kRadiance / pdf) * std::max(0.0f, glm::dot(r.normal, wi));
}

// The former triangle sampling: area and normal from the float cross product.
double naiveTriangleSample(const Triangle& t, const Receiver& r, Vec2 u) {
    const Vec3 cross = glm::cross(t.b - t.a, t.c - t.a);
    const float area = 0.5f * glm::length(cross);
    if (!(area > 0.0f)) return 0.0;  // dropped as a zero-area triangle: its light is lost
    const Vec3 normal = glm::normalize(cross);
    const Vec3 b = sampleUniformTriangle(u);
    const Vec3 p = b.x * t.a + b.y * t.b + b.z * t.c;
    const Vec3 toLight = p - r.point;
    const Vec3 wi = toLight / std::sqrt(glm::dot(toLight, toLight));
    if (-glm::dot(normal, wi) <= 0.0f) return 0.0;
    const float pdf = naiveSolidAngleDensity(area, r.point, p, normal);
    if (!(pdf > 0.0f)) return 0.0;
    return double(kRadiance / pdf) * std::max(0.0f, glm::dot(r.normal, wi));
}

// Irradiance from a uniformly emitting sphere whose cap lies above the receiver's horizon, the
// receiver facing its centre: E = pi L sin^2(theta_max), sin(theta_max) = r / d (exact).
double sphereIrradiance(const Sphere& s, const Receiver& r) {
    const long double dx = (long double)r.point.x - s.center.x, dy = (long double)r.point.y - s.center.y,
                      dz = (long double)r.point.z - s.center.z;
    const long double d2 = dx * dx + dy * dy + dz * dz;
    return static_cast<double>(std::numbers::pi * kRadiance * (long double)s.radius * s.radius / d2);
}

struct Tally {
    double worst = 0.0;
    std::string detail;
    void add(const std::string& label, double value, double reference) {
        const double error = std::isfinite(value) ? 100.0 * std::fabs(value - reference) / reference
                                                  : std::numeric_limits<double>::infinity();
        worst = std::max(worst, error);
        char buffer[64];
        std::snprintf(buffer, sizeof buffer, "%s:%.2g%% ", label.c_str(), error);
        detail += buffer;
    }
};

void pushRows(std::vector<ScoreRow>& rows, const char* row, const Tally& robust, const Tally& naive,
              const std::string& note) {
    const char* metric = "max error of irradiance, % of the closed form";
    rows.push_back({row, "robust", "float", metric, robust.worst, kTargetPercent, note + robust.detail});
    rows.push_back({row, "naive", "float", metric, naive.worst, kTargetPercent, note + naive.detail});
}

const PathEvent kEvent{lpe::EventType::Emitter, lpe::Scatter::None, Subject::Object, 0};

// Sphere lights of radius 1e-12 .. 1e6, at 2 r from a receiver facing them (centred at the
// origin, where floats hold 2 r), and at r + 1e3 (centred 1e3 from the origin, as in the issue).
void sphereRow(const StressConfig& config, std::vector<ScoreRow>& rows) {
    const int n = config.quick ? 64 : 256;
    Tally robust, naive;
    for (const double radius : {1e-12, 1e-9, 1e-6, 1e-3, 1.0, 1e3, 1e6}) {
        for (const bool near : {true, false}) {
            const Sphere sphere{{near ? 0.0f : 1000.0f, 0.0f, 0.0f}, static_cast<float>(radius), 0};
            const double distance = near ? 2.0 * radius : radius + 1e3;
            const Receiver r{sphere.center + Vec3{0.0f, 0.0f, static_cast<float>(distance)}, {0.0f, 0.0f, -1.0f}};
            const SceneGeometry geometry({sphere}, {}, {});
            const AreaLightSource light(kEvent, Rgb{kRadiance}, geometry, {geometry.shapeId(0)});
            const double reference = sphereIrradiance(sphere, r);
            const std::uint64_t seed = 0xE417 + static_cast<std::uint64_t>(std::log10(radius) + 20) * 2 + near;
            const std::string label = "r=" + stress::powerLabel(radius) + (near ? ",d=2r" : ",d=r+1e3");
            robust.add(label, estimate([&](Vec2 u) { return robustSample(light, r, u); }, n, seed), reference);
            naive.add(label, estimate([&](Vec2 u) { return naiveSphereSample(sphere, r, u); }, n, seed), reference);
        }
    }
    pushRows(rows, "sphere light", robust, naive, std::to_string(n * n) + " samples per case; ");
}

// A sliver 1e-3 long and w wide, 1 below a receiver facing it: E = L A cos cos' / d^2 to 1e-6.
void sliverRow(const StressConfig& config, std::vector<ScoreRow>& rows) {
    const int n = config.quick ? 32 : 128;
    Tally robust, naive;
    for (const double width : {1e-4, 1e-10, 1e-16, 1e-22, 1e-28, 1e-33}) {
        const Triangle t{{0.0f, 0.0f, 0.0f}, {1e-3f, 0.0f, 0.0f}, {5e-4f, static_cast<float>(width), 0.0f}, 0};
        const Receiver r{{5e-4f, 0.0f, 1.0f}, {0.0f, 0.0f, -1.0f}};
        const SceneGeometry geometry({}, {}, {t});
        const AreaLightSource light(kEvent, Rgb{kRadiance}, geometry, {geometry.triangleId(0)});
        const double area = surfaceArea(t);  // the reference's own: in double, never through the light
        const double reference = kRadiance * area;  // cos = cos' = 1 and d = 1, to (1e-3)^2
        const std::uint64_t seed = 0x511E + static_cast<std::uint64_t>(-std::log10(width));
        const std::string label = "w=" + stress::powerLabel(width);
        robust.add(label, estimate([&](Vec2 u) { return robustSample(light, r, u); }, n, seed), reference);
        naive.add(label, estimate([&](Vec2 u) { return naiveTriangleSample(t, r, u); }, n, seed), reference);
    }
    pushRows(rows, "sliver triangle light", robust, naive, std::to_string(n * n) + " samples per case; ");
}

// A receiver 1e-7 above a sphere light's surface, facing its centre: nearly a hemisphere of
// light, E = pi L sin^2(theta_max) from the float positions.
void nearSurfaceRow(const StressConfig& config, std::vector<ScoreRow>& rows) {
    const int n = config.quick ? 128 : 512;
    Tally robust, naive;
    for (const double radius : {1e-4, 1e-3, 1e-2}) {
        const Sphere sphere{{0.0f, 0.0f, 0.0f}, static_cast<float>(radius), 0};
        const float z = static_cast<float>(radius + 1e-7);
        const Receiver r{{0.0f, 0.0f, z}, {0.0f, 0.0f, -1.0f}};
        const SceneGeometry geometry({sphere}, {}, {});
        const AreaLightSource light(kEvent, Rgb{kRadiance}, geometry, {geometry.shapeId(0)});
        const double reference = sphereIrradiance(sphere, r);
        const std::uint64_t seed = 0x6A9 + static_cast<std::uint64_t>(std::log10(radius) + 5);
        const std::string label = "r=" + stress::powerLabel(radius);
        robust.add(label, estimate([&](Vec2 u) { return robustSample(light, r, u); }, n, seed), reference);
        naive.add(label, estimate([&](Vec2 u) { return naiveSphereSample(sphere, r, u); }, n, seed), reference);
    }
    pushRows(rows, "light 1e-7 from a surface", robust, naive, std::to_string(n * n) + " samples per case; ");
}

}  // namespace

void runEmitterRows(const StressConfig& config, std::vector<ScoreRow>& rows) {
    sphereRow(config, rows);
    sliverRow(config, rows);
    nearSurfaceRow(config, rows);
}

}  // namespace lightpath
