#include "config/scene_events.h"

#include <algorithm>
#include <functional>
#include <map>

#include "lpe/analysis.h"
#include "lpe/automaton.h"
#include "materials/material_type.h"
#include "materials/scatter_events.h"
#include "scene/ambient_label.h"
#include "scene/emission.h"

namespace lightpath {
namespace {

// Every scattering event of the alphabet: what a scene may lack, or a label's object.
constexpr ScatterEvent kScatterEvents[] = {
    {lpe::EventType::Reflection, lpe::Scatter::Diffuse},    {lpe::EventType::Reflection, lpe::Scatter::Glossy},
    {lpe::EventType::Reflection, lpe::Scatter::Specular},   {lpe::EventType::Reflection, lpe::Scatter::Straight},
    {lpe::EventType::Transmission, lpe::Scatter::Diffuse},  {lpe::EventType::Transmission, lpe::Scatter::Glossy},
    {lpe::EventType::Transmission, lpe::Scatter::Specular}, {lpe::EventType::Transmission, lpe::Scatter::Straight},
};

bool contains(const std::vector<ScatterEvent>& events, const ScatterEvent& event) {
    return std::find(events.begin(), events.end(), event) != events.end();
}

bool hasEvent(const SceneEvents& events, const ScatterEvent& event) { return contains(events.scatter, event); }

void addEvent(SceneEvents& events, const ScatterEvent& event) {
    if (!hasEvent(events, event)) events.scatter.push_back(event);
}

std::string letters(const ScatterEvent& e) { return {lpe::letter(e.type), lpe::letter(e.scatter)}; }
std::string tuple(const ScatterEvent& e) { return "<" + letters(e) + ">"; }

bool smooth(const ScatterEvent& e) { return e.scatter == lpe::Scatter::Diffuse || e.scatter == lpe::Scatter::Glossy; }

std::string alternation(const std::vector<std::string>& parts) {
    std::string text;
    for (const std::string& p : parts) text += (text.empty() ? "(" : "|") + p;
    return text.empty() ? text : text + ")";
}

// A light that is not the ambient term (every light but 'ambient' is one a scene declares).
const std::string kDeclaredLight = std::string("<L.[^'") + kAmbientLabel + "']>";

// The parts of a scene's paths, each an LPE tuple (labelled or not).
struct PathParts {
    std::vector<std::string> scatter;       // every scattering event
    std::vector<std::string> smooth;        // those of them a light sample can leave from (D, G)
    std::vector<std::string> hit;           // emitters a ray can hit: area lights, emitting surfaces, B
    std::vector<std::string> shapeless;     // point lights
    std::vector<std::string> ambientAfter;  // the <RD> events the ambient term follows
};

// The one statement of which paths a scene's parts make; none when nothing can end a path.
std::optional<std::string> pathsOf(const PathParts& parts) {
    const std::string any = parts.scatter.empty() ? "" : alternation(parts.scatter) + "*";
    std::vector<std::string> paths;
    // A ray hits an area light, an emitting surface or the sky after any events, or none.
    if (!parts.hit.empty()) paths.push_back("E" + any + alternation(parts.hit));
    // A point light is never hit: only a light sample from a diffuse or glossy event reaches it,
    // from the eye's side or (bdpt) the light's, so some such event is on the path.
    if (!parts.shapeless.empty() && !parts.smooth.empty())
        paths.push_back("E" + any + alternation(parts.smooth) + any + alternation(parts.shapeless));
    // The ambient term ka Ia, recorded after the diffuse event (integrators/direct_light.cpp).
    if (!parts.ambientAfter.empty())
        paths.push_back("E" + any + alternation(parts.ambientAfter) + "<L.'" + kAmbientLabel + "'>");
    if (paths.empty()) return std::nullopt;
    std::string language;
    for (const std::string& p : paths) language += (language.empty() ? "" : "|") + ("(" + p + ")");
    return language;
}

// What the scene lacks for a path, as one change to SceneEvents, with its cause and fix.
struct Lack {
    // What to say, asked only of the lack that is reported (a missing lobe's message asks every
    // material type's events, an automaton search each).
    std::function<std::string()> cause;
    std::function<void(SceneEvents&)> add;
};

// The phong keys (the default material, docs/design.md's units) that give a lobe its event.
std::string phongKeys(const ScatterEvent& e) {
    using lpe::EventType, lpe::Scatter;
    if (e.type == EventType::Reflection && e.scatter == Scatter::Diffuse) return " (kd and ka are 0 in every material): give one kd";
    if (e.type == EventType::Reflection && e.scatter == Scatter::Glossy) return " (ks is 0 in every material): give one ks";
    if (e.type == EventType::Reflection && e.scatter == Scatter::Specular) return " (kr and kt are 0 in every material): give one kr";
    if (e.type == EventType::Transmission && e.scatter == Scatter::Specular) return " (kt is 0 in every material): give one kt";
    return "";
}

std::string lobeName(const ScatterEvent& e) {
    using lpe::EventType, lpe::Scatter;
    const bool reflection = e.type == EventType::Reflection;
    switch (e.scatter) {
        case Scatter::Diffuse: return reflection ? "diffuse" : "diffuse transmission";
        case Scatter::Glossy: return reflection ? "glossy" : "glossy transmission";
        case Scatter::Specular: return reflection ? "mirror" : "refraction";
        default: return "straight " + std::string(reflection ? "reflection" : "transmission");
    }
}

// No material in the scene scatters by `e`: what to say, from the material types' schemas (the
// events each declares, `lightpath types material`).
std::string missingLobe(const ScatterEvent& e) {
    std::string types;
    for (const MaterialType* type : MaterialRegistry::instance().entries())
        if (!std::string_view(type->schema.events).empty() && lpe::commonPath({"E" + tuple(e) + "L", "E(" + std::string(type->schema.events) + ")L"}))
            types += (types.empty() ? "" : " or ") + std::string(type->schema.name);
    const std::string cause = "no material has a " + lobeName(e) + " lobe " + tuple(e);
    if (types.empty()) return cause + ", and no material type has one (lightpath types material lists their events)";
    const std::string keys = phongKeys(e);
    return cause + (keys.empty() ? ": a material of type " + types + " can have one" : keys);
}

// Every single addition that could make a path possible, in the order their causes are named.
std::vector<Lack> lacksOf(const SceneEvents& events) {
    const auto said = [](std::string text) { return [text] { return text; }; };
    std::vector<Lack> lacks;
    for (const ScatterEvent& e : kScatterEvents)
        if (!hasEvent(events, e)) lacks.push_back({[e] { return missingLobe(e); }, [e](SceneEvents& s) { addEvent(s, e); }});
    const bool anyLight = events.hittableLight || events.shapelessLight;
    const std::string unlit = "this scene has no light ([[lights]]): add one";
    if (!events.hittableLight)
        lacks.push_back({said(anyLight ? "no light a ray can hit: a point light is reached only by a light sample from "
                                         "a diffuse or glossy surface; add a [[lights]] quad or sphere"
                                       : unlit),
                         [](SceneEvents& s) { s.hittableLight = true; }});
    if (!events.shapelessLight && !anyLight) lacks.push_back({said(unlit), [](SceneEvents& s) { s.shapelessLight = true; }});
    if (!events.objectEmission)
        lacks.push_back({said("no surface emits (O): no material has an emission (a [[lights]] quad or sphere ends "
                              "its paths with L); give a material emission, or write L"),
                         [](SceneEvents& s) { s.objectEmission = true; }});
    if (!events.background)
        lacks.push_back({said("the background is black (B): set [world] background"), [](SceneEvents& s) { s.background = true; }});
    if (!events.ambientLight || !events.ambientReflectance)
        lacks.push_back({said(!events.ambientLight ? "no ambient light (L'ambient'): set [world] ambient"
                                                   : "no material reflects the ambient light (ka is 0 in every material): "
                                                     "give one ka"),
                         [](SceneEvents& s) {
                             s.ambientLight = s.ambientReflectance = true;
                             addEvent(s, lobes::kDiffuse.event);
                         }});
    return lacks;
}

bool possibleIn(const std::vector<std::string>& languages, const std::string& expression, const SceneEvents& events) {
    const std::optional<std::string> scene = sceneLanguage(events);
    if (!scene) return false;
    std::vector<std::string> all = languages;
    all.push_back(expression);
    all.push_back(*scene);
    return lpe::haveCommonPath(all);
}

// The events each label is on: an object's (its name, else its material's) scatter events, and
// the ends of paths, each already written as a tuple with its label.
struct LabelledEvents {
    std::map<std::string, std::vector<ScatterEvent>> scatter;
    std::vector<std::string> hit;        // <L.'panel'>, <O.'lamp'>, B
    std::vector<std::string> shapeless;  // <L.'key'>: after a diffuse or glossy event only
    std::vector<std::string> ambientAfter;  // <RD'wall'> of each object with ka, when the scene has ambient light
};

// `<RD'floor'>`; an empty label is any label.
std::string labelled(const std::string& head, const std::string& label) {
    return "<" + head + (label.empty() ? "" : "'" + label + "'") + ">";
}

std::optional<LabelledEvents> labelledEventsOf(const Scene& scene) {
    LabelledEvents events;
    bool quotable = true;
    const auto quoted = [&quotable](const std::string& label) {
        quotable = quotable && label.find('\'') == std::string::npos;
        return label;
    };
    for (std::uint32_t i = 0; i < scene.objects.size(); ++i) {
        const std::string label = quoted(scene.labelOf(i));
        const Material& material = *scene.materials[scene.objects[i].material];
        auto& own = events.scatter[label];
        for (const ScatterEvent& e : scatterEventsOf(material))
            if (!contains(own, e)) own.push_back(e);
        if (const auto emission = emissionEventOf(scene, i))
            events.hit.push_back(labelled(std::string(1, lpe::letter(*emission)) + ".", label));
        if (!isBlack(scene.ambient) && !isBlack(material.ambientReflectance()))
            events.ambientAfter.push_back(labelled(letters(lobes::kDiffuse.event), label));
    }
    for (const LightSlot& light : scene.lights)
        events.shapeless.push_back(light->name.empty() ? kDeclaredLight : labelled("L.", quoted(light->name)));
    if (!isBlack(scene.background)) events.hit.emplace_back("B");
    if (!quotable) return std::nullopt;
    return events;
}

std::optional<std::string> labelledLanguage(const LabelledEvents& events) {
    PathParts parts{{}, {}, events.hit, events.shapeless, events.ambientAfter};
    for (const auto& [label, own] : events.scatter)
        for (const ScatterEvent& e : own) {
            const std::string t = labelled(letters(e), label);
            parts.scatter.push_back(t);
            if (smooth(e)) parts.smooth.push_back(t);
        }
    return pathsOf(parts);
}

bool possibleOnLabels(const std::vector<std::string>& languages, const std::string& expression,
                      const LabelledEvents& events) {
    const std::optional<std::string> scene = labelledLanguage(events);
    if (!scene) return false;
    std::vector<std::string> all = languages;
    all.push_back(expression);
    all.push_back(*scene);
    return lpe::haveCommonPath(all);
}

std::string eventList(const std::vector<ScatterEvent>& events) {
    std::string list;
    for (std::size_t i = 0; i < events.size(); ++i)
        list += (i == 0 ? "" : i + 1 == events.size() ? " and " : ", ") + tuple(events[i]);
    return list.empty() ? "nothing" : list;
}

}  // namespace

std::optional<std::string> whyNotOnItsLabels(const std::string& expression, const std::vector<std::string>& languages,
                                             const Scene& scene) {
    const std::optional<LabelledEvents> events = labelledEventsOf(scene);
    if (!events || possibleOnLabels(languages, expression, *events)) return std::nullopt;
    const lpe::Automaton automaton = lpe::Automaton::compile({{"x", expression}});
    for (const std::string& label : automaton.labels()) {
        const auto own = events->scatter.find(label);
        if (own == events->scatter.end()) continue;
        for (const ScatterEvent& e : kScatterEvents) {
            if (contains(own->second, e)) continue;
            LabelledEvents more = *events;
            more.scatter[label].push_back(e);
            if (possibleOnLabels(languages, expression, more))
                return label + " has no " + lobeName(e) + " lobe " + tuple(e) +
                       ": its material scatters only by " + eventList(own->second);
        }
    }
    return std::string("no path has its labels on events their objects and lights produce");
}

SceneEvents sceneEventsOf(const Scene& scene) {
    SceneEvents events;
    for (std::uint32_t i = 0; i < scene.objects.size(); ++i) {
        const Material& material = *scene.materials[scene.objects[i].material];
        for (const ScatterEvent& e : scatterEventsOf(material)) addEvent(events, e);
        events.ambientReflectance |= !isBlack(material.ambientReflectance());
        if (const auto emission = emissionEventOf(scene, i)) {
            if (*emission == lpe::EventType::Emitter) events.hittableLight = true;
            else events.objectEmission = true;
        }
    }
    events.shapelessLight = !scene.lights.empty();
    events.ambientLight = !isBlack(scene.ambient);
    events.background = !isBlack(scene.background);
    return events;
}

std::optional<std::string> sceneLanguage(const SceneEvents& events) {
    PathParts parts;
    for (const ScatterEvent& e : events.scatter) {
        parts.scatter.push_back(tuple(e));
        if (smooth(e)) parts.smooth.push_back(tuple(e));
    }
    if (events.hittableLight) parts.hit.push_back(kDeclaredLight);
    if (events.objectEmission) parts.hit.emplace_back("O");
    if (events.background) parts.hit.emplace_back("B");
    if (events.shapelessLight) parts.shapeless.push_back(kDeclaredLight);
    if (events.ambientLight && events.ambientReflectance) parts.ambientAfter.push_back(tuple(lobes::kDiffuse.event));
    return pathsOf(parts);
}

std::optional<std::string> whyNotInScene(const std::string& expression, const std::vector<std::string>& languages,
                                         const Scene& scene) {
    const SceneEvents events = sceneEventsOf(scene);
    if (possibleIn(languages, expression, events)) return std::nullopt;
    const auto noPath = [&] {
        const std::optional<std::string> language = sceneLanguage(events);
        return "no path has it: every path here is one of " + language.value_or("none (nothing emits)");
    };
    const std::vector<Lack> lacks = lacksOf(events);
    for (const Lack& lack : lacks) {
        SceneEvents more = events;
        lack.add(more);
        if (possibleIn(languages, expression, more)) return lack.cause();
    }
    for (std::size_t i = 0; i < lacks.size(); ++i)
        for (std::size_t j = i + 1; j < lacks.size(); ++j) {
            SceneEvents more = events;
            lacks[i].add(more);
            lacks[j].add(more);
            if (possibleIn(languages, expression, more))
                return lacks[i].cause() + "; and " + lacks[j].cause();
        }
    return noPath();
}

}  // namespace lightpath
