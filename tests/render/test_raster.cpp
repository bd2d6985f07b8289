// The rasteriser (issue "Slides a lecturer uses", figure 1): "ray casting is just rasterisation
// with a different order of the for loops". On every shipped scene, the z-buffer's image and ray
// casting's without shadow rays agree in every layer (beauty and AOVs) on every pixel whose
// neighbours see the same object; they may differ only on edge pixels, where the two visibility
// methods sample a silhouette differently. The edge pixels come from the ray caster's own hits
// (SceneGeometry::intersect through each pixel centre), not from the rasteriser. A control must
// fail: with shadow rays on, ray casting differs from the rasteriser off the edges.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "film/aov_presets.h"
#include "film/aov_set.h"
#include "integrators/raster.h"
#include "render/renderer.h"
#include "scene/scene_loader.h"
#include "../support/shipped_scenes.h"

namespace lightpath {
namespace {

// An interior pixel's layers agree to this fraction of the pixel's brightest channel (or of 1 in
// the dark): the two methods compute the same surface point from different formulas (perspective-
// correct barycentrics and edge functions, against Woop et al.'s watertight test), so they differ
// by rounding, about 1e-6; half a pixel's shift in the rasteriser's sample positions is about 1e-3.
constexpr double kInteriorTolerance = 1e-4;

struct Comparison {
    int interiorPixels = 0;
    int edgePixels = 0;        // pixels a neighbour of which (or which itself) sees another object
    int interiorDiffering = 0;  // interior pixels over the tolerance
    int edgeDiffering = 0;
    double maxInterior = 0.0;  // largest relative difference of an interior pixel
};

// The object each pixel centre sees, by the ray caster's closest hit; -1 for the background.
std::vector<std::int64_t> objectsSeen(const Scene& scene) {
    const SceneGeometry geometry(scene.spheres, scene.planes, scene.triangles, NumericsOptions{}, Accelerator::Bvh,
                                 scene.triangleNormals, 0, scene.shapes, scene.triangleUvs, scene.triangleTangents,
                                 scene.objectCoverage(), scene.triangleColors);
    const Camera camera(scene.camera);
    std::vector<std::int64_t> objects;
    for (int y = 0; y < camera.height(); ++y) {
        for (int x = 0; x < camera.width(); ++x) {
            const auto hit = geometry.intersect(camera.generateRay(float(x) + 0.5f, float(y) + 0.5f));
            objects.push_back(hit ? std::int64_t{hit->object} : -1);
        }
    }
    return objects;
}

Film renderWith(const Scene& scene, const AovSet& aovs, const std::string& integrator, std::optional<bool> shadows) {
    RenderOptions options;
    options.integrator = integrator;
    options.shadows = shadows;
    return Renderer(scene, aovs, options).render().film;
}

Comparison compare(const Scene& scene, const Film& a, const Film& b) {
    const std::vector<std::int64_t> objects = objectsSeen(scene);
    const int w = a.width(), h = a.height();
    const auto seen = [&](int x, int y) { return objects[static_cast<std::size_t>(y) * w + x]; };
    Comparison c;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            bool edge = false;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int nx = std::clamp(x + dx, 0, w - 1), ny = std::clamp(y + dy, 0, h - 1);
                    edge = edge || seen(nx, ny) != seen(x, y);
                }
            double difference = 0.0, scale = 1.0;
            for (std::size_t l = 0; l < a.layerCount(); ++l) {
                const Rgb p = a.at(l, x, y), q = b.at(l, x, y);
                difference = std::max({difference, double(std::fabs(p.r - q.r)), double(std::fabs(p.g - q.g)),
                                       double(std::fabs(p.b - q.b))});
                scale = std::max({scale, double(p.r), double(p.g), double(p.b)});
            }
            const double relative = difference / scale;
            if (edge) {
                ++c.edgePixels;
                c.edgeDiffering += relative > kInteriorTolerance;
            } else {
                ++c.interiorPixels;
                c.interiorDiffering += relative > kInteriorTolerance;
                c.maxInterior = std::max(c.maxInterior, relative);
            }
        }
    }
    return c;
}

