#pragma once
// The standard checks every integrator of the registry gets (docs/extending.md): the classes AOVs
// sum to the beauty with `rest` zero, images are bit-identical for 1 and 3 threads, a request for
// one AOV renders it bit-identically to the full render (skipping changes nothing asked for), the
// light on the paths it shares with the path tracer is the path tracer's (a Welch test, whose
// control, the scene 5% brighter, must be rejected), and degenerate scenes give finite images that
// are black or right.
#include <string>

#include "check_result.h"
#include "integrators/registry.h"
#include "render/renderer.h"
#include "scene/scene.h"

namespace lightpath::conformance {

// Rejection threshold of one agreement test.
inline constexpr double kAgreementAlpha = 1e-3;

// The options every check renders with (small, two threads, radiosity's mesh coarse).
RenderOptions checkOptions(const IntegratorInfo& integrator);

CheckResult checkAovsSumToBeauty(const IntegratorInfo& integrator, const Scene& scene);
CheckResult checkThreadDeterminism(const IntegratorInfo& integrator, const Scene& scene);
CheckResult checkSkipIdentity(const IntegratorInfo& integrator, const Scene& scene);

// The integrator's light on its own path language (registry.h's pathLanguage), which the path
// tracer follows too, against the path tracer's: image means over independent renders.
struct Agreement {
    double pValue = 1.0;
    double mean = 0.0, pathMean = 0.0;  // of the image's R + G + B per pixel
};
// `scene` rendered by `integrator` and by the path tracer, and `control` (a brighter copy) by
// `integrator` against the same path-traced renders, which are made once.
struct Agreements {
    Agreement same, control;
};
Agreements agreementsWithPath(const IntegratorInfo& integrator, const Scene& scene, const Scene& control);
// Every light and emitter `factor` times brighter.
Scene brighter(Scene scene, float factor);

// An empty scene shows its background in every pixel; a sphere light alone shows its radiance
// where it covers a pixel and nothing brighter anywhere; a camera inside a diffuse sphere (albedo
// rho, radius R) around a point light of intensity I sees rho I / R^2 in E D L and, with every
// bounce, at most that over 1 - rho. Every value finite, no contribution dropped as non-finite.
CheckResult checkDegenerateScenes(const IntegratorInfo& integrator);

}  // namespace lightpath::conformance
