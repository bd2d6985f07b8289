#include "config/lpe_feasibility.h"

#include <algorithm>

#include "integrators/event_symbols.h"
#include "transport/path_event.h"
#include "lpe/automaton.h"
#include "lpe/path_string.h"
#include "lpe/reading.h"
#include "scene/emission.h"

namespace lightpath {
namespace {

using lpe::EventType;

const std::vector<EventType> kLightEvents = {EventType::Emitter};
const std::vector<EventType> kObjectEvents = {EventType::Reflection, EventType::Transmission, EventType::ObjectEmission};

// Any event sequence that ends at an emitter or the background.
constexpr const char* kEndsAtEmitter = ".*[LOB]";

std::string quotedExpression(const std::string& text) { return "'" + text + "'"; }

// Is there a `|` outside every group and label? Then appending an event needs parentheses.
bool alternatesAtTop(const std::string& text) {
    int depth = 0;
    bool inLabel = false;
    for (const char c : text) {
        if (c == '\'') inLabel = !inLabel;
        if (inLabel) continue;
        depth += (c == '(' || c == '[' || c == '<') ? 1 : (c == ')' || c == ']' || c == '>') ? -1 : 0;
        if (c == '|' && depth == 0) return true;
    }
    return false;
}

// The integrators whose language does hold a path of `expression`.
std::string integratorsThatCan(const std::string& expression, const lpe::LabelPlacement& placement) {
    std::string names;
    for (const IntegratorInfo& other : integrators()) {
        if (lpe::haveCommonPath({expression, kRenderedPaths, other.pathLanguage}, placement))
            names += (names.empty() ? "" : " or ") + std::string("--integrator ") + other.name;
    }
    return names;
}

}  // namespace

// Why `expression` matches no path lightpath renders at all.
std::string whyNeverRendered(const std::string& expression) {
    if (const auto spelling = lpe::labelledEventSpelling(expression); spelling && lpe::haveCommonPath({*spelling, kRenderedPaths})) {
        return "a letter followed by a label is two events (L'key' is a light, then an event labelled key); "
               "did you mean " + quotedExpression(*spelling) + "?";
    }
    if (const auto osl = lpe::oslPrecedenceReading(expression); osl && lpe::haveCommonPath({*osl, kRenderedPaths})) {
        return "| binds loosest, as in regular expressions, and so it matches no path; OSL binds | tighter "
               "than concatenation: did you mean " + quotedExpression(*osl) + "?";
    }
    if (!lpe::haveCommonPath({expression, kEndsAtEmitter})) {
        return "never reaches a light: every path ends at a light, an emitting object or the background "
               "(L matches all three), e.g. write " +
               quotedExpression((alternatesAtTop(expression) ? "(" + expression + ")" : expression) + "L");
    }
    if (lpe::haveCommonPath({expression, kPathsWithVolumes})) {
        return "needs a volume event (V): only scenes with [media] have them, under --integrator " + mediaRenderers();
    }
    return "matches no path lightpath renders: a path is E, then reflections and transmissions "
           "(<[RT][DGSs]>), then one light, emitting object or background ([LOB])";
}

namespace {

// "R, T and L events (<R.'panel'>, <T.'panel'>, <L.'panel'>)": the events `label` is on in the
// scene, each written as the expression that names it there.
std::string eventsOf(const std::string& label, const std::vector<EventType>& types) {
    std::string letters, tuples;
    for (std::size_t i = 0; i < types.size(); ++i) {
        const std::string letter(1, lpe::letter(types[i]));
        letters += (i == 0 ? "" : i + 1 == types.size() ? " and " : ", ") + letter;
        tuples += (i == 0 ? "<" : ", <") + letter + ".'" + label + "'>";
    }
    return letters + " events (" + tuples + ")";
}

// The first label of `expression` whose placement in `scene` rules it out, with what it is and
// what the expression wanted it to be.
std::optional<std::string> misplacedLabel(const std::string& expression, const std::vector<std::string>& languages,
                                          const lpe::LabelPlacement& placement) {
    const lpe::Automaton automaton = lpe::Automaton::compile({{"x", expression}});
    for (const std::string& label : automaton.labels()) {
        const auto placed = placement.find(label);
        if (placed == placement.end()) continue;
        lpe::LabelPlacement freed = placement;
        freed.erase(label);
        std::vector<std::string> all = languages;
        all.push_back(expression);
        if (!lpe::haveCommonPath(all, freed)) continue;
        const bool isLight =
            std::find(placed->second.begin(), placed->second.end(), EventType::Emitter) != placed->second.end() &&
            std::find(placed->second.begin(), placed->second.end(), EventType::Reflection) == placed->second.end();
        freed[label] = isLight ? kObjectEvents : kLightEvents;
        const std::string is = isLight ? "a light" : "an object";
        const std::string wanted = lpe::haveCommonPath(all, freed) ? (isLight ? ", not an object" : ", not a light") : "";
        return label + " is " + is + wanted + ": it labels only " + eventsOf(label, placed->second);
    }
    return std::nullopt;
}

}  // namespace

lpe::LabelPlacement labelPlacement(const Scene& scene) {
    lpe::LabelPlacement placement;
    const auto add = [&placement](const std::string& label, std::vector<EventType> types) {
        auto& events = placement[label];
        // A label shared by several things (a material's name, a light's) may be on any of their events.
        for (const EventType type : types)
            if (std::find(events.begin(), events.end(), type) == events.end()) events.push_back(type);
    };
    add(kAmbientLabel, kLightEvents);
    for (const LightSlot& light : scene.lights)
        if (!light->name.empty()) add(light->name, kLightEvents);
    for (std::uint32_t i = 0; i < scene.objects.size(); ++i) {
        std::vector<EventType> events = {EventType::Reflection, EventType::Transmission};
        if (const auto emission = emissionEventOf(scene, i)) events.push_back(*emission);
        add(scene.labelOf(i), events);
    }
    for (const MediumSlot& medium : scene.media) add(medium->name, {EventType::Volume});
    return placement;
}

std::optional<std::string> whyNeverFilled(const std::string& expression, const IntegratorInfo& integrator,
                                          const Scene* scene) {
    if (!lpe::haveCommonPath({expression, kRenderedPaths})) return whyNeverRendered(expression);

    const std::vector<std::string> languages = {kRenderedPaths, integrator.pathLanguage};
    if (!lpe::haveCommonPath({expression, kRenderedPaths, integrator.pathLanguage})) {
        const lpe::Path needed = *lpe::commonPath({expression, kRenderedPaths});
        std::string message = std::string(integrator.limitation) + " (" + integrator.name + " renders only " +
                              integrator.pathLanguage + "; the shortest path this expression needs is " +
                              lpe::toDisplayString(needed) + ")";
        const std::string others = integratorsThatCan(expression, {});
        if (!others.empty()) message += "; " + others + " can fill it";
        return message;
    }
    if (!scene) return std::nullopt;
    const lpe::LabelPlacement placement = labelPlacement(*scene);
    std::vector<std::string> all = languages;
    all.push_back(expression);
    if (lpe::haveCommonPath(all, placement)) return std::nullopt;
    if (auto message = misplacedLabel(expression, languages, placement)) return message;
    return "no path of " + std::string(integrator.name) + " in this scene carries these labels where the expression needs them";
}

}  // namespace lightpath
