#pragma once
// No silent black AOVs: an expression that no path of the chosen integrator can ever match is
// refused before rendering, with the reason and a fix. Judged on automata (lpe::commonPath), not
// by rendering: against every path lightpath renders (kRenderedPaths), the integrator's own path
// language (integrators/registry.h) and, given a scene, which events each label can be on.
#include <optional>
#include <string>

#include "integrators/registry.h"
#include "lpe/analysis.h"
#include "scene/scene.h"

namespace lightpath {

// Every path lightpath renders, media included: kRenderedPaths with volume events let in (a
// volume scattering has no scattering type, OSL's x: integrators/direct_light.h, MediumPoint).
inline constexpr const char* kPathsWithVolumes = "E(<[RT][DGSs]>|<Vx>)*[LOB]";

// Which events carry each label of `scene`: a light's name (and "ambient") only L events, an
// object's label (its name, else its material's) R and T events, and L for a [[lights]] quad or
// sphere, O for another emitting surface.
lpe::LabelPlacement labelPlacement(const Scene& scene);

// Why `expression` matches no path of kRenderedPaths, with a fix ("did you mean ...").
std::string whyNeverRendered(const std::string& expression);

// Nothing when `expression` can accept some path `integrator` produces (in `scene`, if given);
// otherwise why not, with a fix, e.g. "never reaches a light: ...". Throws lpe::SyntaxError.
std::optional<std::string> whyNeverFilled(const std::string& expression, const IntegratorInfo& integrator,
                                          const Scene* scene = nullptr);

}  // namespace lightpath