TEST_CASE("the rasteriser and ray casting without shadows agree off the edges on every shipped scene" * doctest::test_suite("statistical")) {
    const AovSet aovs(classesSet());
    double worstInterior = 0.0;
    int edgeDiffering = 0, edgePixels = 0, pixels = 0;
    for (const std::filesystem::path& path : test::shippedScenes()) {
        CAPTURE(path.filename().string());
        const Scene scene = loadScene(path.string());
        if (!scene.media.empty()) continue;  // the rasteriser refuses media (RenderConfig::judge)
        const Comparison c =
            compare(scene, renderWith(scene, aovs, "raster", std::nullopt), renderWith(scene, aovs, "raycast", false));
        MESSAGE(path.filename().string() << ": " << c.interiorPixels << " interior pixels, largest relative difference "
                                         << c.maxInterior << "; " << c.edgeDiffering << " of " << c.edgePixels
                                         << " edge pixels differ");
        CHECK(c.interiorDiffering == 0);
        // The edges are silhouettes, not the whole image (a perforated screen and a pane of alpha 0.5,
        // whose pixels see it or the floor by chance, make 11% of perforated-screen.toml edges).
        CHECK(c.interiorPixels > 5 * c.edgePixels);
        worstInterior = std::max(worstInterior, c.maxInterior);
        edgeDiffering += c.edgeDiffering;
        edgePixels += c.edgePixels;
        pixels += c.interiorPixels + c.edgePixels;
    }
    MESSAGE("all scenes: " << pixels << " pixels, largest interior relative difference " << worstInterior << ", "
                           << edgeDiffering << " of " << edgePixels << " edge pixels differ");
    CHECK(worstInterior <= kInteriorTolerance);
}

// The scene's camera made orthographic, seeing at its look-at point what the pinhole saw there.
Scene orthographic(Scene scene) {
    CameraDescription& c = scene.camera;
    const float distance = glm::length(c.lookAt - c.eye);
    c.orthographicHeight = 2.0f * distance * std::tan(glm::radians(c.verticalFovDegrees) * 0.5f);
    c.projection = Projection::Orthographic;
    return scene;
}

TEST_CASE("under an orthographic camera too, the rasteriser and ray casting agree off the edges on every shipped scene" *
          doctest::test_suite("statistical")) {
    const AovSet aovs(classesSet());
    int edgePixels = 0, pixels = 0;
    for (const std::filesystem::path& path : test::shippedScenes()) {
        CAPTURE(path.filename().string());
        const Scene scene = orthographic(loadScene(path.string()));
        if (!scene.media.empty()) continue;
        const Comparison c =
            compare(scene, renderWith(scene, aovs, "raster", std::nullopt), renderWith(scene, aovs, "raycast", false));
        CAPTURE(c.maxInterior);
        CHECK(c.interiorDiffering == 0);
        CHECK(c.interiorPixels > 5 * c.edgePixels);
        edgePixels += c.edgePixels;
        pixels += c.interiorPixels + c.edgePixels;
    }
    MESSAGE("orthographic, all scenes: " << pixels << " pixels, " << edgePixels << " on edges");
}

// A sphere about 450 pixels across under `camera`: the z-buffer keeps exactly the pixels whose
// centre's ray meets it, each at the ray's own t.
void checkSphereCoverage(const Camera& camera) {
    const SceneGeometry geometry({Sphere{Vec3{0.1f, -0.05f, 0.0f}, 1.8f, 0}}, {}, {});
    const ZBuffer zBuffer(geometry, camera);
    int seen = 0, wrong = 0;
    for (int y = 0; y < camera.height(); ++y) {
        for (int x = 0; x < camera.width(); ++x) {
            const float t = geometry.intersectPrimitive(camera.generateRay(float(x) + 0.5f, float(y) + 0.5f), 0);
            const RasterFragment& kept = zBuffer.at(x, y);
            seen += t != kNoHit;
            if ((t != kNoHit) != (kept.primitive == 0) || (t != kNoHit && kept.t != t)) ++wrong;
        }
    }
    CHECK(seen > 100000);
    CHECK(wrong == 0);
}

