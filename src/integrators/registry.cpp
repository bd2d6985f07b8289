#include "integrators/registry.h"

namespace lightpath {

// The rows are registered by the integrators' own .cpp files (each beside the code its path
// language is read off); this is the table in rank order, built once after static initialisation.
const std::vector<IntegratorInfo>& integrators() {
    static const std::vector<IntegratorInfo> table = [] {
        std::vector<IntegratorInfo> rows;
        for (const IntegratorInfo* info : IntegratorRegistry::instance().entries()) rows.push_back(*info);
        return rows;
    }();
    return table;
}

const IntegratorInfo* findIntegrator(std::string_view name) {
    for (const IntegratorInfo& info : integrators())
        if (name == info.name) return &info;
    return nullptr;
}

std::vector<std::string> integratorNames() {
    std::vector<std::string> names;
    for (const IntegratorInfo& info : integrators()) names.emplace_back(info.name);
    return names;
}

std::string mediaRenderers() {
    std::string names;
    for (const IntegratorInfo& info : integrators())
        if (info.rendersMedia) names += (names.empty() ? "" : ", ") + std::string(info.name);
    return names;
}

}  // namespace lightpath
