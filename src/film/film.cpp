#include "film/film.h"

#include <utility>

namespace lightpath {

Film::Film(int width, int height, std::vector<std::string> layerNames)
    : width_(width), height_(height), layerNames_(std::move(layerNames)),
      pixels_(layerNames_.size() * static_cast<std::size_t>(width) * static_cast<std::size_t>(height), Rgb{0.0f}) {}

std::span<const Rgb> Film::layer(std::size_t layer) const {
    const std::size_t size = static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_);
    return {pixels_.data() + layer * size, size};
}

}  // namespace lightpath
