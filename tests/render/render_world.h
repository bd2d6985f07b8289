#pragma once
// Everything a RenderContext refers to, built from one scene, for tests that call an integrator,
// the light set or the geometry directly instead of through the Renderer.
#include <vector>

#include "film/aov_presets.h"
#include "film/aov_set.h"
#include "integrators/direct_light.h"
#include "integrators/integrator.h"
#include "lights/light_set.h"
#include "scene/camera.h"
#include "scene/scene_analysis.h"

namespace lightpath::test {

struct RenderWorld {
    explicit RenderWorld(Scene s, std::vector<lpe::NamedExpression> set = classesSet(), int maxDepth = 5,
                         const RadiosityOptions& radiosity = {}, int threads = 0)
        : scene(std::move(s)),
          aovs(std::move(set)),
          geometry(scene.spheres, scene.planes, scene.triangles, {}, Accelerator::Bvh, scene.triangleNormals, 0,
                   scene.shapes, scene.triangleUvs, scene.triangleTangents),
          symbols(scene, aovs.automaton()),
          analysis(scene),
          lights(scene, geometry),
          lobeSteps(scene, aovs.automaton(), symbols, lights),
          camera(scene.camera),
          context{scene, geometry, aovs.automaton(), symbols, analysis, lights, lobeSteps, camera, maxDepth,
                  aovs.automaton().allOutputs(), true, true, radiosity, threads} {
        context.eyeMedium = cameraMedium(context);
    }
    RenderWorld(const RenderWorld&) = delete;
    RenderWorld& operator=(const RenderWorld&) = delete;

    Scene scene;
    AovSet aovs;
    SceneGeometry geometry;
    EventSymbols symbols;
    SceneAnalysis analysis;
    LightSet lights;
    LobeStepTable lobeSteps;
    Camera camera;
    RenderContext context;
};

}  // namespace lightpath::test
