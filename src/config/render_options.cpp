#include "config/render_options.h"

#include "film/aov_presets.h"
#include "integrators/registry.h"
#include "transport/path_event.h"

namespace lightpath {

const TypeSchema& renderOptionsSchema() {
    using T = ParameterType;
    static const TypeSchema schema{
        "render",
        "options",
        "the options of render, explain and serve",
        {
            {.name = "scene", .type = T::Text, .doc = "Scene file (TOML, see scenes/README.md)", .required = true},
            {.name = "integrator", .type = T::Name, .defaultText = "whitted", .doc = "The light transport method"},
            {.name = "lpe", .type = T::Text,
             .doc = "An AOV as [name=]EXPR, e.g. --lpe 'direct=E(D|G)L'; repeatable. Replaces the default classes set "
                    "unless --aovs classes is also given"},
            {.name = "aovs", .type = T::Name,
             .doc = "Predefined AOV set"},
            {.name = "spp", .type = T::Integer, .defaultText = "1", .range = {1.0, double(kMaxSamplesPerPixel)},
             .doc = "Samples per pixel (1 = through the pixel centre)"},
            {.name = "sampler", .type = T::Name, .defaultText = "sobol",
             .doc = "Pixel sample sequence: sobol (Owen-scrambled, low discrepancy), stratified, or independent",
             .choices = "independent|stratified|sobol"},
            {.name = "filter", .type = T::Name, .defaultText = "box",
             .doc = "Pixel reconstruction filter, by filter importance sampling: box (the pixel's square), tent (radius "
                    "1), gaussian (sigma 0.5, radius 1.5) or blackman-harris (radius 1.5, as Cycles' default); a single "
                    "sample per pixel always goes through the centre",
             .choices = "box|tent|gaussian|blackman-harris"},
            {.name = "target-error", .type = T::Number, .defaultText = "0", .range = {0.0, 1.0},
             .doc = "Adaptive sampling: stop a pixel once the standard error of its mean is below this fraction of it "
                    "(e.g. 0.02); --spp is then the most a pixel may take"},
            {.name = "max-depth", .type = T::Integer, .defaultText = "5", .range = {0.0, double(kMaxDepth)},
             .doc = "Most specular bounces (whitted), scattering events (path) or bounces (radiosity)"},
            {.name = "resolution", .type = T::Text,
             .doc = "Image size WxH, overriding the scene's; the vertical field of view is kept"},
            {.name = "threads", .type = T::Integer, .defaultText = "0", .range = {0.0, 1024.0},
             .doc = "Worker threads (0 = all cores)"},
            {.name = "seed", .type = T::Integer, .defaultText = "0", .range = kNonNegative,
             .doc = "Seed of the per-pixel sample sequences"},
            {.name = "no-beauty", .type = T::Boolean, .defaultText = "false",
             .doc = "Compute only the requested AOVs (no beauty, no rest): paths none of them accepts are not traced"},
            {.name = "accel", .type = T::Name, .defaultText = "bvh",
             .doc = "Closest-hit and shadow-ray search: bvh (ours), embree (if built with it; triangles) or none (test "
                    "every primitive)",
             .choices = "bvh|embree|none"},
            {.name = "quiet", .type = T::Boolean, .defaultText = "false",
             .doc = "No progress bar (shown on a terminal for renders over a second) and no warnings; errors are always "
                    "shown"},
            {.name = "robust", .type = T::Name, .defaultText = "on",
             .doc = "Numerics: on (stable sphere test, watertight triangles, error-bound ray offsets) or off (the "
                    "lecture's b^2-4ac, Moller-Trumbore with |det| < 1e-6, t_min = --epsilon)",
             .choices = "on|off"},
            {.name = "sphere-test", .type = T::Name, .doc = "Override --robust for spheres: stable or naive",
             .choices = "stable|naive"},
            {.name = "triangle-test", .type = T::Name,
             .doc = "Override --robust for triangles: watertight or moller-trumbore", .choices = "watertight|moller-trumbore"},
            {.name = "ray-offset", .type = T::Name,
             .doc = "Override --robust for secondary ray origins: robust, wachter-binder, epsilon, none or own-primitive "
                    "(the lecture's: ignore the surface the ray leaves)",
             .choices = "robust|wachter-binder|epsilon|none|own-primitive"},
            {.name = "epsilon", .type = T::Number, .unit = "scene units", .defaultText = "0.0001", .range = kPositive,
             .doc = "t_min of --ray-offset epsilon"},
            {.name = "shadows", .type = T::Name,
             .doc = "Shadow rays of raycast and whitted: on (default) or off (every light counts as visible: "
                    "Szymczak's formula with S_i = 1, what the raster integrator shows)",
             .choices = "on|off"},
            {.name = "no-skip", .type = T::Boolean, .defaultText = "false",
             .doc = "Trace every ray and evaluate every term, even those that cannot contribute (for comparison)"},
            {.name = "fit", .type = T::Boolean, .defaultText = "false",
             .doc = "Move the camera to frame the whole scene, along its own view, as a scene without [camera] is "
                    "framed; a scene without a light then gets the default light (scenes/README.md)"},
        },
        ""};
    return schema;
}

std::vector<std::string> optionChoices(const Parameter& option) {
    if (option.name == "integrator") return integratorNames();
    if (option.name == "aovs") {
        std::vector<std::string> presets = aovPresetNames();
        presets.emplace_back("none");
        return presets;
    }
    return choicesOf(option);
}

std::string optionHelp(const Parameter& option) {
    std::string help(option.doc);
    if (option.name == "aovs") help += ": " + aovPresetHelp();
    if (option.name == "integrator") {
        help += ": ";
        bool first = true;
        for (const IntegratorInfo& info : integrators()) {
            help += (first ? "" : "; ") + std::string(info.name) + ": " + info.summary + " (" + info.pathLanguage + ")";
            first = false;
        }
    }
    return help;
}

}  // namespace lightpath
