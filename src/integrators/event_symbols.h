#pragma once
// The automaton symbols of every event a scene can produce, looked up once per render so the
// tracer advances its automaton state by table lookups only (DESIGN.md: no strings in the hot loop).
#include <string>
#include <vector>

#include "lpe/automaton.h"
#include "scene/scene.h"

namespace lightpath {

struct SurfaceSymbols {
    lpe::Automaton::Symbol diffuse;     // R D: the kd (N.L) term and the ambient term
    lpe::Automaton::Symbol glossy;      // R G: the ks (H.N)^n highlight
    lpe::Automaton::Symbol mirror;      // R S: the kr-weighted mirror ray (and total internal reflection)
    lpe::Automaton::Symbol refraction;  // T S: the kt-weighted refracted ray
    lpe::Automaton::Symbol emission;    // L: the surface itself emitting (an area light)
};

struct EventSymbols {
    lpe::Automaton::Symbol camera;
    lpe::Automaton::Symbol background;
    lpe::Automaton::Symbol ambient;
    std::vector<lpe::Automaton::Symbol> lights;  // per point light
    std::vector<SurfaceSymbols> objects;         // per scene object

    EventSymbols(const Scene& scene, const lpe::Automaton& automaton);
};

// The label of the ambient term's L event (DESIGN.md: `<L'ambient'>`).
inline constexpr const char* kAmbientLabel = "ambient";

// Every label an event of this scene can carry: "ambient", the point lights' names, and each
// object's label (its name, else its material's; area lights are objects). Sorted, no repeats.
std::vector<std::string> sceneLabels(const Scene& scene);

}  // namespace lightpath
