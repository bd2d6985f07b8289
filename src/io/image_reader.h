#pragma once
#include <filesystem>

#include "film/film.h"

namespace lightpath {

// Reads an EXR written by writeFilm back into a film (through OpenEXR): R,G,B as "beauty" first,
// then <layer>.R/G/B as the other layers in the file's order (EXR sorts channels by name).
// Throws std::runtime_error naming the file when it cannot.
Film readFilm(const std::filesystem::path& path);

}  // namespace lightpath
