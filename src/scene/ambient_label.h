#pragma once
// The label of the ambient term's L event (docs/design.md: `<L'ambient'>`), reserved: no light may
// take it. One constant for the integrators that emit it and the presets and checks that name it.

namespace lightpath {

inline constexpr const char* kAmbientLabel = "ambient";

}  // namespace lightpath
