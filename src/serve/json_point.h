#pragma once
// A point or direction as the API writes it: a JSON array [x, y, z].
#include <nlohmann/json.hpp>

#include "math/types.h"

namespace lightpath::serve {

inline nlohmann::json point(const Vec3& p) { return nlohmann::json::array({p.x, p.y, p.z}); }

}  // namespace lightpath::serve
