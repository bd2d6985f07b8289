#pragma once
// The triangles of one BVH leaf block, laid out for four-at-once tests, and the SIMD half of the
// watertight test (Woop, Benthin and Wald, JCGT 2013) over them. The SIMD part only filters: it
// evaluates the same float expressions as intersectTriangle (geometry/intersect.cpp) in the
// same order, lane by lane, so a lane it drops is one the scalar test rejects too; the lanes it
// keeps go to the scalar test, whose answer is final. Hence results stay bit for bit those of
// testing each triangle alone.
#include "accel/bvh.h"
#include "accel/simd.h"
#include "geometry/intersect.h"
#include "geometry/shapes.h"
#include "math/ray.h"

#include <glm/gtc/type_ptr.hpp>

namespace lightpath {

// Coordinates as corners[vertex][axis][lane]: vertex 0, 1, 2 are a triangle's a, b, c.
// No initializer: SceneGeometry writes every lane of every block, zeros in padding lanes.
struct alignas(16) TrianglePack {
    float corners[3][3][kBvhLeafSize];

    void clear(int lane) {
        for (int v = 0; v < 3; ++v)
            for (int a = 0; a < 3; ++a) corners[v][a][lane] = 0.0f;
    }
    void set(int lane, const Triangle& t) {
        const Vec3* vertices[3] = {&t.a, &t.b, &t.c};
        for (int v = 0; v < 3; ++v)
            for (int a = 0; a < 3; ++a) corners[v][a][lane] = (*vertices[v])[a];
    }
    Triangle triangle(int lane) const {
        Triangle t;
        Vec3* vertices[3] = {&t.a, &t.b, &t.c};
        for (int v = 0; v < 3; ++v)
            for (int a = 0; a < 3; ++a) (*vertices[v])[a] = corners[v][a][lane];
        return t;
    }
};
static_assert(sizeof(TrianglePack) == 144);

// The per-ray part of the test, computed once per ray: the watertight shear, and the origin
// permuted like the vertices and broadcast to four lanes.
struct PackedRay {
    WatertightRay sheared;
    int k[3];
    simd::Float4 origin[3];
    simd::Float4 sx, sy, sz;

    explicit PackedRay(const Ray& ray)
        : sheared(ray.direction), k{sheared.kx, sheared.ky, sheared.kz}, sx(sheared.sx), sy(sheared.sy),
          sz(sheared.sz) {
        const float* o = glm::value_ptr(ray.origin);  // indexed loads: glm's operator[] is a switch
        for (int i = 0; i < 3; ++i) origin[i] = simd::Float4(o[k[i]]);
    }
};

// What the four-at-once watertight test found among the lanes it was given.
struct PackHits {
    int hits = 0;    // lanes hit at t[lane], exactly as intersectTriangle finds them
    int onEdge = 0;  // lanes with an edge function of exactly zero: intersectTriangle decides them
    alignas(16) float t[kBvhLeafSize];
    // The edge functions (the weights of a, b, c before division) and their sum, valid in the
    // hit lanes: a hit's barycentrics are {u, v, w} / det, as intersectTriangle computes them.
    // Kept in registers, read only for a hit that becomes the nearest (any-hit never reads them).
    simd::Float4 u, v, w, det;

    Vec4 edges(int lane) const {
        alignas(16) float lanes[4][kBvhLeafSize];
        u.store(lanes[0]);
        v.store(lanes[1]);
        w.store(lanes[2]);
        det.store(lanes[3]);
        return {lanes[0][lane], lanes[1][lane], lanes[2][lane], lanes[3][lane]};
    }
};

// intersectTriangle (geometry/intersect.cpp) on the lanes of `lanes`: the same float expressions
// in the same order, so a lane's t and verdict are bit for bit the scalar test's. Only the rare
// lane where an edge function rounds to exactly zero, which the scalar test recomputes in double,
// is left to it. Always inlined: GCC had made it a call per leaf (callgrind on bunny shadow rays:
// the call and its loads cost 11% of the instructions).
[[gnu::always_inline]] inline PackHits watertightHits(const TrianglePack& pack, int lanes, const PackedRay& ray, float tMin, float tMax) {
    using simd::Float4;
    Float4 x[3], y[3], z[3];
    for (int v = 0; v < 3; ++v) {
        // permute(corner - origin) then the shear.
        const Float4 px = Float4::load(pack.corners[v][ray.k[0]]) - ray.origin[0];
        const Float4 py = Float4::load(pack.corners[v][ray.k[1]]) - ray.origin[1];
        const Float4 pz = Float4::load(pack.corners[v][ray.k[2]]) - ray.origin[2];
        x[v] = px + ray.sx * pz;
        y[v] = py + ray.sy * pz;
        z[v] = ray.sz * pz;
    }
    // a, b, c = vertex 0, 1, 2.
    const Float4 u = x[2] * y[1] - y[2] * x[1];
    const Float4 v = x[0] * y[2] - y[0] * x[2];
    const Float4 w = x[1] * y[0] - y[1] * x[0];
    const Float4 zero(0.0f);
    PackHits result;
    result.onEdge = lanes & (simd::equal(u, zero) | simd::equal(v, zero) | simd::equal(w, zero));
    // Some edge function negative and some positive: min < 0 < max. A NaN one makes det and t
    // NaN, so its lane is no hit whatever these say, as in the scalar test.
    const Float4 lowest = simd::minKeepSecond(u, simd::minKeepSecond(v, w));
    const Float4 highest = simd::maxKeepSecond(u, simd::maxKeepSecond(v, w));
    const int inside = lanes & ~result.onEdge & ~(simd::less(lowest, zero) & simd::less(zero, highest));
    if (inside == 0) return result;  // most leaves a ray enters: no division needed
    const Float4 det = u + v + w;
    const Float4 t = (u * z[0] + v * z[1] + w * z[2]) / det;
    const int hits = inside & ~simd::equal(det, zero) & simd::less(Float4(tMin), t) & simd::less(t, Float4(tMax));
    if (hits == 0) return result;
    // The bound of t's rounding error (pbrt-v4, section 6.8.4), as intersectTriangle computes it.
    const auto max3 = [](Float4 a, Float4 b, Float4 c) {
        return simd::maxKeepSecond(simd::maxKeepSecond(simd::abs(a), simd::abs(b)), simd::abs(c));
    };
    const Float4 maxZ = max3(z[0], z[1], z[2]);
    const Float4 maxX = max3(x[0], x[1], x[2]);
    const Float4 maxY = max3(y[0], y[1], y[2]);
    const Float4 deltaZ = Float4(roundingGamma(3)) * maxZ;
    const Float4 deltaX = Float4(roundingGamma(5)) * (maxX + maxZ);
    const Float4 deltaY = Float4(roundingGamma(5)) * (maxY + maxZ);
    const Float4 deltaE = Float4(2.0f) * (Float4(roundingGamma(2)) * maxX * maxY + deltaY * maxX + deltaX * maxY);
    const Float4 maxE = max3(u, v, w);
    const Float4 deltaT =
        Float4(3.0f) * (Float4(roundingGamma(3)) * maxE * maxZ + deltaE * maxZ + deltaZ * maxE) / simd::abs(det);
    result.hits = hits & ~simd::lessEqual(t, deltaT);
    t.store(result.t);
    result.u = u;
    result.v = v;
    result.w = w;
    result.det = det;
    return result;
}

}  // namespace lightpath
