#include "integrators/registry.h"

#include "integrators/bdpt.h"
#include "integrators/path.h"
#include "integrators/radiosity.h"
#include "integrators/raster.h"
#include "integrators/raycast.h"
#include "integrators/whitted.h"

namespace lightpath {

// The languages are read off the integrators: raycast.cpp shades the first hit with
// local_illumination.cpp's diffuse and highlight terms towards each light and the ambient light
// (E(D|G)L), and adds emission and the background seen directly (EL); whitted.cpp adds mirror and
// refraction rays before that (S*); path.cpp samples every lobe at every bounce; radiosity.cpp
// shows its patches' diffuse bounces (ED+L), emitters and the background seen directly (EL);
// raster.cpp finds ray casting's first hits with a z-buffer and shades them with raycast.cpp.
const std::vector<IntegratorInfo>& integrators() {
    static const std::vector<IntegratorInfo> table = {
        {"raycast", "first hit only: Szymczak's formula, emitters and the background seen directly",
         "E(D|G)L|EL", "ray casting follows no specular bounce and no second bounce: it shades the first hit only",
         [] { return std::unique_ptr<Integrator>(std::make_unique<RaycastIntegrator>()); }, ShadowRays::Optional},
        {"raster", "z-buffer rasterisation: ray casting's first hits with the loops swapped, one sample per pixel, no shadows",
         "E(D|G)L|EL", "rasterisation shades the first visible surface only, like ray casting",
         [] { return std::unique_ptr<Integrator>(std::make_unique<RasterIntegrator>()); }, ShadowRays::Never},
        {"whitted", "adds mirror and refraction rays (Whitted ray tracing)", "ES*(D|G)L|ES*L",
         "Whitted ray tracing follows specular bounces only: no diffuse or glossy interreflection",
         [] { return std::unique_ptr<Integrator>(std::make_unique<WhittedIntegrator>()); }, ShadowRays::Optional},
        {"path", "path tracing with global illumination (physically based reading)", "E.*L",
         "path tracing follows every bounce",
         [] { return std::unique_ptr<Integrator>(std::make_unique<PathIntegrator>()); }},
        {"radiosity", "diffuse patches, form factors by ray casting, solved bounce by bounce (Jacobi)", "ED*L",
         "radiosity follows diffuse bounces only: no highlight, mirror or refraction",
         [] { return std::unique_ptr<Integrator>(std::make_unique<RadiosityIntegrator>()); }},
        {"bdpt", "bidirectional path tracing: also light from the light's side, caustics under point lights", "E.*L",
         "bidirectional path tracing follows every bounce, from the eye and from the lights",
         [] { return std::unique_ptr<Integrator>(std::make_unique<BdptIntegrator>()); }},
    };
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

}  // namespace lightpath
