#include "bench/ray_benchmark.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <optional>
#include <thread>

#include "bench/height_field.h"
#include "bench/timing.h"
#include "film/aov_set.h"
#include "geometry/scene_geometry.h"
#include "lights/point_light.h"
#include "math/random.h"
#include "render/renderer.h"
#include "scene/camera.h"
#include "scene/scene_loader.h"
#include "film/aov_presets.h"

namespace lightpath {
namespace {

using Clock = std::chrono::steady_clock;

struct BenchScene {
    std::string name;
    std::string file;  // a shipped scene, or empty for the generated height field
};

// The memory test's height field (src/bench/height_field.h), 2 * 708^2 = 1,002,528 triangles
// (quick: 2 * 224^2 = 100,352), seen from above at an angle and lit from one side.
Scene heightFieldScene(std::size_t side) {
    Scene scene;
    std::vector<Vec3> vertices;
    vertices.reserve((side + 1) * (side + 1));
    for (std::size_t row = 0; row <= side; ++row) {
        for (std::size_t column = 0; column <= side; ++column) {
            const float x = height_field::coordinate(column, side), z = height_field::coordinate(row, side);
            vertices.emplace_back(x, height_field::height(x, z), z);
        }
    }
    scene.triangles.reserve(2 * side * side);
    height_field::forEachTriangle(side, [&](std::size_t a, std::size_t b, std::size_t c) {
        scene.triangles.push_back({vertices[a], vertices[b], vertices[c], 0});
    });
    scene.camera.eye = Vec3(0.0f, 1.2f, 2.2f);
    scene.camera.lookAt = Vec3(0.0f, -0.1f, 0.0f);
    scene.camera.verticalFovDegrees = 50.0f;
    PointLight light;
    light.location = Vec3(-2.0f, 1.5f, 1.0f);
    scene.lights.push_back(light);
    return scene;
}

// Rays handed out in chunks from an atomic counter: the same dynamic scheme as the renderer.
double timeParallel(std::size_t count, int threads, const std::function<void(std::size_t, std::size_t)>& work) {
    constexpr std::size_t kChunk = 4096;
    std::atomic<std::size_t> next{0};
    const auto loop = [&] {
        for (std::size_t begin = next.fetch_add(kChunk); begin < count; begin = next.fetch_add(kChunk))
            work(begin, std::min(begin + kChunk, count));
    };
    const auto started = Clock::now();
    {
        std::vector<std::jthread> workers;
        for (int t = 1; t < threads; ++t) workers.emplace_back(loop);
        loop();
    }
    return std::chrono::duration<double>(Clock::now() - started).count();
}

Bounds triangleBox(const std::vector<Triangle>& triangles) {
    Bounds box;
    for (const Triangle& t : triangles) {
        box.grow(t.a);
        box.grow(t.b);
        box.grow(t.c);
    }
    return box;
}

std::vector<Ray> primaryRays(const Scene& scene, int side) {
    CameraDescription description = scene.camera;
    description.width = side;
    description.height = side;
    const PinholeCamera camera(description);
    std::vector<Ray> rays;
    rays.reserve(static_cast<std::size_t>(side) * static_cast<std::size_t>(side));
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x)
            rays.push_back(camera.generateRay(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f));
    return rays;
}

// Origins uniform in the box, directions uniform on the sphere (z = 1 - 2u, phi = 2 pi v).
std::vector<Ray> randomRays(const Bounds& box, int count) {
    Pcg32 rng(0x5eed, 7);
    std::vector<Ray> rays(static_cast<std::size_t>(count));
    for (Ray& ray : rays) {
        ray.origin = box.lo + (box.hi - box.lo) * Vec3(rng.nextFloat(), rng.nextFloat(), rng.nextFloat());
        const float z = 1.0f - 2.0f * rng.nextFloat();
        const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
        const float phi = 2.0f * kPi * rng.nextFloat();
        ray.direction = Vec3(r * std::cos(phi), r * std::sin(phi), z);
    }
    return rays;
}

// From every primary hit towards the light. The origin is lifted off the surface by a small
// fraction of the scene size, so both accelerators answer the same question without a filter.
std::vector<Ray> shadowRays(const SceneGeometry& geometry, const std::vector<Ray>& primary, const Vec3& light,
                            float lift) {
    std::vector<Ray> rays;
    for (const Ray& ray : primary) {
        const auto hit = geometry.intersect(ray);
        if (!hit) continue;
        const Vec3 side = glm::dot(hit->normal, light - hit->point) >= 0.0f ? hit->normal : -hit->normal;
        Ray shadow;
        shadow.origin = hit->point + lift * side;
        const Vec3 toLight = light - shadow.origin;
        const float distance = glm::length(toLight);
        shadow.direction = toLight / distance;
        shadow.tMax = distance;
        rays.push_back(shadow);
    }
    return rays;
}

struct Measured {
    std::string rays;
    std::string accel;
    int threads;
    std::vector<double> rates;
};

}  // namespace

