#pragma once
// What a scene can and cannot produce, worked out once before rendering so the integrators never
// evaluate or spawn what cannot contribute (a term whose coefficient is zero, a mirror ray from a
// surface that is not a mirror).
#include <array>
#include <vector>

#include "materials/lobe.h"
#include "scene/scene.h"

namespace lightpath {

struct MaterialTerms {
    bool ambient = false;                 // ka Ia != 0
    std::array<bool, kMaxLobes> lobes{};  // per lobe of the material's lobes(): it scatters something
    bool smoothTransmission = false;      // a smooth lobe that scatters to the other side is present
};

struct SceneAnalysis {
    std::vector<MaterialTerms> materials;  // per material

    explicit SceneAnalysis(const Scene& scene);
};

}  // namespace lightpath
