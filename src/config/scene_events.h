#pragma once
// What a scene can produce, as the LPE judge reads it: the events its objects' materials scatter
// by (materials/scatter_events.h, from their lobes) and the emitters that can end its paths. An
// expression with no path among them is black in that scene whatever the integrator (docs/lpe.md,
// "No silent black AOVs").
#include <optional>
#include <string>
#include <vector>

#include "materials/lobe.h"
#include "scene/scene.h"

namespace lightpath {

struct SceneEvents {
    std::vector<ScatterEvent> scatter;  // every event some object's material scatters by
    bool hittableLight = false;         // a [[lights]] quad or sphere: an L a ray can hit
    bool objectEmission = false;        // a surface whose material emits: O
    bool shapelessLight = false;        // a point light: an L only a light sample from a smooth event reaches
    bool ambientLight = false;          // [world] ambient is not black
    bool ambientReflectance = false;    // some material has ka: with ambientLight, <L'ambient'> after <RD>
    bool background = false;            // the background is not black: B
};

SceneEvents sceneEventsOf(const Scene& scene);

// Every path the scene can carry, unlabelled but for 'ambient', as an LPE; none when nothing can
// end a path (no light, no emitting surface, a black background).
std::optional<std::string> sceneLanguage(const SceneEvents& events);

// Nothing when `expression` shares a path with `languages` (what lightpath and the integrator
// render) among the events `scene` produces; otherwise what the scene lacks for it and how to add
// it, worded to follow "in this scene ", e.g. "no material has a mirror lobe (kr and kt are 0 in
// every material): give one kr".
std::optional<std::string> whyNotInScene(const std::string& expression, const std::vector<std::string>& languages,
                                         const Scene& scene);

// The same on each thing's own label: nothing when `expression` shares a path with `languages`
// among the events each object scatters by and each emitter ends a path with, under its label;
// otherwise which labelled object lacks the event, e.g. "floor has no mirror lobe <RS>: its material
// scatters only by <RD>". Nothing, too, when a label cannot be quoted in an LPE.
std::optional<std::string> whyNotOnItsLabels(const std::string& expression, const std::vector<std::string>& languages,
                                             const Scene& scene);

}  // namespace lightpath
