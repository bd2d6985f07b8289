#include "stress/bvh_row.h"

#include <algorithm>

#include "accel/scene_geometry.h"
#include "stress/sampling.h"

namespace lightpath {
namespace {

using stress::Rng;

struct Box {
    Vec3 lo, hi;
};

// Random triangles and spheres in a cube of half-size `size` around `centre`, a third of the
// triangles axis-aligned so their boxes are flat; each primitive's exact box for aiming rays.
struct BvhScene {
    std::vector<Sphere> spheres;
    std::vector<Triangle> triangles;
    std::vector<Box> boxes;
};

BvhScene randomScene(Vec3 centre, float size, Rng& rng) {
    BvhScene scene;
    const auto point = [&] {
        return centre + size * Vec3{static_cast<float>(2 * stress::uniform(rng) - 1),
                                    static_cast<float>(2 * stress::uniform(rng) - 1),
                                    static_cast<float>(2 * stress::uniform(rng) - 1)};
    };
    for (int i = 0; i < 60; ++i) {
        const Sphere s{point(), size * static_cast<float>(0.01 + 0.15 * stress::uniform(rng)), 0};
        scene.spheres.push_back(s);
        scene.boxes.push_back({s.center - Vec3(s.radius), s.center + Vec3(s.radius)});
    }
    for (int i = 0; i < 240; ++i) {
        const Vec3 a = point();
        const float extent = size * static_cast<float>(0.02 + 0.4 * stress::uniform(rng));
        Vec3 b = a + extent * stress::randomUnitVector(rng), c = a + extent * stress::randomUnitVector(rng);
        if (i % 3 == 0) {  // flat box: all three vertices share one coordinate exactly
            const int axis = i % 9 / 3;
            b[axis] = a[axis];
            c[axis] = a[axis];
        }
        scene.triangles.push_back({a, b, c, 0});
        scene.boxes.push_back({glm::min(a, glm::min(b, c)), glm::max(a, glm::max(b, c))});
    }
    return scene;
}

Vec3 axisDirection(Rng& rng) {
    Vec3 d{0.0f};
    d[static_cast<int>(stress::uniform(rng) * 3.0) % 3] = stress::uniform(rng) < 0.5 ? -1.0f : 1.0f;
    return d;
}

// One of four kinds of ray: random; axis-parallel; from a point exactly on a primitive's box
// face; and in the plane of a flat box (zero direction component along its flat axis).
Ray stressRay(int kind, const BvhScene& scene, Vec3 centre, float size, Rng& rng) {
    Ray ray;
    ray.origin = centre + 1.5f * size * stress::randomUnitVector(rng);
    ray.direction = stress::randomUnitVector(rng);
    const Box& box = scene.boxes[std::min(scene.boxes.size() - 1,
                                          static_cast<std::size_t>(stress::uniform(rng) * scene.boxes.size()))];
    const auto inBox = [&](int axis) {
        return box.lo[axis] + static_cast<float>(stress::uniform(rng)) * (box.hi[axis] - box.lo[axis]);
    };
    switch (kind) {
        case 1:
            ray.direction = axisDirection(rng);
            break;
        case 2: {
            const int axis = static_cast<int>(stress::uniform(rng) * 3.0) % 3;
            ray.origin = {inBox(0), inBox(1), inBox(2)};
            ray.origin[axis] = stress::uniform(rng) < 0.5 ? box.lo[axis] : box.hi[axis];
            if (stress::uniform(rng) < 0.5) ray.direction = axisDirection(rng);
            break;
        }
        case 3: {
            const int axis = static_cast<int>(stress::uniform(rng) * 3.0) % 3;
            const Vec3 inside{inBox(0), inBox(1), inBox(2)};
            ray.origin[axis] = box.lo[axis];
            Vec3 towards = inside - ray.origin;
            towards[axis] = 0.0f;
            if (glm::dot(towards, towards) > 0.0f) ray.direction = glm::normalize(towards);
            ray.direction[axis] = 0.0f;
            break;
        }
        default:
            break;
    }
    return ray;
}

}  // namespace

void runBvhRow(const StressConfig& config, std::vector<ScoreRow>& rows) {
    const int raysPerCase = config.quick ? 25000 : 250000;
    const std::vector<std::pair<Vec3, float>> placements = {
        {Vec3{0.0f}, 1.0f}, {Vec3{1e5f, -3e4f, 2e4f}, 1.0f}, {Vec3{0.0f}, 1e-3f}, {Vec3{-7e3f, 0.0f, 1e4f}, 1e3f}};
    for (const bool robust : {true, false}) {
        const NumericsOptions numerics = robust ? NumericsOptions{} : NumericsOptions::naive();
        double differing = 0, rays = 0, hits = 0;
        for (std::size_t p = 0; p < placements.size(); ++p) {
            const auto [centre, size] = placements[p];
            Rng rng(0xB7A + p);
            const BvhScene scene = randomScene(centre, size, rng);
            const SceneGeometry brute(scene.spheres, {}, scene.triangles, numerics, Accelerator::BruteForce);
            const SceneGeometry bvh(scene.spheres, {}, scene.triangles, numerics, Accelerator::Bvh);
            for (int kind = 0; kind < 4; ++kind) {
                for (int i = 0; i < raysPerCase / 4; ++i) {
                    const Ray ray = stressRay(kind, scene, centre, size, rng);
                    const auto expected = brute.closestPrimitive(ray);
                    const auto found = bvh.closestPrimitive(ray);
                    hits += expected.has_value();
                    const bool same = expected.has_value() == found.has_value() &&
                                      (!expected || (expected->t == found->t && expected->primitive == found->primitive));
                    differing += !same;
                    ++rays;
                }
            }
        }
        rows.push_back({"BVH = brute force", robust ? "robust" : "naive", "float", "closest (t, primitive) differs",
                        differing, 0.0,
                        std::to_string(static_cast<long long>(rays)) + " rays (" + stress::percent(hits, rays) +
                            " hit): random, axis-parallel, on box faces, in flat boxes' planes; at 0, 1e5, scale 1e-3, 1e3"});
    }
}

}  // namespace lightpath
