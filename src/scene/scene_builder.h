#pragma once
// What a [[lights]] type may add to the scene being loaded: a light without a shape (point), or an
// emissive object and its shapes (quad, sphere); and what a shape type (src/shapes/) adds: an
// object and its shape (a sphere, a plane, a triangle, or a record of its kind's ShapeOps table),
// or a mesh's objects, materials and triangles. An interface, so types add to the scene without
// knowing the loader; the loader implements it.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "geometry/shape.h"
#include "geometry/shapes.h"
#include "materials/material.h"
#include "math/types.h"
#include "media/medium.h"
#include "scene/camera.h"
#include "scene/scene_light.h"
#include "schema/format.h"
#include "schema/parameter_values.h"

namespace lightpath {

class SceneBuilder {
public:
    virtual ~SceneBuilder() = default;

    virtual void addLight(LightSlot light) = 0;
    // An area light's object: a material of its own that only emits `radiance`, labelled `name` or,
    // unnamed, by that material's name "area-light-K". Returns the object index shapes store.
    virtual std::uint32_t addEmitterObject(std::string name, const ColorParameter& radiance) = 0;
    virtual void addSphere(const Sphere& sphere) = 0;
    virtual void addPlane(const Plane& plane) = 0;
    // A triangle shaded flat (its geometric normal).
    virtual void addTriangle(const Triangle& triangle) = 0;
    // A triangle shaded with the normals at its corners interpolated (a mesh's `vn`); a zero
    // normal shades it flat.
    virtual void addTriangle(const Triangle& triangle, const TriangleNormals& normals) = 0;
    // The texture coordinates at the corners of the triangle added last (a mesh's `vt`).
    virtual void setTriangleUvs(const TriangleUvs& uvs) { (void)uvs; }
    // The tangents at the corners of the triangle added last (glTF's TANGENT).
    virtual void setTriangleTangents(const TriangleTangents& tangents) { (void)tangents; }
    // The colours at the corners of the triangle added last (glTF's COLOR_0).
    virtual void setTriangleColors(const TriangleColors& colors) { (void)colors; }
    // A shape declaration's object, from its `name` (optional) and `material` (a material of the
    // scene, else a located error at `material`). Returns the object index its shapes store.
    virtual std::uint32_t addShapeObject(const ParameterValues& values) = 0;
    // An object labelled `name` (empty: by its material's name) made of the scene's material
    // number `material`; a mesh makes one per material its faces use. Returns the object index.
    virtual std::uint32_t addObject(std::string name, std::uint32_t material) = 0;
    // A medium a model file brings (glTF's KHR_materials_volume); returns its index in the scene's
    // media, for setInterior.
    virtual std::uint32_t addMedium(MediumSlot medium) {
        (void)medium;
        return kNoMedium;
    }
    // Object `object` (from addObject) bounds medium `medium`: a ray through its surface enters it.
    // A declaration's `interior`, where given, replaces it.
    virtual void setInterior(std::uint32_t object, std::uint32_t medium) {
        (void)object;
        (void)medium;
    }
    // The index of the scene's material named as `material` is, which wins if there is one (its
    // [materials] table or an earlier mesh's: how a scene retunes an MTL material), else of
    // `material`, added (a mesh's MTL material, or its grey).
    virtual std::uint32_t sceneMaterial(MaterialSlot material) = 0;
    // The folder of the scene file: the files it names (a mesh's OBJ) are relative to it.
    virtual std::filesystem::path folder() const = 0;
    // The emission of object `object`'s material, its mean where textured (for tooSmallToSampleWarning).
    virtual Rgb emissionOf(std::uint32_t object) const = 0;
    virtual void addShape(const ShapeRecord& shape) = 0;
    // A camera a model file brings (a glTF camera): the scene's camera unless it has one already
    // (its [camera], or an earlier model's). Returns whether it was taken.
    virtual bool offerCamera(const CameraDescription& camera) {
        (void)camera;
        return false;
    }
    // A located warning ("FILE:LINE:COL: KEY: ..."), printed by the command line.
    virtual void warn(std::string located) = 0;
};

// An emitter whose area is below kMinSampledEmitterArea is legal but cannot be light-sampled (its
// density per unit area would not be a float): said once, where it is declared. LightSet then
// leaves it to the rays that hit it. Nothing when it emits nothing or is large enough.
inline std::optional<std::string> tooSmallToSampleWarning(const char* what, double area, const Rgb& emission) {
    if (isBlack(emission) || area >= kMinSampledEmitterArea) return std::nullopt;
    return std::string("the emitting ") + what + " has an area of " + formatNumber(area) +
           ", below the smallest a light can sample (" + formatNumber(kMinSampledEmitterArea) +
           "): its light is seen where a ray hits it but never sampled";
}

}  // namespace lightpath
