// CoplanarTriangleIndex (radiosity's lookup on a plane's many triangles): its candidates for a
// point must include every triangle whose barycentric test accepts the point within the slack
// radiosity's lookup allows (RadiosityMesh::lookupTriangle), found here by testing all of them.
#include <doctest/doctest.h>

#include <cmath>
#include <set>
#include <vector>

#include "integrators/coplanar_triangle_index.h"
#include "math/random.h"

namespace lightpath {
namespace {

using Corners = CoplanarTriangleIndex::Corners;

// The point's barycentric coordinates along b - a and c - a, by least squares (lookupTriangle's).
bool holdsWithSlack(const Corners& t, const Vec3& point, double slack) {
    const Vec3 e1 = t[1] - t[0], e2 = t[2] - t[0], d = point - t[0];
    const double d00 = glm::dot(e1, e1), d01 = glm::dot(e1, e2), d11 = glm::dot(e2, e2);
    const double d20 = glm::dot(d, e1), d21 = glm::dot(d, e2);
    const double den = d00 * d11 - d01 * d01;
    const double s = (d11 * d20 - d01 * d21) / den, u = (d00 * d21 - d01 * d20) / den;
    return s >= -slack && u >= -slack && s + u <= 1.0 + slack;
}

// Triangles of a tilted plane at radiosity's range of sizes: a fine grid of squares inside, and
// three rings of squares around it, each ring's 4x larger than the last's (the central four of each
// ring's 4 x 4 are left out: the rings need not tile exactly to test the index).
std::vector<Corners> tiledPlane(const Vec3& origin, const Vec3& u, const Vec3& v) {
    std::vector<Corners> triangles;
    const auto at = [&](float x, float y) { return origin + x * u + y * v; };
    const auto square = [&](float x0, float y0, float size) {
        triangles.push_back({at(x0, y0), at(x0 + size, y0), at(x0 + size, y0 + size)});
        triangles.push_back({at(x0, y0), at(x0 + size, y0 + size), at(x0, y0 + size)});
    };
    for (int i = 0; i < 16; ++i)
        for (int j = 0; j < 16; ++j) square(i * 0.25f - 2.0f, j * 0.25f - 2.0f, 0.25f);
    for (float outer : {8.0f, 32.0f, 128.0f})
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j)
                if ((i == 0 || i == 3) || (j == 0 || j == 3)) square(-outer + i * outer / 2.0f, -outer + j * outer / 2.0f, outer / 2.0f);
    return triangles;
}

TEST_CASE("CoplanarTriangleIndex: every triangle that holds a point (with lookup's slack) is a candidate, and few others are") {
    const Vec3 u = glm::normalize(Vec3{1.0f, 0.2f, -0.3f});
    const Vec3 v = glm::normalize(glm::cross(Vec3{0.1f, 1.0f, 0.4f}, u));
    const Vec3 origin{3.0f, -1.0f, 2.0f};
    const std::vector<Corners> triangles = tiledPlane(origin, u, v);
    const auto index = CoplanarTriangleIndex::build(triangles, 1e-3f);
    REQUIRE(index);
    Pcg32 random(7, 1);
    std::size_t candidates = 0, missed = 0, points = 0;
    for (int k = 0; k < 20000; ++k) {
        // Points over the whole tiling, many near its fine edges, each off the plane by roundoff.
        const float scale = k % 2 == 0 ? 2.5f : 40.0f;
        float x = (random.nextFloat() * 2.0f - 1.0f) * scale, y = (random.nextFloat() * 2.0f - 1.0f) * scale;
        if (k % 3 == 0) x = std::round(x * 4.0f) / 4.0f;  // on an edge of the fine grid
        const Vec3 point = origin + x * u + y * v + glm::cross(u, v) * (random.nextFloat() - 0.5f) * 1e-5f;
        std::set<std::uint32_t> found;
        index->forEachCandidate(point, [&](std::uint32_t i) { found.insert(i); });
        candidates += found.size();
        ++points;
        for (std::uint32_t i = 0; i < triangles.size(); ++i)
            if (holdsWithSlack(triangles[i], point, 1e-4) && !found.count(i)) ++missed;
    }
    CHECK(missed == 0);
    CAPTURE(double(candidates) / double(points));
    CHECK(double(candidates) / double(points) < 8.0);
}

TEST_CASE("CoplanarTriangleIndex: triangles off one plane, or degenerate, get no index") {
    std::vector<Corners> triangles{{Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}}, {Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 0, 1}}};
    CHECK_FALSE(CoplanarTriangleIndex::build(triangles, 1e-3f));
    triangles[1] = {Vec3{0, 0, 0.01f}, Vec3{1, 0, 0.01f}, Vec3{0, 1, 0.01f}};  // parallel, another plane
    CHECK_FALSE(CoplanarTriangleIndex::build(triangles, 1e-3f));
    triangles[1] = {Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{2, 0, 0}};
    CHECK_FALSE(CoplanarTriangleIndex::build(triangles, 1e-3f));
    triangles[1] = {Vec3{1, 1, 0}, Vec3{0, 1, 0}, Vec3{1, 0, 0}};
    CHECK(CoplanarTriangleIndex::build(triangles, 1e-3f));
}

}  // namespace
}  // namespace lightpath
