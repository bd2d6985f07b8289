#pragma once
// An emissive object as a light: one sphere, or the triangles of one scene object, whose material
// emits radiance Le. Triangles emit on the side their winding's normal faces, or on both when the
// material says so (two_sided_emission, glTF's doubleSided); a sphere always on both sides, so a
// closed emissive sphere also lights its inside. Light sampling picks points
// uniformly by area, except on a sphere seen from outside, where it samples the cone of
// directions the sphere subtends (pbrt-v4 6.2.4): its density then stays finite and noiseless
// for a sphere of any size at any distance. A textured emission (materials/texture.h) is read at
// the texture coordinates of the point a ray hits or a sample picks (SceneGeometry::uvAt); the
// light's power, which only steers the choice of lights, takes the texture's mean.
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include "accel/scene_geometry.h"
#include "lights/light.h"
#include "materials/texture.h"

namespace lightpath {

class AreaLightSource final : public Light {
public:
    // `primitives`: scene-wide ids of the object's spheres or triangles; those without area are
    // left out. `twoSided`: its open surfaces emit from both sides too. Throws std::invalid_argument
    // when one-sided triangles and spheres mix: the two emit on different sides, and
    // pdfEmissionDirection, given only a normal, could not tell which applies (one scene object is
    // one sphere or a mesh).
    AreaLightSource(const PathEvent& event, ColorParameter emission, const SceneGeometry& geometry,
                    const std::vector<std::uint32_t>& primitives, bool twoSided = false);

    LightSample sample(const Vec3& receiver, Vec2 u) const override;
    float pdf(const Vec3& receiver, const Vec3& point, const Vec3& normal) const override;
    bool samplesByArea(const Vec3& receiver) const override;
    EmittedRay sampleEmission(Vec2 uPoint, Vec2 uDirection) const override;
    float pdfEmissionPosition() const override { return pdfArea_; }
    float pdfEmissionDirection(const Vec3& normal, const Vec3& direction) const override;
    EmittedRay emitAlong(const EmittedRay& from, const Vec3& direction) const override;
    Rgb radiance(const SurfaceHit& hit, const Vec3& towardViewer) const override;
    Rgb power() const override;
    bool isDelta() const override { return false; }

    float area() const { return area_; }
    bool empty() const { return shapes_.empty(); }
    // Its area is at least kMinSampledEmitterArea, so that 1/area is a float.
    bool sampleable() const override { return sampleable_; }

private:
    struct Shape {
        std::uint32_t primitive;
        float cumulativeArea;  // of the shapes up to and including this one
        // A triangle's normal, computed once rather than per sample (a profile of Whitted and
        // raycast renders had triangleNormal among the largest shading items); unused for a shape.
        Vec3 triangleNormal{0.0f};
    };
    struct SurfacePoint {
        Vec3 point, normal;
        Vec2 uv{0.0f};  // its texture coordinates, found only when the emission is textured
    };
    // A point uniformly by area: a shape in proportion to its area, then a point on it.
    SurfacePoint samplePoint(Vec2 u) const;
    // Le at texture coordinates `uv` (the constant when untextured).
    Rgb emissionAt(Vec2 uv) const;

    ColorParameter emission_;
    const SceneGeometry& geometry_;
    std::vector<Shape> shapes_;
    float area_ = 0.0f;
    float pdfArea_ = 0.0f;  // 1 / area_: the density of a point chosen by area, per unit area
    bool sampleable_ = false;
    bool twoSided_ = false;  // it emits from both sides: closed shapes (spheres), or a two-sided material
    // The light's one shape when its kind samples by solid angle (a sphere: its visible cone).
    const ShapeRecord* solidAngle_ = nullptr;
};

// Solid-angle density at `receiver` of a point sampled with `pdfArea` on a surface with `normal`;
// 0 where it would not be a finite float (a point seen edge-on, or a tiny light).
float areaToSolidAngle(float pdfArea, const Vec3& receiver, const Vec3& point, const Vec3& normal);
// The same from the vector `toPoint` (receiver to point) already measured: its squared length,
// its length and normal . toPoint. pdf_omega = pdf_area d^2 / |cos theta_light| (Pharr, Jakob and
// Humphreys, pbrt 4th ed., 4.2.3), with |cos theta_light| = |normal . toPoint| / d.
inline float areaToSolidAngle(float pdfArea, float distance2, float distance, float normalDotToPoint) {
    const float cosEmitter = std::fabs(normalDotToPoint) / distance;
    const float pdf = cosEmitter > 0.0f ? pdfArea * distance2 / cosEmitter : 0.0f;
    return std::isfinite(pdf) ? pdf : 0.0f;
}


}  // namespace lightpath
