#include "integrators/lobe_step_table.h"

#include <map>
#include <utility>

namespace lightpath {

LobeStepTable::LobeStepTable(const Scene& scene, const lpe::Automaton& automaton, const EventSymbols& symbols,
                             const LightSet& lights, std::size_t maxMasks)
    : symbols_(symbols) {
    // Shading classes: objects whose hits step the automaton alike (same material, same symbols).
    std::map<std::pair<std::uint32_t, std::vector<lpe::Automaton::Symbol>>, std::uint32_t> classIds;
    for (std::uint32_t object = 0; object < scene.objects.size(); ++object) {
        const std::uint32_t material = scene.objects[object].material;
        SmoothLobes lobes;
        const Lobes all = scene.materials[material]->lobes();
        for (int l = 0; l < int(all.size()); ++l) {
            if (all[l].delta()) continue;
            const int slot = lobes.count++;
            lobes.lobe[slot] = l;
            lobes.glossy[slot] = all[l].event.scatter == lpe::Scatter::Glossy;
            lobes.symbol[slot] = symbols(PathEvent{all[l].event.type, all[l].event.scatter, Subject::Object, object});
            if (lobes.ambient < 0 && !all[l].transmits() && all[l].event.scatter == lpe::Scatter::Diffuse)
                lobes.ambient = slot;
        }
        auto key = std::make_pair(material, std::vector(lobes.symbol, lobes.symbol + lobes.count));
        const auto [found, added] = classIds.try_emplace(std::move(key), std::uint32_t(classes_.size()));
        if (added) {
            slotBase_.push_back(slotCount_);
            slotCount_ += std::size_t(lobes.count);
            classes_.push_back(lobes);
        }
        classOfObject_.push_back(found->second);
    }

    // Columns: the ambient term, then each distinct light symbol.
    std::map<lpe::Automaton::Symbol, int> columnIds;
    const auto columnFor = [&](lpe::Automaton::Symbol symbol) {
        const auto [found, added] = columnIds.try_emplace(symbol, int(columnSymbols_.size()));
        if (added) columnSymbols_.push_back(symbol);
        return found->second;
    };
    columnFor(symbols(PathEvent{lpe::EventType::Emitter, lpe::Scatter::None, Subject::Ambient, 0}));
    sceneLightColumns_.assign(scene.lights.size(), -1);
    objectColumns_.assign(scene.objects.size(), -1);
    for (const std::unique_ptr<Light>& light : lights.all()) {
        const PathEvent& event = light->event();
        std::vector<int>* columns = event.subject == Subject::SceneLight ? &sceneLightColumns_
                                    : event.subject == Subject::Object   ? &objectColumns_
                                                                         : nullptr;
        if (columns != nullptr && event.index < columns->size()) (*columns)[event.index] = columnFor(symbols(event));
    }

    const std::size_t masks = automaton.stateCount() * columnSymbols_.size() * slotCount_;
    if (masks > maxMasks) return;
    masks_.resize(masks);
    for (lpe::Automaton::State state = 0; state < automaton.stateCount(); ++state)
        for (std::size_t column = 0; column < columnSymbols_.size(); ++column)
            for (std::size_t c = 0; c < classes_.size(); ++c) {
                // A class without smooth lobes (an interface) has no slots: with no other class,
                // masks_ is empty and even its row's address would be out of bounds.
                if (classes_[c].count == 0) continue;
                lpe::OutputMask* row = &masks_[(state * columnSymbols_.size() + column) * slotCount_ + slotBase_[c]];
                for (int slot = 0; slot < classes_[c].count; ++slot)
                    row[slot] = automaton.accepts(
                        automaton.step(automaton.step(state, classes_[c].symbol[slot]), columnSymbols_[column]));
            }
    tabled_ = true;
}

}  // namespace lightpath
