#pragma once
// Where light tracing adds the contributions it finds for pixels other than the one being sampled.
// Splats arrive from every worker in any order, so they are summed in fixed point: integer addition
// is associative, and the image is bit-identical for any number of threads and any order of tiles
// (issue "bidirectional path tracing": deterministic splatting). 128 bits, one unit 2^-64 of
// radiance: a splat is rounded by at most 2.7e-20 (a scene lit 1e-9 as brightly keeps 9 significant
// digits), and a pixel holds up to 9.2e18. Each sum is two 64-bit words added with a carry, so the
// adds stay lock-free.
#include <atomic>
#include <cstdint>
#include <memory>

#include "math/types.h"

namespace lightpath {

class SplatFilm {
public:
    SplatFilm(int width, int height, std::size_t layers);

    // The bytes a splat film of this size holds (the constructor allocates valueCount sums).
    static std::size_t valueCount(int width, int height, std::size_t layers) {
        return static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * layers * 3;
    }
    static std::size_t bytes(int width, int height, std::size_t layers) {
        return valueCount(width, height, layers) * sizeof(Sum);
    }

    int width() const { return width_; }
    int height() const { return height_; }
    // Thread-safe; values are finite (the caller drops non-finite ones).
    void add(int x, int y, std::size_t layer, const Rgb& value);
    Rgb at(int x, int y, std::size_t layer) const;

private:
    // A signed 128-bit sum kept as its low and high words (two's complement, wrapping like unsigned).
    struct Sum {
        std::atomic<std::uint64_t> low{0}, high{0};
    };
    static constexpr int kFractionBits = 64;
    std::size_t index(int x, int y, std::size_t layer) const {
        return ((static_cast<std::size_t>(y) * width_ + x) * layers_ + layer) * 3;
    }
    int width_, height_;
    std::size_t layers_;
    std::unique_ptr<Sum[]> sums_;
};

}  // namespace lightpath
