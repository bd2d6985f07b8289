#include "stress/sphere_rows.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "geometry/intersect.h"
#include "accel/scene_geometry.h"
#include "geometry/spawn_ray.h"
#include "shapes/sphere.h"
#include "stress/exact_reference.h"
#include "stress/sampling.h"

namespace lightpath {
namespace {

using stress::Rng;
using stress::ExactRoots;
using stress::exactSphereRoots;
using stress::ulpsBetween;

struct MethodTally {
    double wrong = 0, rays = 0, worstUlps = 0;
    std::string wrongDetail, ulpDetail;
};

void silhouetteAndT(const StressConfig& config, std::vector<ScoreRow>& rows) {
    const std::vector<double> distances = {1e1, 1e2, 1e3, 3e3, 1e4, 1e5, 1e6};
    const int raysPerDistance = config.quick ? 20000 : 200000;
    const Sphere sphere{{0.0f, 0.0f, 0.0f}, 1.0f, 0};
    MethodTally robust, naive;
    for (const double distance : distances) {
        Rng rng(0x5111'0E77E + static_cast<std::uint64_t>(distance));
        double robustWrong = 0, naiveWrong = 0, robustUlps = 0, naiveUlps = 0;
        for (int i = 0; i < raysPerDistance; ++i) {
            // From `distance` radii away, at a uniform point of a disk of radius 1.1 r facing the
            // origin: about 17% of the rays miss, and many pass close to the silhouette.
            const Vec3 axis = stress::randomUnitVector(rng);
            Vec3 e1, e2;
            stress::orthonormalBasis(axis, e1, e2);
            const double rho = 1.1 * std::sqrt(stress::uniform(rng));
            const double phi = 2.0 * std::numbers::pi * stress::uniform(rng);
            const Vec3 target = static_cast<float>(rho * std::cos(phi)) * e1 + static_cast<float>(rho * std::sin(phi)) * e2;
            Ray ray;
            ray.origin = static_cast<float>(distance) * axis;
            ray.direction = glm::normalize(target - ray.origin);
            const ExactRoots reference = exactSphereRoots(ray, sphere);
            const bool referenceHit = reference.hit && reference.t1 > 0;

            const bool robustHit = intersectSphere(ray, sphere, 0.0f) != kNoHit;
            const bool naiveHit = intersectSphereNaive(ray, sphere, 0.0f) != kNoHit;
            robustWrong += robustHit != referenceHit;
            naiveWrong += naiveHit != referenceHit;
            float t0 = 0, t1 = 0;
            if (referenceHit && robustHit && sphereRoots(ray, sphere, t0, t1))
                robustUlps = std::max({robustUlps, ulpsBetween(t0, reference.t0), ulpsBetween(t1, reference.t1)});
            if (referenceHit && naiveHit && sphereRootsNaive(ray, sphere, t0, t1))
                naiveUlps = std::max({naiveUlps, ulpsBetween(t0, reference.t0), ulpsBetween(t1, reference.t1)});
        }
        const std::string label = stress::powerLabel(distance) + ":";
        robust.wrong += robustWrong;
        naive.wrong += naiveWrong;
        robust.rays += raysPerDistance;
        naive.rays += raysPerDistance;
        robust.wrongDetail += label + stress::percent(robustWrong, raysPerDistance) + " ";
        naive.wrongDetail += label + stress::percent(naiveWrong, raysPerDistance) + " ";
        char buffer[48];
        std::snprintf(buffer, sizeof buffer, "%.3g ", robustUlps);
        robust.ulpDetail += label + buffer;
        std::snprintf(buffer, sizeof buffer, "%.3g ", naiveUlps);
        naive.ulpDetail += label + buffer;
        robust.worstUlps = std::max(robust.worstUlps, robustUlps);
        naive.worstUlps = std::max(naive.worstUlps, naiveUlps);
    }
    const std::string rays = std::to_string(raysPerDistance) + " rays per d/r ";
    for (const auto& [method, tally] : {std::pair{"robust", &robust}, std::pair{"naive", &naive}}) {
        rows.push_back({"sphere silhouette", method, "float", "wrong hit/miss, % of rays",
                        100.0 * tally->wrong / tally->rays, 0.0, rays + "(d/r:%) " + tally->wrongDetail});
    }
    for (const auto& [method, tally] : {std::pair{"robust", &robust}, std::pair{"naive", &naive}}) {
        rows.push_back({"sphere t", method, "float", "max error of t0, t1 in ulps", tally->worstUlps, 4.0,
                        "(d/r:ulps) " + tally->ulpDetail});
    }
}

// A secondary ray from `hit` in `direction` is wrong when it finds the surface it starts on:
// leaving outward it must find nothing (a sphere is convex), going inward it must reach the far
// side, where the ray exits (normal . direction > 0).
struct SpawnCheck {
    double selfHits = 0, wrongRefractions = 0, rays = 0;
};

void checkFrom(const SceneGeometry& geometry, const SurfaceHit& hit, Rng& rng, SpawnCheck& check) {
    const NumericsOptions& numerics = geometry.numerics();
    const Vec3& outward = hit.normal;  // a sphere's geometric normal points out, from either side
    // Outward: reflection off the outside, or refraction out of the inside; down to grazing.
    const Ray out = spawnRay(hit, stress::randomInCone(rng, outward, 1e-3, 1.0), numerics);
    check.selfHits += geometry.intersect(out).has_value();
    // Inward: refraction into the sphere, or internal reflection; chords of at least 0.2 r.
    const Vec3 inwardDirection = stress::randomInCone(rng, -outward, 0.1, 1.0);
    const auto far = geometry.intersect(spawnRay(hit, inwardDirection, numerics));
    const bool exits = far && glm::dot(far->point - sphereOf(geometry.shapes()[0]).center, inwardDirection) > 0.0f;
    check.wrongRefractions += !exits;
    check.rays += 2;
}

void spawnRow(const StressConfig& config, std::vector<ScoreRow>& rows) {
    const std::vector<double> radii = {1e-3, 1.0, 1e3};
    const std::vector<double> centreDistances = {0.0, 1e1, 1e2, 1e3, 1e4};  // in radii
    const int hitsPerCase = config.quick ? 1500 : 15000;
    for (const bool robustMethod : {true, false}) {
        NumericsOptions numerics = robustMethod ? NumericsOptions{} : NumericsOptions::naive();
        SpawnCheck total;
        std::string detail;
        for (const double radius : radii) {
            SpawnCheck perRadius;
            for (const double k : centreDistances) {
                Rng rng(0x5BA3 + static_cast<std::uint64_t>(k * 7 + radius * 1000));
                const Vec3 centre = static_cast<float>(k * radius) * stress::randomUnitVector(rng);
                const SceneGeometry geometry({Sphere{centre, static_cast<float>(radius), 0}}, {}, {}, numerics);
                for (int i = 0; i < hitsPerCase; ++i) {
                    // A camera ray from 4 r away aimed inside the sphere: its hit is on the outside.
                    Ray camera;
                    camera.origin = centre + static_cast<float>(4.0 * radius) * stress::randomUnitVector(rng);
                    const Vec3 inside = centre + static_cast<float>(0.95 * radius * std::cbrt(stress::uniform(rng))) *
                                                     stress::randomUnitVector(rng);
                    camera.direction = glm::normalize(inside - camera.origin);
                    const auto entry = geometry.intersect(camera);
                    if (!entry) {
                        ++perRadius.wrongRefractions;  // not even the camera ray found the sphere
                        continue;
                    }
                    checkFrom(geometry, *entry, rng, perRadius);
                    // And from inside: the exit point of a refracted ray, as the far hit of a chord.
                    const auto exit = geometry.intersect(spawnRay(*entry, camera.direction, numerics));
                    if (exit && glm::dot(exit->point - centre, camera.direction) > 0.0f)
                        checkFrom(geometry, *exit, rng, perRadius);
                }
            }
            total.selfHits += perRadius.selfHits;
            total.wrongRefractions += perRadius.wrongRefractions;
            total.rays += perRadius.rays;
            char buffer[96];
            std::snprintf(buffer, sizeof buffer, "r=%s: %.0f self-hits, %.0f wrong refr. of %.0f; ",
                          stress::powerLabel(radius).c_str(), perRadius.selfHits, perRadius.wrongRefractions,
                          perRadius.rays);
            detail += buffer;
        }
        rows.push_back({"sphere spawn", robustMethod ? "robust" : "naive", "float",
                        "self-hits + wrong refractions", total.selfHits + total.wrongRefractions, 0.0,
                        "centre 0..1e4 r; " + detail});
    }
}

}  // namespace

void runSphereRows(const StressConfig& config, std::vector<ScoreRow>& rows) {
    silhouetteAndT(config, rows);
    spawnRow(config, rows);
}

}  // namespace lightpath
