#include "film/film.h"

#include <utility>

namespace lightpath {

Film::Film(int width, int height, std::vector<std::string> layerNames)
    : width_(width), height_(height), layerNames_(std::move(layerNames)),
      pixels_(layerNames_.size() * static_cast<std::size_t>(width) * static_cast<std::size_t>(height), Rgb{0.0f}) {}

std::vector<Rgb> Film::layer(std::size_t layer) const {
    std::vector<Rgb> pixels;
    pixels.reserve(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_));
    for (std::size_t i = layer; i < pixels_.size(); i += layerNames_.size()) pixels.push_back(pixels_[i]);
    return pixels;
}

}  // namespace lightpath
