#include "serve/server.h"

#include <httplib.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <stdexcept>

#include "io/image_writer.h"
#include "serve/assets.h"
#include "serve/explain_report.h"
#include "serve/graphviz.h"
#include "serve/request_error.h"
#include "serve/scene_report.h"

namespace lightpath::serve {
namespace {

using nlohmann::json;

void sendJson(httplib::Response& res, const json& body, int status = 200) {
    res.status = status;
    res.set_header("Cache-Control", "no-store");
    res.set_content(body.dump(), "application/json");
}

void sendError(httplib::Response& res, const RequestError& e) {
    json body = {{"error", e.what()}};
    if (!e.field().empty()) body["field"] = e.field();
    if (e.column) {
        body["column"] = *e.column;
        body["expression"] = e.expression;
    }
    sendJson(res, body, e.status());
}

// Every query parameter must be one of `known`: a misspelt one is an error, not silently ignored.
void allowParameters(const httplib::Request& req, std::initializer_list<std::string_view> known) {
    for (const auto& [key, value] : req.params)
        if (std::find(known.begin(), known.end(), key) == known.end())
            throw RequestError(400, key, key + ": unknown query parameter");
}

double numberParameter(const httplib::Request& req, const std::string& key, double fallback, double low, double high) {
    if (!req.has_param(key)) return fallback;
    const std::string text = req.get_param_value(key);
    std::size_t used = 0;
    double value = 0.0;
    try {
        value = std::stod(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used != text.size() || text.empty() || !std::isfinite(value) || value < low || value > high)
        throw RequestError(400, key, key + ": expected a number in " + json(low).dump() + ".." + json(high).dump() +
                                         ", got \"" + text.substr(0, 40) + "\"");
    return value;
}

int integerParameter(const httplib::Request& req, const std::string& key, long low, long high) {
    if (!req.has_param(key)) throw RequestError(400, key, key + ": required integer parameter is missing");
    const std::string text = req.get_param_value(key);
    std::size_t used = 0;
    long value = 0;
    try {
        value = std::stol(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used != text.size() || text.empty() || value < low || value > high)
        throw RequestError(400, key, key + ": expected an integer " + std::to_string(low) + ".." + std::to_string(high) +
                                         ", got \"" + text.substr(0, 40) + "\"");
    return static_cast<int>(value);
}

json progressJson(const Progress& p) {
    const Job& job = *p.job;
    return {{"generation", job.generation},
            {"settings", toJson(job.settings)},
            {"warnings", job.warnings},
            {"layers", job.aovs.layerNames()},
            {"passes", p.passes},
            {"samples", p.samples},
            {"done", p.done},
            {"seconds", p.seconds},
            {"sumError", p.sumError}};
}

// Handlers throw RequestError for the client's mistakes; this turns them into the response.
template <class Handler>
httplib::Server::Handler guarded(Handler handler) {
    return [handler](const httplib::Request& req, httplib::Response& res) {
        try {
            handler(req, res);
        } catch (const RequestError& e) {
            sendError(res, e);
        }
    };
}

}  // namespace

Server::Server(Session& session) : session_(session), http_(std::make_unique<httplib::Server>()) {
    // A client that hangs up mid-response must not kill the process (writes to its socket, or to
    // Graphviz's pipe, would raise SIGPIPE).
    std::signal(SIGPIPE, SIG_IGN);
    http_->set_payload_max_length(kMaxBodyBytes);
    http_->set_read_timeout(kIoTimeoutSeconds, 0);
    http_->set_write_timeout(kIoTimeoutSeconds, 0);
    routes();
}

Server::~Server() = default;

int Server::bind(const std::string& host, int port) {
    const int bound = port == 0 ? http_->bind_to_any_port(host) : (http_->bind_to_port(host, port) ? port : -1);
    if (bound < 0)
        throw std::runtime_error("cannot listen on " + host + ":" + std::to_string(port) +
                                 " (in use, or not an address of this machine); try another --port");
    return bound;
}

void Server::run() { http_->listen_after_bind(); }

void Server::stop() { http_->stop(); }

void Server::routes() {
    httplib::Server& http = *http_;

    http.Get("/|/app\\.js|/style\\.css", [](const httplib::Request& req, httplib::Response& res) {
        const Asset* asset = findAsset(req.path);
        res.set_content(asset->content.data(), asset->content.size(), std::string(asset->contentType).c_str());
    });

    http.Get("/api/scene", guarded([this](const httplib::Request& req, httplib::Response& res) {
        allowParameters(req, {});
        sendJson(res, describeScene(session_.scene(), session_.scenePath()));
    }));

    http.Get("/api/settings", guarded([this](const httplib::Request& req, httplib::Response& res) {
        allowParameters(req, {});
        // The settings last accepted, even before the render worker has picked them up: a client
        // reads back what its PUT was answered with.
        Progress p = session_.progress();
        if (const auto job = session_.job(); p.job != job) {
            p = Progress{};
            p.job = job;
        }
        sendJson(res, progressJson(p));
    }));

    // No query parameters are checked here: httplib files a form-encoded body under req.params.
    const auto putSettings = guarded([this](const httplib::Request& req, httplib::Response& res) {
        const auto job = session_.update(applySettings(session_.job()->settings, req.body));
        sendJson(res, {{"generation", job->generation}, {"settings", toJson(job->settings)}, {"warnings", job->warnings}});
    });
    http.Put("/api/settings", putSettings);
    http.Post("/api/settings", putSettings);

    http.Get("/api/progress", guarded([this](const httplib::Request& req, httplib::Response& res) {
        allowParameters(req, {"generation", "pass", "wait"});
        const double wait = numberParameter(req, "wait", 0.0, 0.0, kMaxWaitSeconds);
        Progress p = session_.progress();
        if (wait > 0.0) {
            const auto generation = static_cast<std::uint64_t>(numberParameter(req, "generation", 0.0, 0.0, 1e15));
            const int pass = static_cast<int>(numberParameter(req, "pass", -1.0, -1.0, 1e9));
            p = session_.waitForProgress(generation, pass, wait);
        }
        sendJson(res, progressJson(p));
    }));

    http.Get(R"(/api/image/([A-Za-z_][A-Za-z0-9_]*)\.png)", guarded([this](const httplib::Request& req, httplib::Response& res) {
        allowParameters(req, {"exposure", "generation", "pass"});
        const double exposure = numberParameter(req, "exposure", 0.0, -20.0, 20.0);
        const Progress p = req.has_param("generation")
                               ? session_.progressOf(static_cast<std::uint64_t>(numberParameter(req, "generation", 0.0, 0.0, 1e15)))
                               : session_.progress();
        const std::vector<std::string> names = p.job->aovs.layerNames();
        const auto layer = std::find(names.begin(), names.end(), req.matches[1].str());
        if (layer == names.end()) throw RequestError(404, "layer", "no layer \"" + req.matches[1].str() + "\" in this render");
        if (!p.image) throw RequestError(503, "", "no image yet: the first pass is still rendering");
        const auto png = encodePng(*p.image, static_cast<std::size_t>(layer - names.begin()),
                                   static_cast<float>(std::exp2(exposure)));
        res.set_header("Cache-Control", "no-store");
        res.set_header("X-Lightpath-Generation", std::to_string(p.job->generation));
        res.set_header("X-Lightpath-Passes", std::to_string(p.passes));
        res.set_content(reinterpret_cast<const char*>(png.data()), png.size(), "image/png");
    }));

    http.Get("/api/render.exr", guarded([this](const httplib::Request& req, httplib::Response& res) {
        allowParameters(req, {});
        const Progress p = session_.progress();
        if (!p.image) throw RequestError(503, "", "no image yet: the first pass is still rendering");
        const Settings& s = p.job->settings;
        ImageMetadata metadata{{"lightpath:scene", session_.scenePath()},
                               {"lightpath:integrator", s.integrator},
                               {"lightpath:spp", std::to_string(p.samples)},
                               {"lightpath:max_depth", std::to_string(s.maxDepth)},
                               {"lightpath:seconds", std::to_string(p.seconds)}};
        for (const auto& e : p.job->aovs.expressions()) metadata.emplace_back("lightpath:lpe:" + e.name, e.expression);
        const auto exr = encodeExr(*p.image, metadata);
        res.set_header("Content-Disposition", "attachment; filename=\"render.exr\"");
        res.set_content(reinterpret_cast<const char*>(exr.data()), exr.size(), "image/x-exr");
    }));

    http.Get("/api/explain", guarded([this](const httplib::Request& req, httplib::Response& res) {
        allowParameters(req, {"x", "y"});
        const int x = integerParameter(req, "x", -1000000, 1000000);
        const int y = integerParameter(req, "y", -1000000, 1000000);
        sendJson(res, explainPixel(*session_.job(), x, y));
    }));

    http.Get("/api/automaton.svg", guarded([this](const httplib::Request& req, httplib::Response& res) {
        allowParameters(req, {"generation"});
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
        res.set_header("X-Lightpath-Generation", std::to_string(job->generation));
        res.set_content(automatonSvg_, "image/svg+xml");
    }));

    // Unknown paths, and requests whose handler set an error status without a body.
    http.set_error_handler([](const httplib::Request& req, httplib::Response& res) {
        if (!res.body.empty()) return;
        if (res.status == 404) sendJson(res, {{"error", "no such resource: " + req.method + " " + req.path}}, 404);
        else if (res.status == 413) sendJson(res, {{"error", "request body too large: at most " + std::to_string(kMaxBodyBytes) + " bytes"}}, 413);
        else sendJson(res, {{"error", "bad request (HTTP " + std::to_string(res.status) + ")"}}, res.status);
    });
    http.set_exception_handler([](const httplib::Request&, httplib::Response& res, std::exception_ptr error) {
        std::string message = "internal error";
        try {
            std::rethrow_exception(error);
        } catch (const std::exception& e) {
            message += std::string(": ") + e.what();
        } catch (...) {
        }
        sendJson(res, {{"error", message}}, 500);
    });
}

}  // namespace lightpath::serve
