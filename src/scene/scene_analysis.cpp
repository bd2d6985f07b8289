#include "scene/scene_analysis.h"

namespace lightpath {

SceneAnalysis::SceneAnalysis(const Scene& scene) {
    for (const MaterialSlot& m : scene.materials) {
        MaterialTerms terms;
        terms.ambient = !isBlack(m->ambientReflectance() * scene.ambient);
        const Lobes lobes = m->lobes();
        for (int l = 0; l < int(lobes.size()); ++l) {
            terms.lobes[l] = m->has(l);
            terms.smoothTransmission |= terms.lobes[l] && !lobes[l].delta() && lobes[l].transmits();
        }
        materials.push_back(terms);
    }
}

}  // namespace lightpath
