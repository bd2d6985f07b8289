// libFuzzer target for `lightpath serve`'s request handling (serve/api.h): one HTTP request per
// input, handed to Api::handle, the function the server answers every request with. The input is
// the request as on the wire, without the version:
//     METHOD TARGET
//     Name: value          (headers, up to an empty line)
//
//     BODY                 (the rest)
// Invariants: handle never throws or crashes; every status is in 200..599; every error (4xx, 5xx)
// is a JSON object with an "error" string, and every JSON answer parses; the settings change only
// for a PUT or POST answered 200 that carried Content-Type application/json, no Host but the
// server's and no Origin but its own (docs/serve.md, "Safety"; the lists below are written out
// here, not taken from the guard).
//
// Hermetic: the scene is the text below, "living" in a directory that does not exist. Every input
// starts from the same settings (a 6x4 image), so one input cannot leave a large render running
// for the next.
// Reproducible: libFuzzer's coverage feedback must see the same code run for the same input on any
// machine, so the session renders on one thread, every render an input starts is waited for to its
// end (a cancelled one would stop wherever the scheduler left it), and settings that would make
// that wait long (more than kMaxSamples camera samples) are refused as inputs (return -1) before
// they are handled.
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdint>
#include <string>
#include <string_view>

#include "fuzz_support.h"
#include "scene/scene_loader.h"
#include "serve/api.h"
#include "serve/session.h"
#include "serve/settings.h"

namespace {

using namespace lightpath;
using namespace lightpath::serve;
using fuzz::broken;
using nlohmann::json;

constexpr std::size_t kMaxInput = 16 * 1024;
constexpr std::int64_t kMaxSamples = 16 * 16 * 16;  // width x height x spp of a render waited for
constexpr int kPort = 8080;

constexpr std::string_view kScene = R"(
[camera]
eye = [0, 1.8, 7.5]
look_at = [0, 1, 0]
fov = 40
resolution = [6, 4]

[world]
background = [0.5, 0.68, 0.95]
ambient = 0.1

[materials.floor]
kd = 0.55

[materials.mirror]
kd = 0.05
ks = 0.6
n = 400
kr = 0.8

[[lights]]
name = "lamp"
position = [-3, 6, 5]
intensity = 0.95

[[spheres]]
name = "ball"
center = [0, 1.1, 0]
radius = 1.1
material = "mirror"

[[planes]]
name = "floor"
point = [0, 0, 0]
normal = [0, 1, 0]
material = "floor"
)";

struct Server {
    Session session{loadSceneFromText(kScene, "/nonexistent-fuzz/serve.toml"), "/nonexistent-fuzz/serve.toml", 1};
    Api api{session};
    const Settings start = session.job()->settings;
    Server() { api.listenOn("127.0.0.1", kPort); }
};

Server& server() {
    static Server instance;
    return instance;
}

std::string lower(std::string_view text) {
    std::string result(text);
    std::transform(result.begin(), result.end(), result.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return result;
}

Request parse(std::string_view text) {
    Request request;
    const auto [head, body] = fuzz::splitAtLine(text, "");
    request.body = body;
    const std::vector<std::string_view> lines = fuzz::lines(head);
    if (lines.empty()) return request;
    const std::string_view first = lines[0];
    const std::size_t space = first.find(' ');
    request.method = std::string(first.substr(0, space));
    request.target = space == std::string_view::npos ? std::string() : std::string(first.substr(space + 1));
    for (std::size_t i = 1; i < lines.size(); ++i) {
        const std::size_t colon = lines[i].find(':');
        std::string_view value = colon == std::string_view::npos ? std::string_view() : lines[i].substr(colon + 1);
        while (!value.empty() && value.front() == ' ') value.remove_prefix(1);
        request.headers.emplace_back(std::string(lines[i].substr(0, colon)), std::string(value));
    }
    return request;
}

// The conditions under which a request may change the settings, written out independently.
bool mayChangeSettings(const Request& request, int status) {
    if (status != 200 || (request.method != "PUT" && request.method != "POST")) return false;
    std::string port(1, ':');  // appended, not ":" + ...: GCC 12 warns falsely about that (its bug 105329)
    port += std::to_string(kPort);
    const std::vector<std::string> hosts{"127.0.0.1" + port, "localhost" + port, "[::1]" + port};
    int types = 0, hostCount = 0, originCount = 0;
    for (const auto& [name, value] : request.headers) {
        const std::string key = lower(name);
        if (key == "content-type") {
            ++types;
            std::string type = lower(value.substr(0, value.find(';')));
            std::erase_if(type, [](char c) { return c == ' ' || c == '\t'; });
            if (type != "application/json") return false;
        } else if (key == "host") {
            ++hostCount;
            if (std::find(hosts.begin(), hosts.end(), lower(value)) == hosts.end()) return false;
        } else if (key == "origin") {
            ++originCount;
            const std::string origin = lower(value);  // a structured binding: clang 14 cannot capture it
            if (std::none_of(hosts.begin(), hosts.end(), [&](const std::string& h) { return origin == "http://" + h; })) return false;
        }
    }
    return types == 1 && hostCount <= 1 && originCount <= 1;
}

// Settings the request would start a render with that takes longer than the fuzzer should wait.
bool startsLongRender(const Request& request, const Settings& current) {
    if ((request.method != "PUT" && request.method != "POST") || request.target.find("settings") == std::string::npos)
        return false;
    try {
        const Settings next = applySettings(current, request.body);
        return std::int64_t{next.width} * next.height * next.samplesPerPixel > kMaxSamples;
    } catch (const std::exception&) {
        return false;  // refused: starts nothing
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size > kMaxInput) return 0;
    Server& s = server();
    const auto before = s.session.update(s.start);
    s.session.waitUntilIdle();
    const Request request = parse(fuzz::asText(data, size));
    if (startsLongRender(request, s.start)) return -1;

    Response response;
    try {
        response = s.api.handle(request);
    } catch (...) {
        broken("Api::handle threw for " + request.method + " " + request.target.substr(0, 80));
    }
    const std::string what = request.method + " " + request.target.substr(0, 80) + " answered " + std::to_string(response.status);
    if (response.status < 200 || response.status > 599) broken(what + ": status outside 200..599");
    if (response.status >= 400 || response.contentType == "application/json") {
        if (response.contentType != "application/json") broken(what + " as " + response.contentType + ", not JSON");
        json body;
        try {
            body = json::parse(response.body);
        } catch (const json::exception& e) {
            broken(what + ": the JSON does not parse: " + e.what());
        }
        if (response.status >= 400 && !(body.is_object() && body.contains("error") && body["error"].is_string()))
            broken(what + ": an error without an \"error\" string: " + response.body.substr(0, 200));
    }
    if (s.session.job() != before && !mayChangeSettings(request, response.status))
        broken(what + ": the settings changed, but the request may not change them");
    s.session.waitUntilIdle();
    return 0;
}
