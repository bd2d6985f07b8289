#pragma once
// The events a material can scatter by, for its values: the one place that reads a material's
// lobes as events for the LPE judge (config/scene_events.h), so that when lobes change (more
// kinds, lobes as data) this function is all the judge needs adapted.
#include <algorithm>
#include <vector>

#include "materials/material.h"

namespace lightpath {

// One event per lobe the material has (Material::lobes, has), and <RD> for an ambient
// reflectance: the ambient term ka Ia is recorded after the diffuse event (docs/design.md).
inline std::vector<ScatterEvent> scatterEventsOf(const Material& material) {
    std::vector<ScatterEvent> events;
    const auto add = [&events](ScatterEvent event) {
        if (std::find(events.begin(), events.end(), event) == events.end()) events.push_back(event);
    };
    const Lobes lobes = material.lobes();
    for (int i = 0; i < static_cast<int>(lobes.size()); ++i)
        if (material.has(i)) add(lobes[i].event);
    if (!isBlack(material.ambientReflectance())) add(lobes::kDiffuse.event);
    return events;
}

}  // namespace lightpath
