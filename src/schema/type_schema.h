#pragma once
// What one type of a family (a material, a light, an integrator) accepts and produces.
#include <string_view>
#include <vector>

#include "schema/parameter.h"

namespace lightpath {

struct TypeSchema {
    std::string_view family;   // "material", "light", "integrator"
    std::string_view name;     // the `type = "..."` value / the --integrator value
    std::string_view summary;  // one line for listings and --help
    std::vector<Parameter> parameters;
    // The events it produces, as an LPE over the alphabet: phong "<R[DGS]>|<TS>", point "<L.>".
    std::string_view events;

    const Parameter* find(std::string_view key) const {
        for (const Parameter& p : parameters)
            if (p.name == key) return &p;
        return nullptr;
    }
};

}  // namespace lightpath
