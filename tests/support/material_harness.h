#pragma once
// What the material suites (microfacet, conductor, dielectric) share: an outgoing direction in the
// shading frame by its cosine, and a render of a scene's classes AOVs for path-vs-bdpt t-tests.
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "film/aov_presets.h"
#include "film/aov_set.h"
#include "render/renderer.h"

namespace lightpath::test {

// The unit direction at cos theta = cosOut from +z (the shading normal), at azimuth phi.
inline Vec3 outgoing(double cosOut, double phi = 0.0) {
    const double s = std::sqrt(std::max(0.0, 1.0 - cosOut * cosOut));
    return Vec3{float(s * std::cos(phi)), float(s * std::sin(phi)), float(cosOut)};
}

// The scene rendered by `integrator` into the classes AOVs, at most five bounces.
inline Film renderClassesFilm(const Scene& scene, const char* integrator, int spp, std::uint64_t seed) {
    const AovSet aovs(classesSet());
    RenderOptions options;
    options.integrator = integrator;
    options.samplesPerPixel = spp;
    options.maxDepth = 5;
    options.seed = seed;
    return Renderer(scene, aovs, options).render().film;
}

}  // namespace lightpath::test
