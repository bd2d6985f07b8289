#pragma once
// A scene's infinite planes, two to a pack, tested against a ray together: no box holds a plane,
// so every closest-hit and every shadow ray tests each of them (SceneGeometry). One plane through
// the shape table cost about 75 instructions (an indirect call, the record unpacked, the test);
// a pack of two about 30. The arithmetic is intersectPlane's (geometry/intersect.cpp), in double,
// lane by lane: the same IEEE operations in the same order (x86-64 SSE2 has no fused multiply-add),
// so a lane's t and verdict are bit for bit the scalar test's.
#include <cstdint>
#include <vector>

#include "accel/simd.h"
#include "geometry/shapes.h"
#include "math/ray.h"

namespace lightpath {

struct PlanePack {
    // normal[axis][lane], point[axis][lane]; a padding lane has a zero normal (parallel to every
    // ray: never hit) and id kNoPrimitive.
    alignas(16) double normal[3][2] = {};
    alignas(16) double point[3][2] = {};
    std::uint32_t ids[2] = {kNoPrimitive, kNoPrimitive};
};

// Packs `planes`, whose scene-wide ids are firstId, firstId + 1, ...
inline std::vector<PlanePack> packPlanes(const std::vector<Plane>& planes, std::uint32_t firstId) {
    std::vector<PlanePack> packs((planes.size() + 1) / 2);
    for (std::size_t i = 0; i < planes.size(); ++i) {
        PlanePack& pack = packs[i / 2];
        const std::size_t lane = i % 2;
        for (int axis = 0; axis < 3; ++axis) {
            pack.normal[axis][lane] = planes[i].normal[axis];
            pack.point[axis][lane] = planes[i].point[axis];
        }
        pack.ids[lane] = firstId + static_cast<std::uint32_t>(i);
    }
    return packs;
}

// The lanes of `pack` that `ray` hits in (ray.tMin, ray.tMax) (bit l: lane l), t[l] their
// distances, as intersectPlane (with tMin = ray.tMin) finds them; the ray's ignored primitive
// is never hit.
[[gnu::always_inline]] inline int planeHits(const PlanePack& pack, const Ray& ray, float t[2]) {
    int hits = 0;
#ifdef LIGHTPATH_SSE2
    const auto load = [](const double* p) { return _mm_load_pd(p); };
    const auto dot = [](__m128d ax, __m128d ay, __m128d az, __m128d bx, __m128d by, __m128d bz) {
        // glm::dot's order: (x + y) + z.
        return _mm_add_pd(_mm_add_pd(_mm_mul_pd(ax, bx), _mm_mul_pd(ay, by)), _mm_mul_pd(az, bz));
    };
    const __m128d nx = load(pack.normal[0]), ny = load(pack.normal[1]), nz = load(pack.normal[2]);
    const __m128d denominator =
        dot(nx, ny, nz, _mm_set1_pd(ray.direction.x), _mm_set1_pd(ray.direction.y), _mm_set1_pd(ray.direction.z));
    const __m128d ax = _mm_sub_pd(load(pack.point[0]), _mm_set1_pd(ray.origin.x));
    const __m128d ay = _mm_sub_pd(load(pack.point[1]), _mm_set1_pd(ray.origin.y));
    const __m128d az = _mm_sub_pd(load(pack.point[2]), _mm_set1_pd(ray.origin.z));
    const __m128d td = _mm_div_pd(dot(ax, ay, az, nx, ny, nz), denominator);
    // denominator != 0 (true for a NaN, as in the scalar test), t > 0 (false for a NaN).
    hits = _mm_movemask_pd(_mm_and_pd(_mm_cmpneq_pd(denominator, _mm_setzero_pd()), _mm_cmpgt_pd(td, _mm_setzero_pd())));
    const __m128 tf = _mm_cvtpd_ps(td);  // rounds as static_cast<float>; lanes 2, 3 are zero
    hits &= _mm_movemask_ps(_mm_and_ps(_mm_cmpgt_ps(tf, _mm_set1_ps(ray.tMin)), _mm_cmplt_ps(tf, _mm_set1_ps(ray.tMax))));
    alignas(16) float lanes[4];
    _mm_store_ps(lanes, tf);
    t[0] = lanes[0];
    t[1] = lanes[1];
#else
    for (int lane = 0; lane < 2; ++lane) {
        const double denominator = (pack.normal[0][lane] * double(ray.direction.x) +
                                    pack.normal[1][lane] * double(ray.direction.y)) +
                                   pack.normal[2][lane] * double(ray.direction.z);
        if (!(denominator != 0.0)) continue;
        const double numerator = ((pack.point[0][lane] - double(ray.origin.x)) * pack.normal[0][lane] +
                                  (pack.point[1][lane] - double(ray.origin.y)) * pack.normal[1][lane]) +
                                 (pack.point[2][lane] - double(ray.origin.z)) * pack.normal[2][lane];
        const double td = numerator / denominator;
        t[lane] = static_cast<float>(td);
        if (td > 0.0 && t[lane] > ray.tMin && t[lane] < ray.tMax) hits |= 1 << lane;
    }
#endif
    if (pack.ids[0] == ray.ignoredPrimitive) hits &= ~1;
    if (pack.ids[1] == ray.ignoredPrimitive) hits &= ~2;
    return hits;
}

}  // namespace lightpath
