#include "stress/shadow_rows.h"

#include "accel/scene_geometry.h"
#include "geometry/spawn_ray.h"
#include "stress/sampling.h"
#include <numbers>

namespace lightpath {
namespace {

using stress::Rng;


// A square floor of half-size `scale`, tilted 10 to 60 degrees from horizontal, centred up to
// 0.3 scale from the origin: two triangles sharing a diagonal.
struct Floor {
    Vec3 centre, normal, u, v;
    float halfSize;

    std::vector<Triangle> triangles() const {
        const Vec3 a = centre - halfSize * u - halfSize * v, b = centre + halfSize * u - halfSize * v;
        const Vec3 c = centre + halfSize * u + halfSize * v, d = centre - halfSize * u + halfSize * v;
        return {{a, b, c, 0}, {a, c, d, 0}};
    }
    Vec3 pointAt(double x, double y) const {  // x, y in [-1, 1]
        return centre + static_cast<float>(x * halfSize) * u + static_cast<float>(y * halfSize) * v;
    }
};

Floor tiltedFloor(float scale, Rng& rng) {
    Floor floor;
    floor.normal = stress::randomInCone(rng, {0.0f, 1.0f, 0.0f}, std::cos(60.0 * std::numbers::pi / 180.0), std::cos(10.0 * std::numbers::pi / 180.0));
    stress::orthonormalBasis(floor.normal, floor.u, floor.v);
    floor.centre = static_cast<float>(0.3 * scale * stress::uniform(rng)) * stress::randomUnitVector(rng);
    floor.halfSize = scale;
    return floor;
}

// A unit direction at `elevation` above the floor, in a random azimuth.
Vec3 aboveFloor(const Floor& floor, double elevation, Rng& rng, Vec3* azimuthOut = nullptr) {
    const double phi = 2.0 * std::numbers::pi * stress::uniform(rng);
    const Vec3 azimuth = static_cast<float>(std::cos(phi)) * floor.u + static_cast<float>(std::sin(phi)) * floor.v;
    if (azimuthOut != nullptr) *azimuthOut = azimuth;
    return glm::normalize(static_cast<float>(std::cos(elevation)) * azimuth +
                          static_cast<float>(std::sin(elevation)) * floor.normal);
}

// A camera ray from above the floor towards `target` on it; the hit, from the floor alone.
std::optional<SurfaceHit> floorHit(const SceneGeometry& floorOnly, const Floor& floor, const Vec3& target, Rng& rng) {
    Ray camera;
    camera.origin = target + floor.halfSize * stress::randomInCone(rng, floor.normal, 0.2, 1.0);
    camera.direction = glm::normalize(target - camera.origin);
    return floorOnly.intersect(camera);
}

const std::vector<float> kScales = {1e-4f, 1e-2f, 1.0f, 1e2f, 1e4f, 1e6f};

// The robust and naive methods, and Wachter and Binder's offset (robust intersections) to show
// its limit: an absolute 1/65536 offset near the origin, larger than a small scene's gaps.
const std::vector<std::string> kMethods = {"robust", "naive", "wachter-binder"};

NumericsOptions methodNumerics(const std::string& method) {
    if (method == "naive") return NumericsOptions::naive();
    NumericsOptions numerics;
    if (method == "wachter-binder") numerics.offset = RayOffset::WachterBinder;
    return numerics;
}

void acneRow(const StressConfig& config, std::vector<ScoreRow>& rows) {
    const int raysPerCase = config.quick ? 3000 : 30000;
    for (const std::string& method : kMethods) {
        double acne = 0, shadowRays = 0, invisible = 0;
        std::string detail;
        for (const float scale : kScales) {
            Rng rng(0xAC4E + static_cast<std::uint64_t>(std::log10(scale) + 10));
            const Floor floor = tiltedFloor(scale, rng);
            const SceneGeometry geometry({}, {}, floor.triangles(), methodNumerics(method));
            double high = 0, grazing = 0;
            for (int i = 0; i < raysPerCase; ++i) {
                const auto hit = floorHit(geometry, floor, floor.pointAt(1.8 * stress::uniform(rng) - 0.9,
                                                                         1.8 * stress::uniform(rng) - 0.9), rng);
                if (!hit) {
                    ++invisible;
                    continue;
                }
                // A light 0.5 to 2 scale away at 30-90 degrees, and one at 0.5-5 degrees: nothing
                // but the floor is in the scene, and both lights are on its lit side.
                for (const bool grazingLight : {false, true}) {
                    const double elevation = (grazingLight ? 0.5 + 4.5 * stress::uniform(rng)
                                                           : 30.0 + 60.0 * stress::uniform(rng)) * std::numbers::pi / 180.0;
                    const Vec3 light = hit->point + static_cast<float>(scale * (0.5 + 1.5 * stress::uniform(rng))) *
                                                        aboveFloor(floor, elevation, rng);
                    const bool shadowed = geometry.occluded(spawnShadowRay(*hit, light, kNoSurfaceNormal, geometry.numerics()));
                    (grazingLight ? grazing : high) += shadowed;
                    ++shadowRays;
                }
            }
            acne += high + grazing;
            char buffer[96];
            std::snprintf(buffer, sizeof buffer, "%s: %.0f+%.0f; ", stress::powerLabel(scale).c_str(), high, grazing);
            detail += buffer;
        }
        if (invisible > 0) detail += "floor invisible to " + stress::percent(invisible, raysPerCase * 6.0) + " of camera rays";
        rows.push_back({"acne sweep", method, "float", "falsely shadowed, % of shadow rays",
                        shadowRays > 0 ? 100.0 * acne / shadowRays : 0.0, 0.0,
                        "scale: 30-90deg+0.5-5deg counts; " + detail});
    }
}

void contactRow(const StressConfig& config, std::vector<ScoreRow>& rows) {
    const int raysPerCase = config.quick ? 3000 : 30000;
    for (const std::string& method : kMethods) {
        double leaks = 0, shadowRays = 0, invisible = 0;
        std::string detail;
        for (const float scale : kScales) {
            Rng rng(0xC0774C7 + static_cast<std::uint64_t>(std::log10(scale) + 10));
            const Floor floor = tiltedFloor(scale, rng);
            // The occluder: a square of half-size 0.05 scale, parallel to the floor, 1e-3 scale above it.
            const float height = 1e-3f * scale;
            Floor occluder = floor;
            occluder.centre = floor.pointAt(0.5 * stress::uniform(rng), 0.5 * stress::uniform(rng)) + height * floor.normal;
            occluder.halfSize = 0.05f * scale;
            std::vector<Triangle> triangles = floor.triangles();
            for (const Triangle& t : occluder.triangles()) triangles.push_back(t);
            const SceneGeometry floorOnly({}, {}, floor.triangles(), methodNumerics(method));
            const SceneGeometry scene({}, {}, triangles, methodNumerics(method));
            double caseLeaks = 0;
            for (int i = 0; i < raysPerCase; ++i) {
                // A light at 30-90 degrees and a floor point whose segment to it crosses the
                // occluder at most 0.03 scale from its centre: 0.02 scale inside its edges.
                Vec3 azimuth;
                const double elevation = (30.0 + 60.0 * stress::uniform(rng)) * std::numbers::pi / 180.0;
                const Vec3 toLight = aboveFloor(floor, elevation, rng, &azimuth);
                const Vec3 below = occluder.centre - height * floor.normal -
                                   static_cast<float>(height / std::tan(elevation)) * azimuth;
                const Vec3 target = below + static_cast<float>(0.03 * scale * (2.0 * stress::uniform(rng) - 1.0)) * floor.u +
                                    static_cast<float>(0.03 * scale * (2.0 * stress::uniform(rng) - 1.0)) * floor.v;
                const auto hit = floorHit(floorOnly, floor, target, rng);
                if (!hit) {
                    ++invisible;
                    continue;
                }
                const Vec3 light = hit->point + scale * toLight;
                caseLeaks += !scene.occluded(spawnShadowRay(*hit, light, kNoSurfaceNormal, scene.numerics()));
                ++shadowRays;
            }
            leaks += caseLeaks;
            detail += stress::powerLabel(scale) + ": " + stress::percent(caseLeaks, raysPerCase) + "; ";
        }
        if (invisible > 0) detail += "floor invisible to " + stress::percent(invisible, raysPerCase * 6.0) + " of camera rays";
        rows.push_back({"contact shadows", method, "float", "leaked, % of shadow rays",
                        shadowRays > 0 ? 100.0 * leaks / shadowRays : 0.0, 0.0, "scale: leaked; " + detail});
    }
}

}  // namespace

void runShadowRows(const StressConfig& config, std::vector<ScoreRow>& rows) {
    acneRow(config, rows);
    contactRow(config, rows);
}

}  // namespace lightpath
