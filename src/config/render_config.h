#pragma once
// One render's configuration, below the command line and serve: every option render, explain,
// serve (and lpe exercise) share, as plain values, checked once (validate) against the render options'
// schema (config/render_options.h) and the integrators' own schemas, and turned into what the
// renderer needs (a Scene, an AovSet, RenderOptions). Every error is a ConfigError naming its
// option. No command line, JSON or TOML here: the CLI (cli/render_flags.h) and serve
// (serve/settings.h) fill it.
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "config/config_error.h"
#include "config/lpe_verdict.h"
#include "film/aov_set.h"
#include "film/film.h"
#include "integrators/registry.h"
#include "render/renderer.h"
#include "scene/scene.h"
#include "schema/parameter_values.h"

namespace lightpath {

struct RenderConfig {
    RenderConfig();  // every option at its schema default

    std::string scenePath;
    std::string integrator;
    // The integrators' own parameters given, by name, as typed ("patches" -> "1024"). Those of the
    // chosen integrator's schema reach it; another integrator's are checked and left unused.
    std::map<std::string, std::string, std::less<>> integratorParameters;
    std::vector<std::string> lpes;  // [name=]EXPR
    std::string aovs;               // a preset, "none", or empty (classes unless lpes are given)
    int samplesPerPixel = 0;
    int maxDepth = 0;
    int threads = 0;
    std::uint64_t seed = 0;
    std::string resolution;  // WxH, empty for the scene's
    std::string sampler;
    std::string filter;  // the pixel filter (sampling/pixel_filter.h)
    double targetError = 0.0;
    bool noBeauty = false;
    bool noSkip = false;
    bool fit = false;  // frame the scene as if it had no [camera] (scene/framing.h)
    std::string shadows;  // "on", "off" or empty (the integrator's own)
    std::string accel;    // bvh, embree or none (brute force)
    bool quiet = false;   // no progress bar, no warnings
    std::string robust;   // on: robust numerics; off: the lecture's naive ones
    std::string sphereTest, triangleTest, rayOffset;  // per-method choices; empty: as robust says
    float epsilon = 0.0f;                             // t_min of ray-offset epsilon

    // Sets the option `name` (a render option, or a parameter of any registered integrator) from
    // its text as typed; the lpe option appends. Refuses text that is not of the option's type and
    // an unknown name; ranges and choices are validate()'s.
    void set(std::string_view name, const std::string& text);

    // The one check of every option against its schema (range, choices, the integrator and its
    // parameters, options that exclude each other), in the schema's order. Throws ConfigError.
    void validate() const;

    // The chosen integrator's parameters (its schema's defaults and those given). After validate().
    ParameterValues integratorValues() const;
    // With the resolution applied; framed (scene/framing.h), and lit by kDefaultLightName when it
    // has no light, when it has no [camera] or under --fit.
    Scene loadScene() const;
    // The aovs preset's AOVs (made from `scene` for `lights`), then every lpe.
    std::vector<lpe::NamedExpression> expressions(const Scene* scene = nullptr) const;
    // Judges every AOV (config/lpe_verdict.h): refuses one no path of the integrator can ever fill;
    // warns (on stderr, or into `warnings` when given) of one black in `scene`, of a label the scene
    // lacks, and of overlaps, except among a preset's own AOVs.
    AovSet buildAovSet(const Scene& scene, std::vector<std::string>* warnings = nullptr) const;
    // The same with `judge` (made by judge(scene)), which keeps its judgements for the render.
    AovSet buildAovSet(const Scene& scene, const Judge& judge, std::vector<std::string>* warnings = nullptr) const;
    // The judge of this configuration's integrator in `scene`. Throws ConfigError for an unknown
    // integrator.
    Judge judge(const Scene& scene) const;
    RenderOptions renderOptions() const;  // after validate()
    // Refuses a render whose pixel memory, plus `outputBytes` to write its files, is more than this
    // process can get (render/memory_limit.h): names the amount, its parts, the layers, the bound,
    // and what to change (fewer layers, fewer pixels: a resolution that fits).
    void refuseBeyondMemory(const PixelMemory& memory, std::uint64_t outputBytes = 0) const;
    // After a render: warns of each AOV that could have received light but got none.
    void warnEmptyAovs(const Film& film, const AovSet& aovs, const Judge& judge) const;
};

// The point light a framed scene without light gets: its name (an LPE label), and how far above
// and to the left of the eye it stands, per unit of the eye's distance to what it frames.
inline constexpr std::string_view kDefaultLightName = "default-light";
inline constexpr float kDefaultLightOffset = 0.3f;

// The error of one AOV, `name` (field "lpe:NAME").
ConfigError lpeError(const std::string& name, const std::string& message);

}  // namespace lightpath
