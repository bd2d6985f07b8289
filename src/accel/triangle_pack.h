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

namespace lightpath {

// Coordinates as corners[vertex][axis][lane]: vertex 0, 1, 2 are a triangle's a, b, c.
struct alignas(16) TrianglePack {
    float corners[3][3][kBvhWidth]{};

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

// The lanes of `lanes` whose triangle the watertight test may hit in (tMin, ray.tMax): the edge
// functions agree in sign, the determinant is non-zero and t is in range; and every lane with an
// edge function of exactly zero, which the scalar test recomputes in double.
inline int watertightCandidates(const TrianglePack& pack, int lanes, const Ray& ray, const WatertightRay& sheared,
                                float tMin) {
    using simd::Float4;
    const int k[3] = {sheared.kx, sheared.ky, sheared.kz};
    Float4 x[3], y[3], z[3];
    const Float4 sx(sheared.sx), sy(sheared.sy), sz(sheared.sz);
    for (int v = 0; v < 3; ++v) {
        // permute(corner - origin) then the shear, as intersectTriangle does.
        const Float4 px = Float4::load(pack.corners[v][k[0]]) - Float4(ray.origin[k[0]]);
        const Float4 py = Float4::load(pack.corners[v][k[1]]) - Float4(ray.origin[k[1]]);
        const Float4 pz = Float4::load(pack.corners[v][k[2]]) - Float4(ray.origin[k[2]]);
        x[v] = px + sx * pz;
        y[v] = py + sy * pz;
        z[v] = pz;
    }
    // a, b, c = vertex 0, 1, 2.
    const Float4 u = x[2] * y[1] - y[2] * x[1];
    const Float4 v = x[0] * y[2] - y[0] * x[2];
    const Float4 w = x[1] * y[0] - y[1] * x[0];
    const Float4 zero(0.0f);
    const int onEdge = simd::equal(u, zero) | simd::equal(v, zero) | simd::equal(w, zero);
    const int negative = simd::less(u, zero) | simd::less(v, zero) | simd::less(w, zero);
    const int positive = simd::less(zero, u) | simd::less(zero, v) | simd::less(zero, w);
    const Float4 det = u + v + w;
    const Float4 t = (u * (sz * z[0]) + v * (sz * z[1]) + w * (sz * z[2])) / det;
    const int inRange = simd::less(Float4(tMin), t) & simd::less(t, Float4(ray.tMax));
    const int passes = ~(negative & positive) & ~simd::equal(det, zero) & inRange;
    return lanes & (onEdge | passes);
}

}  // namespace lightpath
