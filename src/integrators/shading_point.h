#pragma once
// Everything an integrator knows about one surface hit, built in one place: where and what was
// hit, the direction back along the path, the normal turned towards it, which side of the material
// the path is on, the material and the BSDF that reads it, and the events its lobes name.
#include "geometry/surface_hit.h"
#include "integrators/path_record.h"
#include "materials/bsdf.h"
#include "math/ray.h"
#include "scene/scene_analysis.h"

namespace lightpath {

struct RenderContext;

struct ShadingPoint {
    SurfaceHit hit;
    Vec3 wo;        // unit, towards the previous vertex
    Vec3 normal;    // unit shading normal on the side of wo (Szymczak: "N should point to the side
                    // containing the viewpoint")
    bool entering;  // wo is outside the material
    const Material& material;
    const MaterialTerms& terms;  // which of the material's terms are non-zero
    Bsdf bsdf;

    // The event of scattering here through `lobe` (an index in the material's lobes()), labelled by the object.
    PathEvent eventOf(int lobe) const {
        const ScatterEvent e = bsdf.lobe(lobe).event;
        return {e.type, e.scatter, Subject::Object, hit.object, hit.point};
    }
};

// The shading point of `hit`, reached along `ray`.
ShadingPoint makeShadingPoint(const SurfaceHit& hit, const Ray& ray, const RenderContext& context,
                              TransportMode mode = TransportMode::Radiance);

}  // namespace lightpath
