#include "film/splat_film.h"

#include <cmath>

namespace lightpath {

SplatFilm::SplatFilm(int width, int height, std::size_t layers)
    : width_(width), height_(height), layers_(layers),
      sums_(std::make_unique<std::atomic<std::int64_t>[]>(valueCount(width, height, layers))) {}

void SplatFilm::add(int x, int y, std::size_t layer, const Rgb& value) {
    const std::size_t i = index(x, y, layer);
    for (int c = 0; c < 3; ++c)
        sums_[i + c].fetch_add(std::llround(double(value[c]) * kUnitsPerRadiance), std::memory_order_relaxed);
}

Rgb SplatFilm::at(int x, int y, std::size_t layer) const {
    const std::size_t i = index(x, y, layer);
    Rgb value;
    for (int c = 0; c < 3; ++c)
        value[c] = static_cast<float>(double(sums_[i + c].load(std::memory_order_relaxed)) / kUnitsPerRadiance);
    return value;
}

}  // namespace lightpath
