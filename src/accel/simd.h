#pragma once
// Four floats in one register: the lanes of four triangles, or half of an 8-wide BVH node. SSE2,
// which every x86-64 processor has (no -march flags); a plain loop elsewhere. Each operation is
// one IEEE operation per lane, so a lane's result is bit-identical to the same scalar expression
// (no fused multiply-add: x86-64's baseline has none, and AVX2 code is compiled without FMA).
// The AVX2 path (bvh_traversal-inl.h) is compiled for AVX2 function by function, between
// LIGHTPATH_BEGIN_AVX2 and LIGHTPATH_END_AVX2, and chosen at run time (simd_path.h).
#include <cstdint>

#if defined(__SSE2__) || defined(_M_X64)
#include <emmintrin.h>
#define LIGHTPATH_SSE2 1
#endif

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#define LIGHTPATH_AVX2_PATH 1
#if defined(__clang__)
#define LIGHTPATH_BEGIN_AVX2 \
    _Pragma("clang attribute push(__attribute__((target(\"avx2\"))), apply_to = function)")
#define LIGHTPATH_END_AVX2 _Pragma("clang attribute pop")
#else
#define LIGHTPATH_BEGIN_AVX2 _Pragma("GCC push_options") _Pragma("GCC target(\"avx2\")")
#define LIGHTPATH_END_AVX2 _Pragma("GCC pop_options")
#endif
#endif

namespace lightpath::simd {

#ifdef LIGHTPATH_SSE2

struct Float4 {
    __m128 v;

    Float4() = default;
    explicit Float4(__m128 value) : v(value) {}
    explicit Float4(float s) : v(_mm_set1_ps(s)) {}
    static Float4 load(const float* p) { return Float4(_mm_load_ps(p)); }  // 16-byte aligned
    void store(float* p) const { _mm_store_ps(p, v); }

    friend Float4 operator+(Float4 a, Float4 b) { return Float4(_mm_add_ps(a.v, b.v)); }
    friend Float4 operator-(Float4 a, Float4 b) { return Float4(_mm_sub_ps(a.v, b.v)); }
    friend Float4 operator*(Float4 a, Float4 b) { return Float4(_mm_mul_ps(a.v, b.v)); }
    friend Float4 operator/(Float4 a, Float4 b) { return Float4(_mm_div_ps(a.v, b.v)); }
};

// Lane masks as 4-bit integers (bit i = lane i): comparisons are ordered, so false for a NaN.
inline int lessEqual(Float4 a, Float4 b) { return _mm_movemask_ps(_mm_cmple_ps(a.v, b.v)); }
inline int less(Float4 a, Float4 b) { return _mm_movemask_ps(_mm_cmplt_ps(a.v, b.v)); }
inline int equal(Float4 a, Float4 b) { return _mm_movemask_ps(_mm_cmpeq_ps(a.v, b.v)); }
// maxps/minps return the second operand when either is NaN: max(x, acc) leaves acc unchanged for
// a NaN x, which is how the slab test ignores a slab it cannot decide.
inline Float4 maxKeepSecond(Float4 x, Float4 acc) { return Float4(_mm_max_ps(x.v, acc.v)); }
inline Float4 minKeepSecond(Float4 x, Float4 acc) { return Float4(_mm_min_ps(x.v, acc.v)); }
inline Float4 abs(Float4 x) { return Float4(_mm_andnot_ps(_mm_set1_ps(-0.0f), x.v)); }
// Lanes 0-2 kept, lane 3 zeroed: the BVH builder keeps a primitive id's bits in a box's lane 3.
inline Float4 xyzOnly(Float4 x) {
    return Float4(_mm_and_ps(x.v, _mm_castsi128_ps(_mm_set_epi32(0, -1, -1, -1))));
}
// Each lane truncated toward zero, as static_cast<std::int32_t> does (lanes within int range).
inline void truncateToInts(Float4 x, std::int32_t* out) {
    _mm_storeu_si128(reinterpret_cast<__m128i*>(out), _mm_cvttps_epi32(x.v));
}

#else

struct Float4 {
    alignas(16) float v[4];

    Float4() = default;
    explicit Float4(float s) : v{s, s, s, s} {}
    static Float4 load(const float* p) {
        Float4 r;
        for (int i = 0; i < 4; ++i) r.v[i] = p[i];
        return r;
    }
    void store(float* p) const {
        for (int i = 0; i < 4; ++i) p[i] = v[i];
    }
    template <typename Op>
    static Float4 apply(Float4 a, Float4 b, Op op) {
        Float4 r;
        for (int i = 0; i < 4; ++i) r.v[i] = op(a.v[i], b.v[i]);
        return r;
    }
    friend Float4 operator+(Float4 a, Float4 b) { return apply(a, b, [](float x, float y) { return x + y; }); }
    friend Float4 operator-(Float4 a, Float4 b) { return apply(a, b, [](float x, float y) { return x - y; }); }
    friend Float4 operator*(Float4 a, Float4 b) { return apply(a, b, [](float x, float y) { return x * y; }); }
    friend Float4 operator/(Float4 a, Float4 b) { return apply(a, b, [](float x, float y) { return x / y; }); }
};

template <typename Compare>
int maskOf(Float4 a, Float4 b, Compare compare) {
    int mask = 0;
    for (int i = 0; i < 4; ++i) mask |= compare(a.v[i], b.v[i]) ? 1 << i : 0;
    return mask;
}
inline int lessEqual(Float4 a, Float4 b) { return maskOf(a, b, [](float x, float y) { return x <= y; }); }
inline int less(Float4 a, Float4 b) { return maskOf(a, b, [](float x, float y) { return x < y; }); }
inline int equal(Float4 a, Float4 b) { return maskOf(a, b, [](float x, float y) { return x == y; }); }
inline Float4 maxKeepSecond(Float4 x, Float4 acc) {
    return Float4::apply(x, acc, [](float a, float b) { return a > b ? a : b; });
}
inline Float4 minKeepSecond(Float4 x, Float4 acc) {
    return Float4::apply(x, acc, [](float a, float b) { return a < b ? a : b; });
}
inline Float4 abs(Float4 x) { return Float4::apply(x, x, [](float a, float) { return a < 0.0f ? -a : a; }); }
inline Float4 xyzOnly(Float4 x) {
    x.v[3] = 0.0f;
    return x;
}
inline void truncateToInts(Float4 x, std::int32_t* out) {
    for (int i = 0; i < 4; ++i) out[i] = static_cast<std::int32_t>(x.v[i]);
}

#endif

// The lowest set lane of a non-zero mask.
inline int firstLane(int mask) { return __builtin_ctz(static_cast<unsigned>(mask)); }

}  // namespace lightpath::simd
