#pragma once
// The automaton's answers for direct light, made once per render: at a shading point, which
// outputs accept a path that scatters through each smooth lobe and ends in a light (or the
// ambient term). The automaton is deterministic (state x symbol -> state), and a hit's smooth-lobe
// symbols depend only on its object (the material's lobes() and the object's label class), so
// the answer is a function of (path state, shading class, light): a table, not two steps and an
// accept lookup per lobe per light sample (docs/performance.md, Shading share, seventh pass).
// Read only through PathState (docs/design.md); it never steps the automaton itself at render time.
#include <cstdint>
#include <vector>

#include "integrators/event_symbols.h"
#include "lights/light_set.h"
#include "lpe/automaton.h"
#include "materials/lobe.h"
#include "scene/scene.h"

namespace lightpath {

// A material's smooth lobes (those light sampling reaches) as one object's hits name them: every
// hit on objects of one shading class has these, in the material's order.
struct SmoothLobes {
    int count = 0;
    int lobe[kMaxLobes]{};      // each one's index in the material's lobes()
    bool glossy[kMaxLobes]{};   // a glossy lobe, as the stats count them
    lpe::Automaton::Symbol symbol[kMaxLobes]{};  // its event's symbol, labelled by the object
    int ambient = -1;  // the slot whose event the ambient term ka Ia takes: the first diffuse reflection
};

// A light (or the ambient term) as the table knows it: its column, and its symbol for stepping
// when the table has no column for it.
struct LightColumn {
    int column = -1;  // -1: not tabled
    lpe::Automaton::Symbol symbol = 0;
};

class LobeStepTable {
public:
    // Above this many masks (8 bytes each) the table is not made and PathState steps instead: a
    // set naming many objects and lights with a large automaton would not fit a cache anyway.
    static constexpr std::size_t kMaxMasks = std::size_t{1} << 20;

    LobeStepTable(const Scene& scene, const lpe::Automaton& automaton, const EventSymbols& symbols,
                  const LightSet& lights, std::size_t maxMasks = kMaxMasks);

    std::uint32_t classOf(std::uint32_t object) const { return classOfObject_[object]; }
    const SmoothLobes& lobes(std::uint32_t shadingClass) const { return classes_[shadingClass]; }
    std::size_t classCount() const { return classes_.size(); }
    std::size_t columnCount() const { return columnSymbols_.size(); }

    // The column of a light's event (Light::event()), and the ambient term's.
    LightColumn columnOf(const PathEvent& light) const {
        const std::vector<int>* columns = light.subject == Subject::SceneLight ? &sceneLightColumns_
                                          : light.subject == Subject::Object   ? &objectColumns_
                                                                               : nullptr;
        if (columns != nullptr && light.index < columns->size() && (*columns)[light.index] >= 0 && tabled_) {
            const int column = (*columns)[light.index];
            return {column, columnSymbols_[column]};
        }
        return {-1, symbols_(light)};
    }
    LightColumn ambient() const { return {tabled_ ? 0 : -1, columnSymbols_[0]}; }

    bool tabled() const { return tabled_; }
    // accepts(state, column, class)[slot]: the outputs accepting a path in `state` that scatters
    // through slot `slot` of the class's smooth lobes and ends in the light of `column`.
    // Only when tabled() and column >= 0.
    const lpe::OutputMask* accepts(lpe::Automaton::State state, int column, std::uint32_t shadingClass) const {
        return &masks_[(std::size_t{state} * columnSymbols_.size() + std::size_t(column)) * slotCount_ +
                       slotBase_[shadingClass]];
    }

private:
    const EventSymbols& symbols_;
    std::vector<SmoothLobes> classes_;
    std::vector<std::uint32_t> classOfObject_;  // per scene object
    std::vector<std::size_t> slotBase_;         // per class: its first slot among all classes' slots
    std::size_t slotCount_ = 0;                 // all classes' slots
    std::vector<lpe::Automaton::Symbol> columnSymbols_;  // column 0 is the ambient term
    std::vector<int> sceneLightColumns_;        // per scene light: its column, -1 if it is none
    std::vector<int> objectColumns_;            // per scene object: its emitter's column, -1 if none
    std::vector<lpe::OutputMask> masks_;        // state x column x slot
    bool tabled_ = false;
};

}  // namespace lightpath
