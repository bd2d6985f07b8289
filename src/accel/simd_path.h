#pragma once
// Which SIMD instructions BVH traversal uses, chosen at run time: AVX2 (an 8-wide node in one
// register) on processors that have it, else the baseline: SSE2 on x86-64 (two 4-wide halves),
// plain loops elsewhere (simd.h). Both paths compute the same IEEE operations lane by lane, so
// they give the same answers; a Bvh reads the active path once, when it is built.
#include <string_view>

namespace lightpath::simd {

enum class Path { Baseline, Avx2 };

// The widest path this processor (and its operating system) supports.
Path bestPath();
bool supported(Path path);
// The path Bvhs built from now on use: bestPath(), unless setPath chose another.
Path activePath();
// Chooses the path for Bvhs built from now on (tests and benchmarks compare both with it).
// Throws std::invalid_argument when this processor cannot run `path`.
void setPath(Path path);

// "avx2", or "sse2" / "portable" for the baseline.
std::string_view pathName(Path path);

}  // namespace lightpath::simd
