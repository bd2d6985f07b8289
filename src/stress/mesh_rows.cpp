#include "stress/mesh_rows.h"

#include <algorithm>
#include <numbers>

#include "accel/scene_geometry.h"
#include "stress/closed_mesh.h"

namespace lightpath {
namespace {

using stress::Rng;

enum class Aim { Random, Vertex, Edge };

// A ray from outside through `surfacePoint` (on the mesh) that goes on into the interior: its
// origin lies within 20 degrees of the outward radial direction, which the mesh's facets (at most
// about 17 degrees from the sphere's tangent planes here) leave well clear. Whatever rounding
// does to the direction, the ray crosses the closed surface by the time it reaches that point,
// so tMax ends the ray just past it, by 1e-3 radii plus the rounding of the point (an edge point
// a + s (b - a) is off the edge by a few ulps): far less than the distance to the far side.
// Without a hit by then, the ray has slipped into the mesh between its triangles.
Ray rayThrough(const Vec3& surfacePoint, const stress::ClosedMesh& mesh, Rng& rng) {
    const Vec3 outward = glm::normalize(surfacePoint - mesh.centre);
    const Vec3 w = stress::randomInCone(rng, outward, std::cos(20.0 * std::numbers::pi / 180.0), 1.0);
    Ray ray;
    ray.origin = surfacePoint + static_cast<float>(mesh.radius * (0.5 + 2.5 * stress::uniform(rng))) * w;
    ray.direction = glm::normalize(surfacePoint - ray.origin);
    const Vec3 magnitude = glm::abs(surfacePoint);
    const float rounding = 0x1p-18f * std::max({magnitude.x, magnitude.y, magnitude.z});
    ray.tMax = glm::length(surfacePoint - ray.origin) + 1e-3f * mesh.radius + rounding;
    return ray;
}

Ray aimedRay(Aim aim, const stress::ClosedMesh& mesh, Rng& rng) {
    if (aim == Aim::Vertex) {
        const auto index = static_cast<std::size_t>(stress::uniform(rng) * static_cast<double>(mesh.vertices.size()));
        return rayThrough(mesh.vertices[std::min(index, mesh.vertices.size() - 1)], mesh, rng);
    }
    if (aim == Aim::Edge) {
        const auto f = static_cast<std::size_t>(stress::uniform(rng) * static_cast<double>(mesh.faces.size()));
        const auto& face = mesh.faces[std::min(f, mesh.faces.size() - 1)];
        const auto e = static_cast<int>(stress::uniform(rng) * 3.0) % 3;
        const Vec3 a = mesh.vertices[face[e]], b = mesh.vertices[face[(e + 1) % 3]];
        return rayThrough(a + static_cast<float>(stress::uniform(rng)) * (b - a), mesh, rng);
    }
    // From 3 radii away towards a point well inside, which it must reach through the surface.
    Ray ray;
    ray.origin = mesh.centre + (3.0f * mesh.radius) * stress::randomUnitVector(rng);
    const Vec3 inside = mesh.centre + static_cast<float>(0.5 * mesh.radius * stress::uniform(rng)) *
                                          stress::randomUnitVector(rng);
    ray.direction = glm::normalize(inside - ray.origin);
    ray.tMax = glm::length(inside - ray.origin);
    return ray;
}

}  // namespace

void runMeshRows(const StressConfig& config, std::vector<ScoreRow>& rows) {
    const std::vector<float> scales = {1e-3f, 1.0f, 1e3f};
    const int raysPerCase = config.quick ? 4000 : 40000;
    const std::vector<std::pair<Aim, const char*>> aims = {
        {Aim::Random, "random"}, {Aim::Vertex, "vertex"}, {Aim::Edge, "edge"}};
    for (const bool robustMethod : {true, false}) {
        const NumericsOptions numerics = robustMethod ? NumericsOptions{} : NumericsOptions::naive();
        double leaks = 0, rays = 0;
        std::string detail;
        for (std::size_t s = 0; s < scales.size(); ++s) {
            const float scale = scales[s];
            Rng rng(0xC105ED + s);
            std::vector<double> leaksPerAim(aims.size(), 0.0);
            // At the origin, and 100 and 1e4 radii away.
            const Vec3 direction = stress::randomUnitVector(rng);
            for (const Vec3 centre : {Vec3{0.0f}, (100.0f * scale) * direction, (1e4f * scale) * direction}) {
                const auto mesh = stress::perturbedUvSphere(8, 16, 0.02, scale, centre, rng);
                const SceneGeometry geometry({}, {}, mesh.triangles(), numerics);
                for (std::size_t a = 0; a < aims.size(); ++a) {
                    for (int i = 0; i < raysPerCase; ++i) {
                        const bool leak = !geometry.occluded(aimedRay(aims[a].first, mesh, rng));
                        leaks += leak;
                        leaksPerAim[a] += leak;
                    }
                }
                rays += static_cast<double>(raysPerCase * aims.size());
            }
            detail += "scale " + stress::powerLabel(scale) + ":";
            for (std::size_t a = 0; a < aims.size(); ++a)
                detail += std::string(" ") + aims[a].second + " " + stress::percent(leaksPerAim[a], 3.0 * raysPerCase);
            detail += s + 1 < scales.size() ? "; " : "";
        }
        detail = std::to_string(static_cast<long long>(rays)) + " rays; " + detail;
        rows.push_back({"watertight mesh", robustMethod ? "robust" : "naive", "float", "leaks per million rays",
                        1e6 * leaks / rays, 0.0, detail});
    }
}

}  // namespace lightpath
