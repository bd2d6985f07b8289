#include "integrators/integrator.h"

#include "integrators/registry.h"

namespace lightpath {

std::unique_ptr<Integrator> makeIntegrator(std::string_view name) {
    const IntegratorInfo* info = findIntegrator(name);
    return info ? info->make() : nullptr;
}

}  // namespace lightpath