RayBenchmarkResult runRayBenchmark(const std::filesystem::path& directory, bool quick,
                                   const std::function<void(const std::string&)>& log) {
    RayBenchmarkResult result;
    result.primarySide = quick ? 256 : 1024;
    result.randomRays = quick ? 1 << 16 : 1 << 20;
    result.repetitions = quick ? 1 : 3;
    result.allThreads = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
    result.embree = embreeAvailable();

    std::vector<std::string> accels{"bvh"};
    if (result.embree) accels.push_back("embree");
    std::vector<int> threadCounts{1};
    if (result.allThreads > 1) threadCounts.push_back(result.allThreads);

    const std::size_t gridSide = quick ? 224 : 708;
    const std::string gridName = quick ? "grid-100k" : "grid-1M";
    const std::vector<BenchScene> scenes{{"CornellBox-Original", "cornell-original.toml"},
                                         {"CornellBox-Sphere", "cornell-sphere.toml"},
                                         {"bunny", "bunny.toml"},
                                         {"dragon", "dragon.toml"},
                                         {gridName, ""},
                                         {"CornellBox-Mirror", "cornell-mirror.toml"}};
    // Throughputs of the render scene (not tabled), to estimate the render's traversal time.
    std::vector<RayBenchmarkRow> renderSceneRows;
    for (const BenchScene& benchScene : scenes) {
        const bool renderSceneOnly = benchScene.name == "CornellBox-Mirror";
        const Scene scene =
            benchScene.file.empty() ? heightFieldScene(gridSide) : loadScene(directory / benchScene.file);
        // Triangles only: the comparison with Embree is on exactly the same primitives.
        const std::vector<Triangle>& triangles = scene.triangles;
        const double triangleCount = static_cast<double>(triangles.size());

        // Our build on 1 thread and on all, Embree's (on all its threads), interleaved.
        struct Build {
            std::string accel;
            int threads;
            std::vector<double> rates;
        };
        std::vector<Build> builds;
        for (int threads : threadCounts) builds.push_back({"bvh", threads, {}});
        if (result.embree) builds.push_back({"embree", result.allThreads, {}});
        std::vector<std::optional<SceneGeometry>> built(accels.size());
        for (int r = 0; r < result.repetitions; ++r) {
            for (Build& build : builds) {
                SceneGeometry geometry({}, {}, triangles, {}, build.accel == "bvh" ? Accelerator::Bvh : Accelerator::Embree,
                                       {}, static_cast<unsigned>(build.threads));
                build.rates.push_back(triangleCount / geometry.acceleratorStats().buildSeconds * 1e-6);
                if (r + 1 == result.repetitions) built[build.accel == "bvh" ? 0 : 1] = std::move(geometry);
            }
        }
        if (!renderSceneOnly)
            for (const Build& build : builds)
                result.rows.push_back({benchScene.name, "build", build.accel, build.threads, median(build.rates)});
        std::vector<SceneGeometry> geometries;
        for (std::optional<SceneGeometry>& geometry : built) geometries.push_back(std::move(*geometry));

        const Bounds box = triangleBox(triangles);
        const std::vector<Ray> primary = primaryRays(scene, result.primarySide);
        const std::vector<Ray> random = randomRays(box, result.randomRays);
        const Vec3 light = scene.lights.empty() ? box.hi : scene.lights.front()->position();
        const float lift = 1e-4f * glm::length(box.hi - box.lo);
        const std::vector<Ray> shadow = shadowRays(geometries.front(), primary, light, lift);

        if (result.embree) {
            // Same rays, two answers: how often the closest primitive differs (ties, shared edges).
            std::size_t differ = 0;
            for (const Ray& ray : random) {
                const auto ours = geometries[0].closestPrimitive(ray);
                const auto theirs = geometries[1].closestPrimitive(ray);
                if (ours.has_value() != theirs.has_value() || (ours && ours->primitive != theirs->primitive)) ++differ;
            }
            result.notes.push_back(benchScene.name + ": closest primitive differs from Embree's on " +
                                   std::to_string(differ) + " of " + std::to_string(random.size()) + " random rays");
        }

        std::vector<Measured> measured;
        for (const char* kind : {"primary", "random", "shadow"})
            for (const std::string& accel : accels)
                for (int threads : threadCounts) measured.push_back({kind, accel, threads, {}});
        for (int r = 0; r < result.repetitions; ++r) {
            for (Measured& m : measured) {  // interleaved: a burst of load hits every configuration
                const SceneGeometry& geometry = geometries[m.accel == "bvh" ? 0 : 1];
                const std::vector<Ray>& rays = m.rays == "primary" ? primary : m.rays == "random" ? random : shadow;
                std::atomic<std::size_t> hits{0};  // keeps the queries from being optimised away
                const bool closest = m.rays != "shadow";
                const double seconds = timeParallel(rays.size(), m.threads, [&](std::size_t begin, std::size_t end) {
                    std::size_t found = 0;
                    for (std::size_t i = begin; i < end; ++i)
                        found += closest ? geometry.closestPrimitive(rays[i]).has_value() : geometry.occluded(rays[i]);
                    hits += found;
                });
                m.rates.push_back(static_cast<double>(rays.size()) / seconds * 1e-6);
            }
        }
        for (const Measured& m : measured) {
            RayBenchmarkRow row{benchScene.name, m.rays, m.accel, m.threads, median(m.rates)};
            (renderSceneOnly ? renderSceneRows : result.rows).push_back(row);
        }
        log(benchScene.name + " done");
    }

    // End to end: the Whitted render of CornellBox-Mirror, every ray it casts per second.
    Scene scene = loadScene(directory / "cornell-mirror.toml");
    scene.camera.width = scene.camera.height = quick ? 256 : 1024;
    const AovSet aovs(classesSet());
    for (const std::string& accel : accels) {
        RenderOptions options;
        options.integrator = "whitted";
        options.threads = result.allThreads;
        options.accelerator = accel == "bvh" ? Accelerator::Bvh : Accelerator::Embree;
        const Renderer renderer(scene, aovs, options);
        std::vector<double> seconds;
        RenderStats stats;
        for (int r = 0; r < result.repetitions; ++r) {
            stats = renderer.render().stats;
            seconds.push_back(stats.seconds);
        }
        RenderThroughput t;
        t.accel = accel;
        t.threads = result.allThreads;
        t.seconds = median(seconds);
        t.rays = stats.rays.total();
        t.millionRaysPerSecond = static_cast<double>(t.rays) / t.seconds * 1e-6;
        const auto rate = [&](const char* kind) {
            for (const RayBenchmarkRow& row : renderSceneRows)
                if (row.rays == kind && row.accel == accel && row.threads == result.allThreads)
                    return row.millionsPerSecond * 1e6;
            return 0.0;
        };
        const RayCounters& c = stats.rays;
        // Camera rays are coherent like the primary set, mirror and glass rays incoherent like the
        // random set, shadow rays like the shadow set.
        t.traversalSeconds = static_cast<double>(c.camera) / rate("primary") +
                             static_cast<double>(c.reflection + c.refraction) / rate("random") +
                             static_cast<double>(c.shadow) / rate("shadow");
        t.shadingOverhead = (t.seconds - t.traversalSeconds) / t.traversalSeconds;
        result.renders.push_back(t);
        log("render with " + accel + " done");
    }
    return result;
}

}  // namespace lightpath
