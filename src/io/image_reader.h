#pragma once
#include <filesystem>

#include "film/film.h"

namespace lightpath {

// Reads an EXR written by writeFilm back into a film: R,G,B as "beauty", <layer>.R/G/B as the
// other layers. Throws std::runtime_error naming the file when it cannot.
Film readFilm(const std::filesystem::path& path);

}  // namespace lightpath
