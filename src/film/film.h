#pragma once
// Image layers of linear RGB, all the same size: the beauty, each AOV, and rest.
#include <span>
#include <string>
#include <vector>

#include "math/types.h"

namespace lightpath {

class Film {
public:
    Film(int width, int height, std::vector<std::string> layerNames);

    int width() const { return width_; }
    int height() const { return height_; }
    std::size_t layerCount() const { return layerNames_.size(); }
    const std::vector<std::string>& layerNames() const { return layerNames_; }

    Rgb& at(std::size_t layer, int x, int y) { return pixels_[index(layer, x, y)]; }
    const Rgb& at(std::size_t layer, int x, int y) const { return pixels_[index(layer, x, y)]; }
    std::span<const Rgb> layer(std::size_t layer) const;

private:
    std::size_t index(std::size_t layer, int x, int y) const {
        return (layer * static_cast<std::size_t>(height_) + static_cast<std::size_t>(y)) *
                   static_cast<std::size_t>(width_) + static_cast<std::size_t>(x);
    }

    int width_, height_;
    std::vector<std::string> layerNames_;
    std::vector<Rgb> pixels_;
};

}  // namespace lightpath
