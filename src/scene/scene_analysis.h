#pragma once
// What a scene can and cannot produce, worked out once before rendering so the integrators never
// evaluate or spawn what cannot contribute (a term whose coefficient is zero, a mirror ray from a
// surface that is not a mirror).
#include <vector>

#include "scene/scene.h"

namespace lightpath {

struct MaterialTerms {
    bool ambient = false;     // ka Ia != 0
    bool diffuse = false;     // kd != 0
    bool highlight = false;   // ks != 0
    bool mirror = false;      // kr != 0
    bool refraction = false;  // kt != 0
};

struct SceneAnalysis {
    std::vector<MaterialTerms> materials;  // per material
    bool anyHighlight = false;
    bool anyMirror = false;
    bool anyRefraction = false;

    explicit SceneAnalysis(const Scene& scene);
};

}  // namespace lightpath
