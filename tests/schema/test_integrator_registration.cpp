// Every shipped integrator registers itself (its own .cpp) and survives static linking into this
// binary, in the lecture's order; materials and lights too.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "integrators/registry.h"
#include "scene/light_type.h"
#include "scene/shape_type.h"
#include "materials/material_type.h"

namespace lightpath {

TEST_CASE("every shipped type is registered in the render tests") {
    CHECK(integratorNames() ==
          std::vector<std::string>{"raycast", "raster", "whitted", "path", "radiosity", "bdpt", "photon", "sppm"});
    CHECK(findIntegrator("whitted")->shadowRays == ShadowRays::Optional);
    // Its path language, which leaves out the ambient term only ray casting and Whitted's formula add.
    CHECK(std::string(findIntegrator("radiosity")->schema.events) == "ED*[<L.[^'ambient']>OB]");
    CHECK(MaterialRegistry::instance().names() == std::vector<std::string>{"phong", "modified-phong", "microfacet", "interface", "conductor", "dielectric"});
    CHECK(LightRegistry::instance().names() == std::vector<std::string>{"point", "quad", "sphere", "spot", "directional"});
    CHECK(ShapeRegistry::instance().names() == std::vector<std::string>{"sphere", "plane", "disk", "triangle", "mesh", "gltf"});
}

}  // namespace lightpath
