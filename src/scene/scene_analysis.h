#pragma once
// What a scene can and cannot produce, worked out once before rendering so the integrators never
// evaluate or spawn what cannot contribute (a term whose coefficient is zero, a mirror ray from a
// surface that is not a mirror).
#include <vector>

#include "scene/scene.h"

namespace lightpath {

struct MaterialTerms {
    bool ambient = false;    // ka Ia != 0
    bool diffuse = false;    // a diffuse lobe
    bool highlight = false;  // a glossy (highlight) lobe
};

struct SceneAnalysis {
    std::vector<MaterialTerms> materials;  // per material

    explicit SceneAnalysis(const Scene& scene);
};

}  // namespace lightpath