TEST_CASE("under an orthographic camera the rasteriser covers exactly the pixels whose centre's ray meets a sphere") {
    CameraDescription description;  // at (0, 0, 5) looking down -z
    description.projection = Projection::Orthographic;
    description.orthographicHeight = 4.0f;
    const Camera camera(description);
    checkSphereCoverage(camera);
    // A triangle through the film (z = 5): only its part in front, where the rays start, is seen.
    const SceneGeometry through({}, {}, {Triangle{{-3, -2, 7}, {3, -2, 7}, {0, 2, 3}, 0}});
    const ZBuffer crossing(through, camera);
    int front = 0, differing = 0, behind = 0;
    for (int y = 0; y < camera.height(); ++y) {
        for (int x = 0; x < camera.width(); ++x) {
            const float t = through.intersectPrimitive(camera.generateRay(float(x) + 0.5f, float(y) + 0.5f), 0);
            const RasterFragment& kept = crossing.at(x, y);
            front += t != kNoHit;
            behind += kept.primitive == 0 && t == kNoHit;
            if ((t != kNoHit) != (kept.primitive == 0) || (t != kNoHit && std::fabs(kept.t - t) > 1e-4f * t)) ++differing;
        }
    }
    CHECK(front > 10000);
    CHECK(behind == 0);
    CHECK(differing <= front / 1000);  // the line where it crosses the film: t near 0 rounds either way
}

TEST_CASE("the control: with shadow rays, ray casting differs from the rasteriser off the edges") {
    const AovSet aovs(classesSet());
    for (const char* name : {"lecture-room.toml", "cornell-sphere.toml"}) {
        CAPTURE(name);
        const Scene scene = loadScene(std::string(LIGHTPATH_SOURCE_DIR "/scenes/") + name);
        const Comparison c =
            compare(scene, renderWith(scene, aovs, "raster", std::nullopt), renderWith(scene, aovs, "raycast", true));
        MESSAGE(std::string(name) << " with shadow rays: " << c.interiorDiffering << " of " << c.interiorPixels
                     << " interior pixels differ");
        CHECK(c.interiorDiffering > c.interiorPixels / 20);
    }
}

TEST_CASE("the rasteriser tests no pixel for a sphere behind the camera, and the pixels of its bounds for one in front") {
    CameraDescription description;  // at (0, 0, 5) looking down -z
    description.width = 64;
    description.height = 48;
    const Camera camera(description);
    const auto tested = [&](Vec3 center) {
        const SceneGeometry geometry({Sphere{center, 0.5f, 0}}, {}, {});
        return ZBuffer(geometry, camera).pixelsTested();
    };
    // Behind the eye, every corner of its bounding box lies behind the eye's plane: nothing can be
    // covered, and nothing is tested (each impostor facet the sphere once had scanned the whole
    // film, 2 x 256 x 128 x 64 x 48 tests).
    CHECK(tested({0.0f, 0.0f, 8.0f}) == 0);
    // In front, each of the box's triangles tests its projected bounding box: between the sphere's
    // image and a generous multiple of the film.
    const std::uint64_t front = tested({0.0f, 0.0f, 0.0f});
    CHECK(front > 0);
    CHECK(front < 1000u * 64u * 48u);
}

TEST_CASE("the rasteriser covers exactly the pixels whose centre's ray meets a sphere, silhouette included") {
    // A sphere about 450 pixels across: facets with corners on it (the 256-sector impostor it was
    // once covered by) lose the pixel centres between a chord and the arc of its outline; its
    // bounding box loses none, and each pixel keeps the true sphere's hit.
    CameraDescription description;  // at (0, 0, 5) looking down -z
    const Camera camera(description);
    checkSphereCoverage(camera);
}

TEST_CASE("the rasteriser refuses what it cannot do, and shadow rays stay on where they must") {
    const Scene scene = loadScene(LIGHTPATH_SOURCE_DIR "/scenes/cornell-sphere.toml");
    const AovSet aovs(classesSet());
    RenderOptions options;
    options.integrator = "raster";
    options.samplesPerPixel = 4;
    CHECK_THROWS_WITH_AS(Renderer(scene, aovs, options), doctest::Contains("once, at its centre"), std::invalid_argument);
    options.samplesPerPixel = 1;
    options.shadows = true;
    CHECK_THROWS_WITH_AS(Renderer(scene, aovs, options), doctest::Contains("no shadows"), std::invalid_argument);
    for (const char* integrator : {"path", "bdpt", "radiosity"}) {
        CAPTURE(integrator);
        options.integrator = integrator;
        options.shadows = false;
        CHECK_THROWS_WITH_AS(Renderer(scene, aovs, options), doctest::Contains("cannot be switched off"),
                             std::invalid_argument);
    }
    for (const char* integrator : {"raycast", "whitted"}) {
        options.integrator = integrator;
        options.shadows = false;
        CHECK_NOTHROW(Renderer(scene, aovs, options));
    }
}

}  // namespace
}  // namespace lightpath
