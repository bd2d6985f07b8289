#pragma once
// A closed triangle mesh for the stress rows: a UV sphere with radially perturbed vertices, every
// edge shared by exactly two triangles through the same two vertex values, so the exact surface
// has no holes and a ray from outside towards an interior point must cross it.
#include <array>
#include <cstdint>
#include <numbers>
#include <vector>

#include "geometry/shapes.h"
#include "stress/sampling.h"

namespace lightpath::stress {

struct ClosedMesh {
    Vec3 centre{0.0f};
    float radius = 1.0f;  // of the unperturbed sphere
    std::vector<Vec3> vertices;
    std::vector<std::array<std::uint32_t, 3>> faces;

    std::vector<Triangle> triangles() const {
        std::vector<Triangle> out;
        for (const auto& f : faces) out.push_back({vertices[f[0]], vertices[f[1]], vertices[f[2]], 0});
        return out;
    }
};

// `rings` latitude bands and `segments` longitudes; radii perturbed by up to `perturbation`,
// then scaled by `scale` and moved to `centre` (in float, as a scene file would give them).
inline ClosedMesh perturbedUvSphere(int rings, int segments, double perturbation, float scale, Vec3 centre, Rng& rng) {
    ClosedMesh mesh;
    mesh.centre = centre;
    mesh.radius = scale;
    const auto place = [&](double theta, double phi) {
        const double r = 1.0 + perturbation * (2.0 * uniform(rng) - 1.0);
        const Vec3 unit{static_cast<float>(r * std::sin(theta) * std::cos(phi)),
                        static_cast<float>(r * std::sin(theta) * std::sin(phi)), static_cast<float>(r * std::cos(theta))};
        mesh.vertices.push_back(centre + scale * unit);
    };
    place(0.0, 0.0);  // north pole: vertex 0
    for (int i = 1; i < rings; ++i)
        for (int j = 0; j < segments; ++j) place(std::numbers::pi * i / rings, 2.0 * std::numbers::pi * j / segments);
    place(std::numbers::pi, 0.0);  // south pole: the last vertex
    const auto ringVertex = [&](int i, int j) {
        return static_cast<std::uint32_t>(1 + (i - 1) * segments + (j % segments));
    };
    const auto south = static_cast<std::uint32_t>(mesh.vertices.size() - 1);
    for (int j = 0; j < segments; ++j) {
        mesh.faces.push_back({0, ringVertex(1, j), ringVertex(1, j + 1)});
        mesh.faces.push_back({south, ringVertex(rings - 1, j + 1), ringVertex(rings - 1, j)});
        for (int i = 1; i + 1 < rings; ++i) {
            mesh.faces.push_back({ringVertex(i, j), ringVertex(i + 1, j), ringVertex(i + 1, j + 1)});
            mesh.faces.push_back({ringVertex(i, j), ringVertex(i + 1, j + 1), ringVertex(i, j + 1)});
        }
    }
    return mesh;
}

}  // namespace lightpath::stress
