#include "serve/api.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <regex>

#include "io/image_writer.h"
#include "serve/assets.h"
#include "serve/explain_report.h"
#include "serve/graphviz.h"
#include "serve/request_error.h"
#include "serve/scene_report.h"

namespace lightpath::serve {
namespace {

using nlohmann::json;

Response jsonResponse(const json& body, int status = 200) {
    // Replaced, not thrown, where a message quotes bytes that are not UTF-8 (a header, a path).
    return {status, "application/json", body.dump(-1, ' ', false, json::error_handler_t::replace), {{"Cache-Control", "no-store"}}};
}

Response errorOf(const RequestError& e) {
    json body = {{"error", e.what()}};
    if (!e.field().empty()) body["field"] = e.field();
    if (e.column) {
        body["column"] = *e.column;
        body["expression"] = e.expression;
    }
    return jsonResponse(body, e.status());
}

// Every query parameter must be one of `known`: a misspelt one is an error, not silently ignored.
void allowParameters(const Target& target, std::initializer_list<std::string_view> known) {
    for (const auto& [key, value] : target.parameters)
        if (std::find(known.begin(), known.end(), key) == known.end())
            throw RequestError(400, key, key + ": unknown query parameter");
}

double numberParameter(const Target& target, const std::string& key, double fallback, double low, double high) {
    const std::optional<std::string> text = target.value(key);
    if (!text) return fallback;
    std::size_t used = 0;
    double value = 0.0;
    try {
        value = std::stod(*text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used != text->size() || text->empty() || !std::isfinite(value) || value < low || value > high)
        throw RequestError(400, key, key + ": expected a number in " + json(low).dump() + ".." + json(high).dump() +
                                         ", got \"" + text->substr(0, 40) + "\"");
    return value;
}

int integerParameter(const Target& target, const std::string& key, long low, long high) {
    const std::optional<std::string> text = target.value(key);
    if (!text) throw RequestError(400, key, key + ": required integer parameter is missing");
    std::size_t used = 0;
    long value = 0;
    try {
        value = std::stol(*text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used != text->size() || text->empty() || value < low || value > high)
        throw RequestError(400, key, key + ": expected an integer " + std::to_string(low) + ".." + std::to_string(high) +
                                         ", got \"" + text->substr(0, 40) + "\"");
    return static_cast<int>(value);
}

json preparationJson(const Preparation& preparation) {
    static constexpr const char* kStates[] = {"waiting", "running", "done"};
    return {{"state", kStates[static_cast<int>(preparation.state)]},
            {"seconds", preparation.seconds},
            {"steps", preparation.steps},
            {"of", preparation.totalSteps}};
}

json progressJson(const Progress& p) {
    const Job& job = *p.job;
    return {{"generation", job.generation},
            {"preparation", preparationJson(job.preparation())},
            {"settings", toJson(job.settings)},
            {"warnings", job.warnings},
            {"layers", job.aovs.layerNames()},
            {"passes", p.passes},
            {"samples", p.samples},
            {"done", p.done},
            {"seconds", p.seconds},
            {"sumError", p.sumError}};
}

Response bytesResponse(const std::vector<unsigned char>& bytes, const std::string& contentType) {
    return {200, contentType, std::string(reinterpret_cast<const char*>(bytes.data()), bytes.size()), {{"Cache-Control", "no-store"}}};
}

// The methods each path answers; a path not listed is a 404.
struct Route {
    std::regex path;
    std::vector<std::string_view> methods;
};

const std::vector<Route>& routes() {
    static const std::vector<Route> table{
        {std::regex("/|/app\\.js|/style\\.css"), {"GET", "HEAD"}},
        {std::regex("/api/(scene|progress|render\\.exr|explain|automaton\\.svg)"), {"GET", "HEAD"}},
        {std::regex("/api/settings"), {"GET", "HEAD", "PUT", "POST"}},
        {std::regex("/api/image/[A-Za-z_][A-Za-z0-9_]*\\.png"), {"GET", "HEAD"}},
    };
    return table;
}

const Route* routeOf(const std::string& path) {
    for (const Route& route : routes())
        if (std::regex_match(path, route.path)) return &route;
    return nullptr;
}

}  // namespace

Response errorResponse(int status, const std::string& message) { return jsonResponse({{"error", message}}, status); }

Api::Api(Session& session) : session_(session) {}

void Api::listenOn(const std::string& host, int port) { guard_.emplace(host, port); }

Response Api::handle(const Request& request) {
    try {
        if (!guard_) throw RequestError(503, "", "the server is not listening yet");
        guard_->check(request);
        if (request.body.size() > kMaxBodyBytes)
            throw RequestError(413, "", "request body too large: at most " + std::to_string(kMaxBodyBytes) + " bytes");
        const Target target = parseTarget(request.target);
        const Route* known = routeOf(target.path);
        if (!known) throw RequestError(404, "", "no such resource: " + request.method + " " + target.path.substr(0, 200));
        if (std::find(known->methods.begin(), known->methods.end(), request.method) == known->methods.end()) {
            std::string allowed;
            for (const std::string_view m : known->methods) allowed += (allowed.empty() ? "" : ", ") + std::string(m);
            Response refused = errorOf(RequestError(405, "", request.method + " " + target.path + ": expected " + allowed));
            refused.headers.emplace_back("Allow", allowed);
            return refused;
        }
        return route(request, target);
    } catch (const RequestError& e) {
        return errorOf(e);
    } catch (const std::exception& e) {
        return errorResponse(500, std::string("internal error: ") + e.what());
    } catch (...) {
        return errorResponse(500, "internal error");
    }
}

Response Api::route(const Request& request, const Target& target) {
    const std::string& path = target.path;
    const bool read = request.method == "GET" || request.method == "HEAD";

    if (const Asset* asset = findAsset(path)) return {200, std::string(asset->contentType), std::string(asset->content), {}};

    if (path == "/api/scene") {
        allowParameters(target, {});
        return jsonResponse(describeScene(session_.scene(), session_.scenePath()));
    }

    if (path == "/api/settings" && read) {
        allowParameters(target, {});
        // The settings last accepted, even before the render worker has picked them up: a client
        // reads back what its PUT was answered with.
        Progress p = session_.progress();
        if (const auto job = session_.job(); p.job != job) {
            p = Progress{};
            p.job = job;
        }
        return jsonResponse(progressJson(p));
    }

    if (path == "/api/settings") {  // PUT or POST
        allowParameters(target, {});
        std::vector<std::string> notices;
        const auto job = session_.update(applySettings(session_.job()->settings, request.body, &notices, &session_.scene()));
        return jsonResponse({{"generation", job->generation},
                             {"settings", toJson(job->settings)},
                             {"warnings", job->warnings},
                             {"notices", notices}});
    }

    if (path == "/api/progress") {
        allowParameters(target, {"generation", "pass", "wait"});
        const double wait = numberParameter(target, "wait", 0.0, 0.0, kMaxWaitSeconds);
        Progress p = session_.progress();
        if (wait > 0.0) {
            const auto generation = static_cast<std::uint64_t>(numberParameter(target, "generation", 0.0, 0.0, 1e15));
            const int pass = static_cast<int>(numberParameter(target, "pass", -1.0, -1.0, 1e9));
            p = session_.waitForProgress(generation, pass, wait);
        }
        return jsonResponse(progressJson(p));
    }

    if (path.starts_with("/api/image/")) {
        allowParameters(target, {"exposure", "generation", "pass"});
        const std::string layerName = path.substr(11, path.size() - 11 - 4);
        const double exposure = numberParameter(target, "exposure", 0.0, -20.0, 20.0);
        const Progress p = target.has("generation")
                               ? session_.progressOf(static_cast<std::uint64_t>(numberParameter(target, "generation", 0.0, 0.0, 1e15)))
                               : session_.progress();
        const std::vector<std::string> names = p.job->aovs.layerNames();
        const auto layer = std::find(names.begin(), names.end(), layerName);
        if (layer == names.end()) throw RequestError(404, "layer", "no layer \"" + layerName + "\" in this render");
        if (!p.image) throw RequestError(503, "", "no image yet: the first pass is still rendering");
        Response response = bytesResponse(encodePng(*p.image, static_cast<std::size_t>(layer - names.begin()),
                                                    static_cast<float>(std::exp2(exposure))),
                                          "image/png");
        response.headers.emplace_back("X-Lightpath-Generation", std::to_string(p.job->generation));
        response.headers.emplace_back("X-Lightpath-Passes", std::to_string(p.passes));
        return response;
    }

    if (path == "/api/render.exr") {
        allowParameters(target, {});
        const Progress p = session_.progress();
        if (!p.image) throw RequestError(503, "", "no image yet: the first pass is still rendering");
        const Settings& s = p.job->settings;
        ImageMetadata metadata{{"lightpath:scene", session_.scenePath()},
                               {"lightpath:integrator", s.integrator},
                               {"lightpath:spp", std::to_string(p.samples)},
                               {"lightpath:max_depth", std::to_string(s.maxDepth)},
                               {"lightpath:seconds", std::to_string(p.seconds)}};
        for (const auto& e : p.job->aovs.expressions()) metadata.emplace_back("lightpath:lpe:" + e.name, e.expression);
        Response response = bytesResponse(encodeExr(*p.image, metadata), "image/x-exr");
        response.headers.emplace_back("Content-Disposition", "attachment; filename=\"render.exr\"");
        return response;
    }

    if (path == "/api/explain") {
        allowParameters(target, {"x", "y"});
        const int x = integerParameter(target, "x", -1000000, 1000000);
        const int y = integerParameter(target, "y", -1000000, 1000000);
        const std::shared_ptr<std::atomic<bool>> cancel = session_.startExplaining();
        try {
            return jsonResponse(explainPixel(*session_.job(), x, y, cancel.get()));
        } catch (const ExplainCancelled&) {
            if (session_.stopping()) throw RequestError(503, "", "the server is stopping");
            throw RequestError(409, "", "the explanation of pixel " + std::to_string(x) + "," + std::to_string(y) +
                                            " was cancelled: a newer explanation or a change of settings replaced it");
        }
    }

    allowParameters(target, {"generation"});  // /api/automaton.svg, the last route
    return automatonSvg();
}

Response Api::automatonSvg() {
    const auto job = session_.job();
    std::lock_guard lock(automatonMutex_);
    if (automatonGeneration_ != job->generation) {
        try {
            automatonSvg_ = dotToSvg(job->aovs.automaton().toDot());
        } catch (const GraphvizError& e) {
            throw RequestError(503, "", e.what());
        }
        automatonGeneration_ = job->generation;
    }
    return {200, "image/svg+xml", automatonSvg_, {{"X-Lightpath-Generation", std::to_string(job->generation)}}};
}

}  // namespace lightpath::serve
