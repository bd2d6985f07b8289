#pragma once
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "geometry/coverage.h"
#include "geometry/shape.h"
#include "geometry/shapes.h"
#include "math/types.h"
#include "scene/camera.h"
#include "scene/scene_light.h"
#include "materials/material.h"
#include "media/medium.h"

namespace lightpath {

// One named thing in the scene file: a sphere, a plane, a shape of a registered kind (a disk), a
// triangle, or the part of a mesh with one material. Its label in light paths is its name, or its material's name when it has none.
struct SceneObject {
    std::string name;
    std::uint32_t material = 0;
    // A [[lights]] quad or sphere: its emission ends a path with `L`. Any other surface whose
    // material emits ends it with OSL's `O` (object emission).
    bool declaredLight = false;
    // Whether it bounds a volume (its kind takes `interior`: a sphere, a closed mesh): a ray through
    // it enters `interior` or leaves for the world's medium. Any other surface (a quad, a plane, a
    // disk, a triangle: a glass pane) leaves the ray in the medium it was in.
    bool enclosesVolume = false;
    // The medium that fills it, an index into Scene::media.
    std::uint32_t interior = kNoMedium;
};

// Everything a scene file describes, as plain data.
struct Scene {
    std::filesystem::path source;
    CameraDescription camera;
    bool cameraGiven = false;  // the file has a [camera]; else the render frames the scene (scene/framing.h)
    Rgb background{0.0f};  // radiance of rays that escape (a `B` event)
    Rgb ambient{0.0f};     // Ia of the illumination formula (an `L'ambient'` event)

    std::vector<MaterialSlot> materials;
    std::vector<MediumSlot> media;             // [media.NAME], in file order
    std::uint32_t worldMedium = kNoMedium;     // [world] medium: fills all space outside objects
    // Some material is an `interface` (index-matched boundary): rays cross such surfaces without an
    // event. False keeps every integrator on its path without the crossing loop (bit-identical).
    bool interfaces = false;
    std::vector<LightSlot> lights;  // [[lights]] without a shape (point lights)
    std::vector<SceneObject> objects;

    std::vector<Sphere> spheres;
    std::vector<Plane> planes;
    std::vector<ShapeRecord> shapes;  // of the registered kinds (geometry/shape.h), e.g. disks
    std::vector<Triangle> triangles;
    // Empty when no triangle has vertex normals, else one entry per triangle (meshes' `vn`).
    std::vector<TriangleNormals> triangleNormals;
    // Empty when no triangle has texture coordinates, else one entry per triangle (meshes' `vt`).
    std::vector<TriangleUvs> triangleUvs;
    // Empty when no triangle has tangents, else one entry per triangle (glTF's TANGENT).
    std::vector<TriangleTangents> triangleTangents;
    // Empty when no triangle has vertex colours, else one entry per triangle (glTF's COLOR_0).
    std::vector<TriangleColors> triangleColors;

    // Legal but probably unintended, located like errors ("FILE:LINE:COL: KEY: ..."), e.g. a
    // triangle without area. The command line prints them.
    std::vector<std::string> warnings;

    // Medium `index`, or null for vacuum (kNoMedium).
    const Medium* medium(std::uint32_t index) const { return index == kNoMedium ? nullptr : &*media[index]; }

    // The medium a ray in medium `current` is in after passing through the surface of `object`
    // (media do not nest).
    std::uint32_t mediumBeyond(std::uint32_t object, bool entering, std::uint32_t current) const {
        const SceneObject& o = objects[object];
        if (!o.enclosesVolume) return current;
        return entering ? o.interior : worldMedium;
    }

    // Whether rays cross the surface of `object` without scattering (an `interface` material).
    bool crossedWithoutEvent(std::uint32_t object) const {
        return interfaces && materials[objects[object].material]->isInterface();
    }

    // The index of `medium` in `media`; kNoMedium for null (vacuum).
    std::uint32_t indexOf(const Medium* medium) const {
        for (std::uint32_t i = 0; i < media.size(); ++i)
            if (&*media[i] == medium) return i;
        return kNoMedium;
    }

    // Per object its material's cut-out (materials/alpha.h), what SceneGeometry looks through;
    // empty when nothing is cut out. An emitter is never cut out: its light samples points all
    // over it, which the cut-out's holes would contradict. Nor is the boundary of a medium: a ray
    // through a hole would be inside without having entered.
    std::vector<std::shared_ptr<const SurfaceCoverage>> objectCoverage() const {
        std::vector<std::shared_ptr<const SurfaceCoverage>> coverage(objects.size());
        bool any = false;
        for (std::size_t i = 0; i < objects.size(); ++i) {
            const Material& material = *materials[objects[i].material];
            if (!material.alpha || !material.emission.black() || objects[i].interior != kNoMedium) continue;
            coverage[i] = material.alpha;
            any = true;
        }
        if (!any) coverage.clear();
        return coverage;
    }

    const std::string& labelOf(std::uint32_t object) const {
        const SceneObject& o = objects[object];
        return o.name.empty() ? materials[o.material]->name : o.name;
    }
};

}  // namespace lightpath
