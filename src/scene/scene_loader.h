#pragma once
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

#include "scene/scene.h"

namespace lightpath {

// A scene file that cannot be used. what() reads "FILE:LINE:COLUMN: KEY: what was expected",
// e.g. "scenes/a.toml:12:10: spheres[2].radius: expected a positive number, got -1".
class SceneError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Every number of a scene, in its TOML file or its meshes' OBJ/MTL, lies within +-kMaxMagnitude
// (scenes/README.md, "Conventions"): the renderer computes in single precision, where the product
// of a few numbers near its largest, 3.4e38 (a radiance times reflectances times an attenuation,
// or a distance squared), would overflow to infinity.
inline constexpr double kMaxMagnitude = 1e6;
// How error messages state the limit.
inline constexpr std::string_view kMaxMagnitudeText = "1e6";
inline constexpr std::string_view kMagnitudeRange = "from -1e6 to 1e6";

// Reads a TOML scene (format: scenes/README.md), or an OBJ file (isObjFile) as a scene of that one
// mesh, without camera or light, or a glTF file (isGltfFile) as the scene of that one model, with
// its own camera and lights if it has them. Throws SceneError; never returns a partial scene.
Scene loadScene(const std::filesystem::path& path);
bool isObjFile(const std::filesystem::path& path);   // by its extension, .obj in any case
bool isGltfFile(const std::filesystem::path& path);  // .gltf or .glb, in any case
// The same from memory (for fuzzing and tests): `path` names the file in errors, and mesh files
// are looked up next to it.
Scene loadSceneFromText(std::string_view text, const std::filesystem::path& path);

}  // namespace lightpath
