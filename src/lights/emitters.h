#pragma once
// Every emissive primitive of the scene (spheres and triangles whose material has emission), for
// next-event estimation: pick one in proportion to its power, then a point on it uniformly by area.
#include <cstdint>
#include <vector>

#include "geometry/scene_geometry.h"
#include "geometry/surface_hit.h"
#include "math/types.h"
#include "scene/scene.h"

namespace lightpath {

struct EmitterSample {
    Vec3 point{0.0f};
    Vec3 normal{0.0f};       // outward unit normal of the emitter at point
    Rgb radiance{0.0f};      // Le towards the receiver (zero when seen from behind)
    float pdfArea = 0.0f;    // density per unit area, the pick of the emitter included
    std::uint32_t object = 0;
    std::uint32_t primitive = 0;
};

class EmitterSet {
public:
    EmitterSet(const Scene& scene, const SceneGeometry& geometry);

    bool empty() const { return emitters_.empty(); }
    // A point on an emitter as seen from `receiver`: radiance is zero when the receiver is behind
    // a one-sided emitter (a triangle faces where its winding's normal points; spheres emit on
    // both sides, so a closed emissive sphere also lights its inside).
    EmitterSample sample(const Vec3& receiver, float uPick, Vec2 u) const;
    // Density per unit area with which sample() would return a point on `primitive`.
    float pdfArea(std::uint32_t primitive) const { return pdfArea_[primitive]; }
    // Emitted radiance leaving the emitter at `hit` towards `towardViewer`; front side only.
    Rgb radiance(const SurfaceHit& hit, const Vec3& towardViewer) const;

private:
    struct Emitter {
        std::uint32_t primitive;
        float area;
        float cumulative;  // of pick probabilities, up to and including this one
    };
    const Scene& scene_;
    const SceneGeometry& geometry_;
    std::vector<Emitter> emitters_;
    std::vector<float> pdfArea_;  // by primitive id: pick probability / area; 0 for non-emitters
};

// Solid-angle density at `receiver` of a point sampled with `pdfArea` on a surface with `normal`.
float areaToSolidAngle(float pdfArea, const Vec3& receiver, const Vec3& point, const Vec3& normal);

}  // namespace lightpath
