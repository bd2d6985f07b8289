#pragma once
// Scenes and rays for checking accelerators against brute force: random soups, the bunny, and
// rays chosen to hit the corner cases of a slab test and of traversal order.
#include <cmath>
#include <vector>

#include "accel/scene_geometry.h"
#include "math/random.h"

namespace lightpath::test {

struct Soup {
    std::vector<Sphere> spheres;
    std::vector<Plane> planes;
    std::vector<Triangle> triangles;
};

inline Vec3 uniformIn(Pcg32& rng, const Vec3& lo, const Vec3& hi) {
    return lo + (hi - lo) * Vec3(rng.nextFloat(), rng.nextFloat(), rng.nextFloat());
}

inline Vec3 uniformDirection(Pcg32& rng) {
    const float z = 1.0f - 2.0f * rng.nextFloat();
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    const float phi = 2.0f * kPi * rng.nextFloat();
    return {r * std::cos(phi), r * std::sin(phi), z};
}

// Triangles of mixed sizes (many overlapping), spheres, axis-aligned triangles whose boxes are
// flat, triangles sharing edges, and one plane (kept outside the BVH).
inline Soup randomSoup(std::uint64_t seed, int triangles, int spheres) {
    Pcg32 rng(seed, 1);
    Soup soup;
    const Vec3 lo(-10.0f), hi(10.0f);
    for (int i = 0; i < spheres; ++i)
        soup.spheres.push_back({uniformIn(rng, lo, hi), 0.05f + 2.0f * rng.nextFloat() * rng.nextFloat(), 0});
    for (int i = 0; i < triangles; ++i) {
        const Vec3 a = uniformIn(rng, lo, hi);
        const float size = i % 5 == 0 ? 6.0f : 0.8f;
        Vec3 b = a + size * uniformDirection(rng), c = a + size * uniformDirection(rng);
        if (i % 7 == 0) b.z = c.z = a.z;  // flat in z: a box of zero depth
        if (i % 11 == 0) b.x = c.x = a.x;  // flat in x
        soup.triangles.push_back({a, b, c, 0});
        if (i % 13 == 0) soup.triangles.push_back({b, c, c + (c - a), 0});  // shares edge bc
    }
    soup.planes.push_back({Vec3(0.0f, -12.0f, 0.0f), glm::normalize(Vec3(0.1f, 1.0f, 0.05f)), 0});
    return soup;
}

// Axis-parallel directions, origins on primitives' box faces (coordinates equal to vertex
// coordinates), rays far from the origin, grazing rays along edges and tangent to spheres, and
// rays aimed exactly at vertices.
inline std::vector<Ray> adversarialRays(const Soup& soup, std::uint64_t seed, int count) {
    Pcg32 rng(seed, 2);
    std::vector<Ray> rays;
    const Vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    const auto pickTriangle = [&]() -> const Triangle& {
        return soup.triangles[rng.nextUint() % soup.triangles.size()];
    };
    while (static_cast<int>(rays.size()) < count) {
        const Triangle& t = pickTriangle();
        const Vec3 corner[3] = {t.a, t.b, t.c};
        const Vec3& v = corner[rng.nextUint() % 3];
        const Vec3& w = corner[rng.nextUint() % 3];
        Ray ray;
        switch (rng.nextUint() % 6) {
            case 0: {  // axis-parallel, from an origin sharing two coordinates with a vertex
                const Vec3 d = axes[rng.nextUint() % 6];
                ray.origin = v - 30.0f * d;
                ray.direction = d;
                break;
            }
            case 1: {  // origin on a box face plane, direction inside that plane
                const int axis = static_cast<int>(rng.nextUint() % 3);
                ray.origin = uniformIn(rng, Vec3(-12.0f), Vec3(12.0f));
                ray.origin[axis] = v[axis];
                Vec3 d = uniformDirection(rng);
                d[axis] = 0.0f;
                ray.direction = glm::length(d) > 0.0f ? glm::normalize(d) : axes[(2 * axis + 2) % 6];
                break;
            }
            case 2: {  // from far away, towards a vertex
                ray.origin = v + (1e3f + 1e5f * rng.nextFloat()) * uniformDirection(rng);
                ray.direction = glm::normalize(v - ray.origin);
                break;
            }
            case 3: {  // grazing: along an edge, nudged off it by a hair
                if (v == w) continue;
                const Vec3 along = glm::normalize(w - v);
                ray.origin = v - 5.0f * along;
                ray.direction = glm::normalize(along + 1e-6f * uniformDirection(rng));
                break;
            }
            case 4: {  // tangent to a sphere
                if (soup.spheres.empty()) continue;
                const Sphere& s = soup.spheres[rng.nextUint() % soup.spheres.size()];
                const Vec3 n = uniformDirection(rng);
                Vec3 d = glm::cross(n, uniformDirection(rng));
                if (glm::length(d) == 0.0f) continue;
                d = glm::normalize(d);
                ray.origin = s.center + s.radius * n - 20.0f * d;
                ray.direction = d;
                break;
            }
            default: {  // exactly at a vertex from a random origin, with a limited segment
                ray.origin = uniformIn(rng, Vec3(-15.0f), Vec3(15.0f));
                const Vec3 to = v - ray.origin;
                if (glm::length(to) == 0.0f) continue;
                ray.direction = glm::normalize(to);
                ray.tMax = glm::length(to) * (0.5f + rng.nextFloat());
                break;
            }
        }
        rays.push_back(ray);
    }
    return rays;
}

inline std::vector<Ray> randomRays(std::uint64_t seed, int count, const Vec3& lo, const Vec3& hi) {
    Pcg32 rng(seed, 3);
    std::vector<Ray> rays(static_cast<std::size_t>(count));
    for (Ray& ray : rays) {
        ray.origin = uniformIn(rng, lo, hi);
        ray.direction = uniformDirection(rng);
        if (rng.nextUint() % 4 == 0) ray.tMax = 20.0f * rng.nextFloat();
        if (rng.nextUint() % 8 == 0) ray.tMin = rng.nextFloat();
    }
    return rays;
}

}  // namespace lightpath::test
