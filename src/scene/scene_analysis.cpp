#include "scene/scene_analysis.h"

namespace lightpath {

SceneAnalysis::SceneAnalysis(const Scene& scene) {
    for (const MaterialSlot& m : scene.materials) {
        MaterialTerms terms;
        terms.ambient = !isBlack(m->ambientReflectance() * scene.ambient);
        terms.diffuse = m->has(Lobe::Diffuse);
        terms.highlight = m->has(Lobe::Highlight);
        materials.push_back(terms);
    }
}

}  // namespace lightpath
