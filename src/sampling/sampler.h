#pragma once
// The random numbers of one pixel sample, drawn dimension by dimension: deterministic per (pixel,
// sample index, seed), so images never depend on threads or tile order. Three kinds:
//   independent  uniform random numbers (PCG32)
//   stratified   each dimension (pair) split into samplesPerPixel strata, one sample in each,
//                their order shuffled per pixel and dimension: a jittered grid when the count is
//                a square, Latin hypercube otherwise
//   sobol        the first two dimensions of Sobol's (0,2)-sequence per dimension pair, index
//                shuffled and values Owen-scrambled by hashing (Burley, "Practical Hash-based
//                Owen Scrambling", JCGT 2020): low discrepancy for any prefix of samples
#include <cstdint>
#include <string_view>

#include "math/random.h"
#include "math/types.h"

namespace lightpath {

enum class SamplerKind { Independent, Stratified, Sobol };

// The largest float below 1: a sample remapped into a sub-range (a mixture's branch, a stratum)
// stays in [0, 1), as the sampler's own numbers do.
inline constexpr float kBelowOne = 0x1.fffffep-1f;

// "independent", "stratified", "sobol"; false for another name.
bool parseSamplerKind(std::string_view name, SamplerKind& kind);
const char* samplerName(SamplerKind kind);

class Sampler {
public:
    Sampler(SamplerKind kind, std::uint64_t seed, int sampleIndex, int samplesPerPixel);

    static Sampler forPixel(SamplerKind kind, int x, int y, int sampleIndex, int samplesPerPixel, std::uint64_t seed);

    float next1D();
    Vec2 next2D();
    // Passes over the next dimension pair without computing it, so later dimensions keep their
    // numbers (the single sample of a pixel goes through its centre and needs none).
    void skip2D();
    // The same for one dimension: what next1D would have drawn is not computed (a free flight's
    // colour channel in a grey medium; docs/performance.md, Shading share, sixth pass).
    void skip1D();

    // The sampler of one vertex of a branching path, keyed by the path that leads to it: its
    // numbers do not depend on which other branches were traced (or skipped) before it, and
    // samples of the pixel that reach the same vertex stay stratified among themselves.
    // What depends only on the kind, index and count (the stratified grid's side, the reversed
    // index) is copied, not recomputed per vertex (docs/performance.md, Shading share, eighth pass).
    Sampler forVertex(std::uint64_t pathKey) const { return Sampler(*this, mixBits(seed_ ^ pathKey)); }

private:
    // `parent`'s kind, index and count with `seed`: the same sampler as Sampler(parent's kind,
    // seed, parent's index, parent's count).
    Sampler(const Sampler& parent, std::uint64_t seed)
        : kind_(parent.kind_), seed_(seed), index_(parent.index_), count_(parent.count_), gridSide_(parent.gridSide_),
          reversedIndex_(parent.reversedIndex_),
          rng_(usesRng() ? Pcg32(mixBits(seed), mixBits(seed ^ static_cast<std::uint64_t>(index_))) : Pcg32::unseeded()) {}

    bool usesRng() const { return kind_ != SamplerKind::Sobol; }
    std::uint64_t dimensionSeed() { return mixBits(seed_ + 0x9e3779b97f4a7c15ull * static_cast<std::uint64_t>(++dimension_)); }

    SamplerKind kind_;
    std::uint64_t seed_;
    std::uint32_t index_;
    std::uint32_t count_;
    std::uint32_t gridSide_;  // stratified: sqrt(count_) when count_ is a square, else 0
    // sobol: index_ with its bits reversed, as the index's Owen scramble takes it (Burley 2020,
    // listing 3: reverse, hash, reverse): once per sampler, not once per dimension.
    std::uint32_t reversedIndex_;
    int dimension_ = 0;
    Pcg32 rng_;  // independent and stratified only (left unseeded for sobol)
};

// Sobol's second dimension (primitive polynomial x + 1, whose generator matrix is Pascal's
// triangle mod 2) of point `index`, as 32 fraction bits.
std::uint32_t sobolDimension1(std::uint32_t index);

}  // namespace lightpath
