#pragma once
// Image layers of linear RGB, all the same size: the beauty, each AOV, and rest. Stored pixel by
// pixel with a pixel's layers side by side, as the renderer writes them and as an EXR interleaves
// its channels.
#include <span>
#include <string>
#include <vector>

#include "film/large_buffer.h"
#include "math/types.h"

namespace lightpath {

class Film {
public:
    // Every pixel black.
    Film(int width, int height, std::vector<std::string> layerNames);
    // Pixels left unset, for a writer that sets every one (the renderer's workers, which so touch
    // the memory first, in parallel).
    struct Unset {};
    Film(int width, int height, std::vector<std::string> layerNames, Unset);

    // The bytes a film of this size holds, before it is allocated (issue #28: a render that cannot
    // get them is refused up front). The constructors allocate exactly valueCount values.
    static std::size_t valueCount(int width, int height, std::size_t layers) {
        return layers * static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    }
    static std::size_t bytes(int width, int height, std::size_t layers) {
        return valueCount(width, height, layers) * sizeof(Rgb);
    }

    int width() const { return width_; }
    int height() const { return height_; }
    std::size_t layerCount() const { return layerNames_.size(); }
    const std::vector<std::string>& layerNames() const { return layerNames_; }

    Rgb& at(std::size_t layer, int x, int y) { return pixels_[index(x, y) + layer]; }
    const Rgb& at(std::size_t layer, int x, int y) const { return pixels_[index(x, y) + layer]; }
    // All layers of one pixel, in layer order.
    std::span<Rgb> pixel(int x, int y) { return {pixels_.data() + index(x, y), layerCount()}; }
    // Every layer of every pixel, row by row: the interleaved order of a multi-layer EXR.
    std::span<const Rgb> interleaved() const { return pixels_; }
    // One layer's pixels, row by row (a copy).
    std::vector<Rgb> layer(std::size_t layer) const;
    // Every value times `factor`: a sum of passes made their mean.
    void scale(float factor) {
        for (Rgb& value : pixels_) value *= factor;
    }

private:
    std::size_t index(int x, int y) const {
        return (static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x)) *
               layerNames_.size();
    }

    int width_, height_;
    std::vector<std::string> layerNames_;
    std::vector<Rgb, LargeBufferAllocator<Rgb>> pixels_;  // 174 MB at 1080p with the classes AOVs
};

}  // namespace lightpath
