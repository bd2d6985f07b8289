#include "integrators/integrator.h"

#include "integrators/path.h"
#include "integrators/radiosity.h"
#include "integrators/raycast.h"
#include "integrators/whitted.h"

namespace lightpath {

std::unique_ptr<Integrator> makeIntegrator(std::string_view name) {
    if (name == "raycast") return std::make_unique<RaycastIntegrator>();
    if (name == "whitted") return std::make_unique<WhittedIntegrator>();
    if (name == "path") return std::make_unique<PathIntegrator>();
    if (name == "radiosity") return std::make_unique<RadiosityIntegrator>();
    return nullptr;
}

}  // namespace lightpath
