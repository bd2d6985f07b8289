#include "serve/explain_report.h"

#include <optional>

#include "integrators/event_symbols.h"
#include "lpe/path_string.h"
#include "scene/camera.h"
#include "serve/json_point.h"
#include "serve/request_error.h"

namespace lightpath::serve {
namespace {

using nlohmann::json;

// World position of a path vertex (PathEvent::position). The ambient term comes from nowhere.
std::optional<Vec3> positionOf(const PathEvent& event) {
    if (event.subject == Subject::Ambient) return std::nullopt;
    return event.position;
}


// The part of segment a-b in front of the eye, projected: [x0, y0, x1, y1] in pixels, or null
// when all of it is behind.
json projectedSegment(const Camera& camera, Vec3 a, Vec3 b) {
    const auto ends = camera.filmSegment(a, b);
    if (!ends) return nullptr;
    return json::array({(*ends)[0].x, (*ends)[0].y, (*ends)[1].x, (*ends)[1].y});
}

}  // namespace

json explainPixel(const Job& job, int x, int y, const std::atomic<bool>* cancel) {
    const int width = job.settings.width, height = job.settings.height;
    if (x < 0 || y < 0 || x >= width || y >= height)
        throw RequestError(400, "x,y", "pixel " + std::to_string(x) + "," + std::to_string(y) + " is outside the " +
                                           std::to_string(width) + "x" + std::to_string(height) + " image");
    std::vector<Rejection> rejections;
    const std::vector<LoggedContribution> log =
        job.renderer().explainPixel(x, y, &rejections, {.samplesPerPixel = 1, .cancel = cancel});
    const lpe::Automaton& automaton = job.aovs.automaton();
    const Camera camera(job.scene.camera);
    const std::vector<std::string> layers = job.aovs.layerNames();
    std::vector<Rgb> sums(layers.size(), Rgb{0.0f});

    json contributions = json::array();
    for (const LoggedContribution& c : log) {
        lpe::Path path;
        json vertices = json::array(), segments = json::array(), states = json::array();
        lpe::Automaton::State state = automaton.start();
        states.push_back(state);
        std::optional<Vec3> previous;
        for (std::size_t i = 0; i < c.path.size(); ++i) {
            const PathEvent& e = c.path[i];
            path.push_back(lpeEventOf(job.scene, e));
            state = automaton.step(state, automaton.symbol(path.back()));
            states.push_back(state);
            const std::optional<Vec3> position = positionOf(e);
            json vertex = {{"event", std::string(1, lpe::letter(e.type)) + (e.type == lpe::EventType::Reflection ||
                                                                                     e.type == lpe::EventType::Transmission
                                                                                 ? std::string(1, lpe::letter(e.scatter))
                                                                                 : std::string())},
                           {"label", path.back().label},
                           {"touched", subjectName(job.scene, e)},
                           {"position", position ? point(*position) : json(nullptr)}};
            if (position) {
                if (const auto p = camera.filmPosition(*position)) vertex["pixel"] = json::array({p->x, p->y});
            }
            vertices.push_back(std::move(vertex));
            segments.push_back(position && previous ? projectedSegment(camera, *previous, *position) : json(nullptr));
            previous = position;
        }
        segments.erase(segments.begin());  // segment i joins vertex i and i + 1

        json aovs = json::array();
        sums[0] += c.value;
        if (c.accepted == 0) {
            aovs.push_back("rest");
            sums.back() += c.value;
        }
        for (std::size_t o = 0; o < job.aovs.expressions().size(); ++o) {
            if (((c.accepted >> o) & 1u) == 0) continue;
            aovs.push_back(job.aovs.expressions()[o].name);
            sums[1 + o] += c.value;
        }
        json factors = json::array();
        for (std::size_t f = 0; f < c.factorCount; ++f)
            factors.push_back({{"name", c.factors[f].name},
                               {"rgb", json::array({c.factors[f].value.r, c.factors[f].value.g, c.factors[f].value.b})},
                               {"inProduct", c.factors[f].inProduct}});
        contributions.push_back({{"compact", lpe::toCompactString(path)},
                                 {"tuple", lpe::toTupleString(path)},
                                 {"lpe", lpe::toExpressionString(path)},
                                 {"rgb", json::array({c.value.r, c.value.g, c.value.b})},
                                 {"aovs", aovs},
                                 {"factors", factors},
                                 {"states", states},
                                 {"vertices", vertices},
                                 {"segments", segments},
                                 // bdpt: the strategy (s light vertices, t eye vertices) that made it
                                 {"strategy", c.lightVertices < 0 ? json(nullptr)
                                                                  : json{{"s", int{c.lightVertices}},
                                                                         {"t", int{c.eyeVertices}},
                                                                         {"splatted", c.splatted}}}});
    }
    json layerSums = json::array();
    for (std::size_t l = 0; l < layers.size(); ++l) {
        const bool aov = l > 0 && l + 1 < layers.size();
        layerSums.push_back({{"layer", layers[l]},
                             {"rgb", json::array({sums[l].r, sums[l].g, sums[l].b})},
                             {"expression", aov ? job.aovs.expressions()[l - 1].expression : ""}});
    }
    json rejected = json::array();
    for (const Rejection& r : rejections) {
        lpe::Path path;
        for (std::size_t i = 0; i < r.path.size(); ++i) path.push_back(lpeEventOf(job.scene, r.path[i]));
        rejected.push_back({{"compact", lpe::toCompactString(path)}, {"lpe", lpe::toExpressionString(path)}, {"reason", r.reason}});
    }
    return {{"pixel", json::array({x, y})},
            {"generation", job.generation},
            {"integrator", job.settings.integrator},
            {"samples", 1},
            {"contributions", contributions},
            {"sums", layerSums},
            {"rejected", rejected}};
}

}  // namespace lightpath::serve
