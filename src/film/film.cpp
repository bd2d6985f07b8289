#include "film/film.h"

#include <type_traits>
#include <utility>

namespace lightpath {

Film::Film(int width, int height, std::vector<std::string> layerNames)
    : width_(width), height_(height), layerNames_(std::move(layerNames)),
      pixels_(valueCount(width, height, layerNames_.size()), Rgb{0.0f}) {}

static_assert(std::is_trivially_default_constructible_v<Rgb>, "Film::Unset relies on Rgb having no constructor to run");

Film::Film(int width, int height, std::vector<std::string> layerNames, Unset)
    : width_(width), height_(height), layerNames_(std::move(layerNames)),
      pixels_(valueCount(width, height, layerNames_.size())) {}

std::vector<Rgb> Film::layer(std::size_t layer) const {
    std::vector<Rgb> pixels;
    pixels.reserve(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_));
    for (std::size_t i = layer; i < pixels_.size(); i += layerNames_.size()) pixels.push_back(pixels_[i]);
    return pixels;
}

}  // namespace lightpath
