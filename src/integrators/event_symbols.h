#pragma once
// Turns a recorded event into the automaton's symbol: its type and scattering, and the label class
// of what it touched, looked up once per render so the tracer advances its automaton state by
// arithmetic and table lookups only (docs/design.md: no strings in the hot loop).
#include <string>
#include <vector>

#include "integrators/path_record.h"
#include "lpe/automaton.h"
#include "scene/ambient_label.h"
#include "scene/scene.h"

namespace lightpath {

class EventSymbols {
public:
    EventSymbols(const Scene& scene, const lpe::Automaton& automaton);

    lpe::Automaton::Symbol operator()(const PathEvent& event) const {
        return automaton_.symbol(event.type, event.scatter, labelClass(event));
    }

private:
    lpe::Automaton::LabelClass labelClass(const PathEvent& event) const {
        switch (event.subject) {
            case Subject::Object: return objects_[event.index];
            case Subject::SceneLight: return lights_[event.index];
            case Subject::Ambient: return ambient_;
            case Subject::Medium: return media_[event.index];
            case Subject::None: break;
        }
        return 0;
    }

    const lpe::Automaton& automaton_;
    lpe::Automaton::LabelClass ambient_;
    std::vector<lpe::Automaton::LabelClass> lights_;   // per point light
    std::vector<lpe::Automaton::LabelClass> objects_;  // per scene object
    std::vector<lpe::Automaton::LabelClass> media_;    // per scene medium
};

// Every label an event of this scene can carry: "ambient", the point lights' names, each
// object's label (its name, else its material's; area lights are objects) and each medium's name. Sorted, no repeats.
std::vector<std::string> sceneLabels(const Scene& scene);

// The recorded event as the LPE engine's event, labelled as the automaton sees it (explain, serve).
lpe::Event lpeEventOf(const Scene& scene, const PathEvent& event);

// What an event touched, as a student reads it: the object's or light's name ("camera",
// "background", "ambient" for those; "every patch" for radiosity's unlabelled bounces, each a sum
// over the patches).
std::string subjectName(const Scene& scene, const PathEvent& event);

}  // namespace lightpath
