#pragma once
// How messages name numbers and vectors: the shortest text that reads back as the same value.
#include <string>

#include "math/types.h"

namespace lightpath {

std::string formatNumber(double value);  // "-1", "0.25", "nan", "inf"
std::string formatVec3(const Vec3& v);   // "[0, 0, 0]"

}  // namespace lightpath
