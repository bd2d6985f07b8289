#pragma once
// Who reaches what (issue #25): for a class of light paths and an integrator, whether it can
// produce some path of the class with point lights only and with area lights, read off the
// integrator's declared languages (integrators/registry.h: pathLanguage, pointLightLanguage) by
// automata (lpe::commonPath), never by rendering. The lecture's table of methods, computed.
#include <array>
#include <string>

#include "integrators/registry.h"

namespace lightpath {

// The classes: ray casting, ray tracing, mirrors, radiosity, caustics, a caustic seen in a
// mirror, emitters seen directly.
inline constexpr std::array<const char*, 7> kReachClasses = {
    "E(D|G)L", "ES+(D|G)L", "ES+L", "ED+L", "E(D|G)S+<L.>", "ES+(D|G)S+<L.>", "EL"};

struct Reach {
    bool pointLights = false;
    bool areaLights = false;
};

// Throws lpe::SyntaxError for a malformed class.
Reach reachOf(const IntegratorInfo& integrator, const std::string& pathClass);

}  // namespace lightpath
