#pragma once
// The options `render` and `explain` share, and how they become a scene, an AOV set and render
// options. Every error here is the user's input: it is reported as a CLI::Error with exit code 2.
#include <CLI/CLI.hpp>

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "film/aov_set.h"
#include "film/film.h"
#include "render/renderer.h"
#include "scene/scene.h"

namespace lightpath {

struct RenderSetup {
    std::string scenePath;
    std::string integrator = "whitted";
    std::vector<std::string> lpes;   // [name=]EXPR
    std::string aovs;                // "classes", "none" or empty (classes unless --lpe is given)
    int samplesPerPixel = 1;
    int maxDepth = 5;
    int threads = 0;
    std::uint64_t seed = 0;
    std::string resolution;          // WxH, empty for the scene's
    std::string sampler = "sobol";
    std::string filter = "box";      // the pixel filter (sampling/pixel_filter.h)
    double targetError = 0.0;
    bool noBeauty = false;
    bool noSkip = false;
    std::string shadows;             // "on", "off" or empty (the integrator's own)
    std::string accel = "bvh";       // bvh, embree or none (brute force)
    bool quiet = false;              // no progress bar, no warnings
    std::string robust = "on";       // on: robust numerics (default); off: the lecture's naive ones
    std::string sphereTest, triangleTest, rayOffset;  // per-method choices; empty: as --robust says
    float epsilon = 1e-4f;           // t_min of --ray-offset epsilon
    // --integrator radiosity: patch size (0: from the budget), patch budget, rays, display.
    float patchSize = 0.0f;
    std::size_t patchBudget = RadiosityOptions{}.patchBudget;
    int formFactorRays = RadiosityOptions{}.formFactorRays;
    int lightSamples = RadiosityOptions{}.lightSamples;
    std::string radiosityDisplay = "smooth";

    void addOptions(CLI::App& command);

    Scene loadScene() const;                           // with --resolution applied
    // The --aovs preset's AOVs (made from `scene` for `lights`), then every --lpe.
    std::vector<lpe::NamedExpression> expressions(const Scene* scene = nullptr) const;
    // Judges every AOV (config/lpe_verdict.h): refuses one no path of the integrator can ever fill;
    // warns (on stderr, or into `warnings` when given) of one black in `scene`, of a label the scene
    // lacks, and of overlaps, except among a preset's own AOVs.
    AovSet buildAovSet(const Scene& scene, std::vector<std::string>* warnings = nullptr) const;
    RenderOptions renderOptions() const;
    // Refuses (exit 2) a render whose pixel memory, plus `outputBytes` to write its files, is more
    // than this process can get (render/memory_limit.h): names the amount, its parts, the layers,
    // the bound, and what to change (fewer layers, fewer pixels: a --resolution that fits).
    void refuseBeyondMemory(const PixelMemory& memory, std::uint64_t outputBytes = 0) const;
    // After a render: warns of each AOV that could have received light but got none.
    void warnEmptyAovs(const Film& film, const AovSet& aovs, const Scene& scene) const;

private:
    void refuseNeverFilled(const std::vector<lpe::NamedExpression>& set, const Scene& scene,
                           const std::function<void(const std::string&)>& warn) const;
};

}  // namespace lightpath
