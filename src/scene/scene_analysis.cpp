#include "scene/scene_analysis.h"

namespace lightpath {

SceneAnalysis::SceneAnalysis(const Scene& scene) {
    for (const PhongMaterial& m : scene.materials) {
        MaterialTerms terms;
        terms.ambient = !isBlack(m.ka * scene.ambient);
        terms.diffuse = !isBlack(m.kd);
        terms.highlight = !isBlack(m.ks);
        terms.mirror = !isBlack(m.kr);
        terms.refraction = !isBlack(m.kt);
        anyHighlight |= terms.highlight;
        anyMirror |= terms.mirror;
        anyRefraction |= terms.refraction;
        materials.push_back(terms);
    }
}

}  // namespace lightpath
