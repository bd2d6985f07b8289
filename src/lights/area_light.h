#pragma once
// An emissive object as a light: every sphere and triangle of one scene object whose material
// emits radiance Le, sampled uniformly by area. Triangles emit on the side their winding's normal
// faces; spheres on both sides, so a closed emissive sphere also lights its inside.
#include <cstdint>
#include <vector>

#include "geometry/scene_geometry.h"
#include "lights/light.h"

namespace lightpath {

class AreaLightSource final : public Light {
public:
    // `primitives`: scene-wide ids of the object's spheres and triangles with non-zero area.
    AreaLightSource(const PathEvent& event, Rgb emission, const SceneGeometry& geometry,
                    const std::vector<std::uint32_t>& primitives);

    LightSample sample(const Vec3& receiver, Vec2 u) const override;
    float pdf(const Vec3& receiver, const Vec3& point, const Vec3& normal) const override;
    EmittedRay sampleEmission(Vec2 uPoint, Vec2 uDirection) const override;
    float pdfEmissionDirection(const Vec3& normal, const Vec3& direction) const override;
    Rgb radiance(const SurfaceHit& hit, const Vec3& towardViewer) const override;
    Rgb power() const override;
    bool isDelta() const override { return false; }

    float area() const { return area_; }
    bool empty() const { return shapes_.empty(); }

private:
    struct Shape {
        std::uint32_t primitive;
        float cumulativeArea;  // of the shapes up to and including this one
    };
    struct SurfacePoint {
        Vec3 point, normal;
        bool twoSided;
    };
    // A point uniformly by area: a shape in proportion to its area, then a point on it.
    SurfacePoint samplePoint(Vec2 u) const;

    Rgb emission_;
    const SceneGeometry& geometry_;
    std::vector<Shape> shapes_;
    float area_ = 0.0f;
    bool spheres_ = false;  // its shapes are spheres (one object is one sphere or a mesh), two-sided
};

// Solid-angle density at `receiver` of a point sampled with `pdfArea` on a surface with `normal`.
float areaToSolidAngle(float pdfArea, const Vec3& receiver, const Vec3& point, const Vec3& normal);

}  // namespace lightpath
