// The samplers' defining properties, checked as mathematical facts: strata hold one sample each,
// scrambled Sobol points form (0,m,2)-nets in base 2, and all are deterministic per pixel.
#include <doctest/doctest.h>

#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "film/aov_set.h"
#include "render/renderer.h"
#include "sampling/sampler.h"
#include "scene_builder.h"

namespace lightpath {
namespace {

std::vector<Vec2> firstPoints(SamplerKind kind, int count, int dimensionPair, std::uint64_t seed) {
    std::vector<Vec2> points;
    for (int i = 0; i < count; ++i) {
        Sampler sampler = Sampler::forPixel(kind, 17, 42, i, count, seed);
        Vec2 p{0.0f};
        for (int d = 0; d <= dimensionPair; ++d) p = sampler.next2D();
        points.push_back(p);
    }
    return points;
}

// Every elementary interval [a/2^i, (a+1)/2^i) x [b/2^j, (b+1)/2^j) with i + j = m holds exactly one point.
bool isZeroNet(const std::vector<Vec2>& points, int m) {
    for (int i = 0; i <= m; ++i) {
        const int cx = 1 << i, cy = 1 << (m - i);
        std::set<int> cells;
        for (const Vec2& p : points) {
            if (p.x < 0.0f || p.x >= 1.0f || p.y < 0.0f || p.y >= 1.0f) return false;
            cells.insert(static_cast<int>(p.x * cx) * cy + static_cast<int>(p.y * cy));
        }
        if (cells.size() != points.size()) return false;
    }
    return true;
}

TEST_CASE("sobol: the first 2^m samples of every dimension pair form a (0,m,2)-net") {
    for (int m : {2, 4, 6, 8}) {
        for (int pair = 0; pair < 4; ++pair) {
            CAPTURE(m);
            CAPTURE(pair);
            CHECK(isZeroNet(firstPoints(SamplerKind::Sobol, 1 << m, pair, 3), m));
        }
    }
}

TEST_CASE("sobol: the second dimension is the index times Pascal's triangle mod 2") {
    // The generator matrix of Sobol's second dimension (polynomial x + 1) has C(k, m) mod 2 in row
    // m, column k (Joe and Kuo's direction numbers for it are all 1): built here by the triangle's
    // own recurrence, then applied bit by bit.
    bool odd[32][32] = {};
    for (int k = 0; k < 32; ++k) {
        odd[k][0] = true;
        for (int m = 1; m <= k; ++m) odd[k][m] = odd[k - 1][m - 1] != odd[k - 1][m];
    }
    const auto reference = [&](std::uint32_t index) {
        std::uint32_t result = 0;
        for (int m = 0; m < 32; ++m) {
            bool bit = false;
            for (int k = 0; k < 32; ++k) bit = bit != (((index >> k) & 1u) != 0 && odd[k][m]);
            if (bit) result |= 1u << (31 - m);
        }
        return result;
    };
    std::vector<std::uint32_t> indices{0u, 1u, 2u, 3u, 0x7fffffffu, 0x80000000u, 0xffffffffu, 0xaaaaaaaau, 0x55555555u};
    for (int k = 0; k < 32; ++k) indices.push_back(1u << k);
    Pcg32 rng(7, 11);
    for (int i = 0; i < 100000; ++i) indices.push_back(rng.nextUint());
    for (std::uint32_t index : indices) {
        CAPTURE(index);
        REQUIRE(sobolDimension1(index) == reference(index));
    }
    CHECK(sobolDimension1(1) == 0x80000000u);  // the first points: 1/2, then 3/4, 1/4
    CHECK(sobolDimension1(2) == 0xc0000000u);
    CHECK(sobolDimension1(3) == 0x40000000u);
}

// A number skipped (Sampler::skip2D, skip1D) and the same number drawn (next2D, next1D).
struct Skip {
    const char* what;
    void (*draw)(Sampler&);
    void (*skip)(Sampler&);
};

TEST_CASE("skipping a dimension pair or one dimension leaves every later number as drawing it would") {
    const Skip skips[] = {
        {"a dimension pair", [](Sampler& s) { s.next2D(); }, [](Sampler& s) { s.skip2D(); }},
        {"one dimension", [](Sampler& s) { s.next1D(); }, [](Sampler& s) { s.skip1D(); }},
    };
    for (const Skip& skip : skips) {
        for (SamplerKind kind : {SamplerKind::Independent, SamplerKind::Stratified, SamplerKind::Sobol}) {
            for (int spp : {1, 9, 12}) {
                // Skipped first, and after a pair drawn by both.
                for (int drawnBefore : {0, 1}) {
                    const std::string what = skip.what;
                    CAPTURE(what);
                    CAPTURE(samplerName(kind));
                    CAPTURE(spp);
                    CAPTURE(drawnBefore);
                    Sampler drawn = Sampler::forPixel(kind, 3, 5, spp - 1, spp, 77);
                    Sampler skipped = Sampler::forPixel(kind, 3, 5, spp - 1, spp, 77);
                    for (int i = 0; i < drawnBefore; ++i) {
                        drawn.next2D();
                        skipped.next2D();
                    }
                    skip.draw(drawn);
                    skip.skip(skipped);
                    CHECK(drawn.next1D() == skipped.next1D());
                    CHECK(drawn.next2D() == skipped.next2D());
                    CHECK(drawn.forVertex(99).next1D() == skipped.forVertex(99).next1D());
                    CHECK(drawn.forVertex(99).next2D() == skipped.forVertex(99).next2D());
                }
            }
        }
    }
}

TEST_CASE("a vertex's sampler is the sampler made from the pixel's kind, index and count with the vertex's seed") {
    // forVertex copies what depends only on the kind, index and count; the reference builds it anew.
    for (SamplerKind kind : {SamplerKind::Independent, SamplerKind::Stratified, SamplerKind::Sobol}) {
        for (int spp : {1, 7, 9, 16}) {
            for (int index : {0, spp / 2, spp - 1}) {
                for (const std::uint64_t key : {0ull, 99ull, 0x9e3779b97f4a7c15ull}) {
                    CAPTURE(samplerName(kind));
                    CAPTURE(spp);
                    CAPTURE(index);
                    CAPTURE(key);
                    const std::uint64_t seed = 0x1234567ull + static_cast<std::uint64_t>(index);
                    Sampler parent(kind, seed, index, spp);
                    parent.next2D();  // the parent's own dimensions do not move the vertex's
                    Sampler vertex = parent.forVertex(key);
                    Sampler reference(kind, mixBits(seed ^ key), index, spp);
                    for (int d = 0; d < 6; ++d) {
                        CHECK(vertex.next1D() == reference.next1D());
                        CHECK(vertex.next2D() == reference.next2D());
                    }
                }
            }
        }
    }
}

TEST_CASE("stratified: one sample per stratum, grid for square counts, Latin hypercube otherwise") {
    const auto grid = firstPoints(SamplerKind::Stratified, 16, 1, 9);
    std::set<int> cells;
    for (const Vec2& p : grid) cells.insert(static_cast<int>(p.x * 4) * 4 + static_cast<int>(p.y * 4));
    CHECK(cells.size() == 16);
    const auto rooks = firstPoints(SamplerKind::Stratified, 12, 2, 9);
    std::set<int> columns, rows;
    for (const Vec2& p : rooks) {
        columns.insert(static_cast<int>(p.x * 12));
        rows.insert(static_cast<int>(p.y * 12));
    }
    CHECK(columns.size() == 12);
    CHECK(rows.size() == 12);
}

TEST_CASE("independent points are not a net, and every sampler is deterministic") {
    CHECK_FALSE(isZeroNet(firstPoints(SamplerKind::Independent, 64, 0, 1), 6));
    for (SamplerKind kind : {SamplerKind::Independent, SamplerKind::Stratified, SamplerKind::Sobol}) {
        const auto a = firstPoints(kind, 32, 1, 5), b = firstPoints(kind, 32, 1, 5), c = firstPoints(kind, 32, 1, 6);
        CHECK(a == b);
        CHECK(a != c);
    }
}

TEST_CASE("low discrepancy integrates a smooth function with less error than independent points") {
    // The integral of x y over the unit square is 1/4; mean squared error over many pixels.
    auto meanSquaredError = [](SamplerKind kind) {
        double total = 0.0;
        for (std::uint64_t seed = 0; seed < 200; ++seed) {
            double sum = 0.0;
            for (const Vec2& p : firstPoints(kind, 64, 0, seed)) sum += double(p.x) * p.y;
            total += (sum / 64 - 0.25) * (sum / 64 - 0.25);
        }
        return total / 200;
    };
    const double independent = meanSquaredError(SamplerKind::Independent);
    CHECK(meanSquaredError(SamplerKind::Stratified) < independent / 4);
    CHECK(meanSquaredError(SamplerKind::Sobol) < independent / 16);
}

TEST_CASE("adaptive sampling stops converged pixels and keeps sampling noisy ones") {
    // The camera looks at the horizon: the top half of the image is black sky (zero variance,
    // converged at the minimum of 8 samples), the bottom half a floor under a small area light.
    Scene scene;
    scene.camera = test::centredCamera({0, 1, 0}, {0, 1, -1}, {0, 1, 0}, 24);
    PhongMaterial floor, lamp;
    floor.name = "floor";
    floor.kd = Rgb{0.5f};
    lamp.name = "lamp";
    lamp.emission = Rgb{20.0f};
    test::addPlane(scene, "floor", test::addMaterial(scene, floor), {0, 0, 0}, {0, 1, 0});
    const std::uint32_t lampObject = test::addObject(scene, "lamp", test::addMaterial(scene, lamp));
    scene.triangles.push_back({{-0.2f, 0.8f, -2.0f}, {0.0f, 0.8f, -2.3f}, {0.2f, 0.8f, -2.0f}, lampObject});
    const Triangle& t = scene.triangles.back();
    REQUIRE(glm::cross(t.b - t.a, t.c - t.a).y < 0.0f);  // the lamp shines down onto the floor

    const AovSet aovs(std::vector<lpe::NamedExpression>{});
    RenderOptions options;
    options.integrator = "path";
    options.samplesPerPixel = 256;
    options.targetError = 0.05;
    const std::uint64_t samples = Renderer(scene, aovs, options).render().stats.samples;
    const std::uint64_t skyPixels = 24 * 12, floorPixels = 24 * 12;
    CHECK(samples <= skyPixels * 8 + floorPixels * 256);  // converged pixels cost nothing more
    CHECK(samples > skyPixels * 8 + floorPixels * 8);     // noisy ones keep sampling
}

}  // namespace
}  // namespace lightpath
