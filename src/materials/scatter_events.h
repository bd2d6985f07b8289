#pragma once
// The events a material can scatter by, for its values: the one place that reads a material's
// lobes as events for the LPE judge (config/scene_events.h), so that when lobes change (more
// kinds, lobes as data) this function is all the judge needs adapted.
#include <vector>

#include "materials/material.h"

namespace lightpath {

// One event per lobe the material has (Material::has, eventOf), and <RD> for an ambient
// reflectance: the ambient term ka Ia is recorded after the diffuse event (docs/design.md).
inline std::vector<ScatterEvent> scatterEventsOf(const Material& material) {
    std::vector<ScatterEvent> events;
    const auto add = [&events](ScatterEvent event) {
        for (const ScatterEvent& e : events)
            if (e.type == event.type && e.scatter == event.scatter) return;
        events.push_back(event);
    };
    for (int i = 0; i < kLobeCount; ++i)
        if (const Lobe lobe = static_cast<Lobe>(i); material.has(lobe)) add(eventOf(lobe));
    if (!isBlack(material.ambientReflectance())) add(eventOf(Lobe::Diffuse));
    return events;
}

}  // namespace lightpath
