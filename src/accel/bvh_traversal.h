#pragma once
// Bvh::closest and Bvh::any: the traversal of bvh_traversal-inl.h compiled for each SIMD path,
// and the choice between them. Only the code that runs queries includes this header, so that
// changing traversal recompiles that code alone.
#include "accel/bvh.h"

#define LIGHTPATH_BVH_AVX2 0
#include "accel/bvh_traversal-inl.h"
#undef LIGHTPATH_BVH_AVX2
#ifdef LIGHTPATH_AVX2_PATH
LIGHTPATH_BEGIN_AVX2
#define LIGHTPATH_BVH_AVX2 1
#include "accel/bvh_traversal-inl.h"
#undef LIGHTPATH_BVH_AVX2
LIGHTPATH_END_AVX2
#endif

namespace lightpath {

template <typename Test>
void Bvh::closest(const Ray& ray, const float& tLimit, Test test) const {
    if (root_ == kNoRoot) return;
#ifdef LIGHTPATH_AVX2_PATH
    if (path_ == simd::Path::Avx2) return bvh_avx2::closest(*this, ray, tLimit, test);
#endif
    bvh_baseline::closest(*this, ray, tLimit, test);
}

template <typename Test>
bool Bvh::any(const Ray& ray, Test test) const {
    if (root_ == kNoRoot) return false;
#ifdef LIGHTPATH_AVX2_PATH
    if (path_ == simd::Path::Avx2) return bvh_avx2::any(*this, ray, test);
#endif
    return bvh_baseline::any(*this, ray, test);
}

}  // namespace lightpath
