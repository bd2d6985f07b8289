// Only the server's own page can drive `lightpath serve` (docs/serve.md, "Safety"): requests for
// another Host (DNS rebinding), from another Origin, and state changes that are not JSON (a
// cross-site "simple" request) are refused with a JSON error, and change nothing. The matrix runs
// through Api::handle, the function the server answers with; the socket tests show the server
// uses it.
#include <regex>

#include "serve/api.h"
#include "serve_fixture.h"

using namespace lightpath;
using namespace lightpath::serve;
using namespace lightpath::serve::test;

namespace {

constexpr int kPort = 8123;  // the Api is not on a socket here: any port names "this server"
const std::string kOwnHost = "127.0.0.1:" + std::to_string(kPort);
const std::string kOwnOrigin = "http://" + kOwnHost;

Request get(const std::string& target, HeaderList headers = {{"Host", kOwnHost}}) { return {"GET", target, std::move(headers), ""}; }

Request putJson(const std::string& body, HeaderList extra = {}, const std::string& contentType = "application/json") {
    HeaderList headers{{"Host", kOwnHost}, {"Content-Type", contentType}};
    headers.insert(headers.end(), extra.begin(), extra.end());
    return {"PUT", "/api/settings", std::move(headers), body};
}

// A refusal: the status, JSON with an error naming the header.
void checkRefused(const Response& r, int status, const std::string& field, const std::string& message) {
    CHECK(r.status == status);
    CHECK(r.contentType == "application/json");
    const json body = json::parse(r.body);
    CHECK(body.value("field", std::string()) == field);
    CHECK(std::regex_search(body["error"].get<std::string>(), std::regex(message)));
}

int sppOf(Api& api) { return json::parse(api.handle(get("/api/settings")).body)["settings"]["spp"]; }

}  // namespace

TEST_CASE("serve safety: a request for another Host is refused before anything is read (DNS rebinding)") {
    ServerFixture fixture("mirror-sphere.toml");
    Api api(fixture.session);
    api.listenOn("127.0.0.1", kPort);
    for (const std::string& host : std::vector<std::string>{"evil.example:" + std::to_string(kPort), "evil.example", "127.0.0.1",
                                   "127.0.0.1:" + std::to_string(kPort + 1), "localhost.evil.example:" + std::to_string(kPort),
                                   "127.0.0.1:" + std::to_string(kPort) + ".evil.example", "[::1]", "0.0.0.0:" + std::to_string(kPort), ""}) {
        CAPTURE(host);
        for (const char* target : {"/", "/api/scene", "/api/settings", "/api/explain?x=1&y=1", "/no/such"}) {
            CAPTURE(target);
            const Response r = api.handle(get(target, {{"Host", host}}));
            checkRefused(r, 421, "Host", "is not this server: expected 127\\.0\\.0\\.1:8123, localhost:8123 or \\[::1\\]:8123");
            CHECK(r.body.find("mirror-ball") == std::string::npos);
        }
        HeaderList headers{{"Host", host}, {"Content-Type", "application/json"}};
        checkRefused(api.handle({"PUT", "/api/settings", headers, "{\"spp\": 4096}"}), 421, "Host", "DNS rebinding");
    }
    CHECK(sppOf(api) != 4096);
    checkRefused(api.handle(get("/api/scene", {{"Host", kOwnHost}, {"host", kOwnHost}})), 400, "Host", "more than one Host");

    // Through the socket: what the issue measured answered 200 with the scene's contents.
    auto c = fixture.client();
    const auto r = c->Get("/api/scene", {{"Host", "evil.example:" + std::to_string(fixture.port)}});
    REQUIRE(r);
    CHECK(r->status == 421);
    CHECK(json::parse(r->body)["field"] == "Host");
    CHECK(r->body.find("mirror-ball") == std::string::npos);
}

TEST_CASE("serve safety: every Host the server answers to is answered") {
    ServerFixture fixture("mirror-sphere.toml");
    Api api(fixture.session);
    api.listenOn("127.0.0.1", kPort);
    const std::string port = std::to_string(kPort);
    for (const std::string& host : std::vector<std::string>{"127.0.0.1:" + port, "localhost:" + port, "[::1]:" + port, "LocalHost:" + port}) {
        CAPTURE(host);
        const Response r = api.handle(get("/api/scene", {{"Host", host}}));
        CHECK(r.status == 200);
        CHECK(r.body.find("mirror-ball") != std::string::npos);
    }
    // HTTP/1.0 without Host: only a client that reaches the socket anyway can omit it.
    CHECK(api.handle(get("/api/scene", {})).status == 200);

    // The --host given, with its port; on port 80 a Host may leave the port out (RFC 9110 4.2.1).
    Api named(fixture.session);
    named.listenOn("lecture.example", kPort);
    CHECK(named.handle(get("/", {{"Host", "lecture.example:" + port}})).status == 200);
    CHECK(named.handle(get("/", {{"Host", "localhost:" + port}})).status == 200);
    CHECK(named.handle(get("/", {{"Host", "lecture.example"}})).status == 421);
    Api ipv6(fixture.session);
    ipv6.listenOn("fd00::7", kPort);
    CHECK(ipv6.handle(get("/", {{"Host", "[fd00::7]:" + port}})).status == 200);
    Api onDefaultPort(fixture.session);
    onDefaultPort.listenOn("127.0.0.1", 80);
    CHECK(onDefaultPort.handle(get("/", {{"Host", "localhost"}})).status == 200);
    CHECK(onDefaultPort.handle(get("/", {{"Host", "localhost:80"}})).status == 200);

    // Through the socket, the Host httplib's client writes (127.0.0.1:PORT) and localhost's.
    auto c = fixture.client();
    for (const std::string& host : std::vector<std::string>{"127.0.0.1:" + std::to_string(fixture.port), "localhost:" + std::to_string(fixture.port)}) {
        const auto r = c->Get("/api/scene", {{"Host", host}});
        REQUIRE(r);
        CHECK(r->status == 200);
    }
}

TEST_CASE("serve safety: a change that is not JSON is refused (a cross-site simple request)") {
    ServerFixture fixture("mirror-sphere.toml");
    Api api(fixture.session);
    api.listenOn("127.0.0.1", kPort);
    const int before = sppOf(api);
    REQUIRE(before != 4096);
    for (const std::string& type : std::vector<std::string>{"text/plain", "text/plain;charset=UTF-8", "application/x-www-form-urlencoded",
                                   "multipart/form-data; boundary=x", "application/jsonx", "application/json-patch+json", ""}) {
        CAPTURE(type);
        for (const char* method : {"PUT", "POST"})
            checkRefused(api.handle({method, "/api/settings", {{"Host", kOwnHost}, {"Content-Type", type}}, "{\"spp\": 4096}"}), 403,
                         "Content-Type", std::string(method) + " needs Content-Type: application/json");
    }
    checkRefused(api.handle({"POST", "/api/settings", {{"Host", kOwnHost}}, "{\"spp\": 4096}"}), 403, "Content-Type", "got none");
    checkRefused(api.handle({"DELETE", "/api/settings", {{"Host", kOwnHost}}, ""}), 403, "Content-Type", "DELETE needs");
    CHECK(sppOf(api) == before);
    // JSON, with parameters or in capitals, is accepted; a known path's other methods are 405.
    for (const std::string& type : std::vector<std::string>{"application/json; charset=utf-8", "Application/JSON", " application/json ;charset=utf-8"}) {
        CAPTURE(type);
        CHECK(api.handle(putJson("{\"spp\": 8}", {}, type)).status == 200);
    }
    CHECK(sppOf(api) == 8);
    const Response deleted = api.handle({"DELETE", "/api/settings", {{"Host", kOwnHost}, {"Content-Type", "application/json"}}, ""});
    checkRefused(deleted, 405, "", "DELETE /api/settings: expected GET, HEAD, PUT, POST");

    // Through the socket, as the issue measured it: text/plain from another site's page.
    const auto r = fixture.client()->Post("/api/settings", {{"Origin", "http://evil.example"}}, "{\"spp\": 4096}", "text/plain");
    REQUIRE(r);
    CHECK(r->status == 403);
    CHECK(json::parse(r->body)["error"].is_string());
    const auto plain = fixture.client()->Post("/api/settings", "{\"spp\": 4096}", "text/plain");
    REQUIRE(plain);
    CHECK(plain->status == 403);
    CHECK(sppOf(api) == 8);
}

TEST_CASE("serve safety: only the server's own Origin may send requests") {
    ServerFixture fixture("mirror-sphere.toml");
    Api api(fixture.session);
    api.listenOn("127.0.0.1", kPort);
    const std::string port = std::to_string(kPort);
    for (const std::string& origin : std::vector<std::string>{"http://evil.example", "http://evil.example:" + port, "null", "https://127.0.0.1:" + port,
                                     "http://127.0.0.1:" + std::to_string(kPort + 1), "http://127.0.0.1", "127.0.0.1:" + port,
                                     "http://127.0.0.1:" + port + "/", "file://", ""}) {
        CAPTURE(origin);
        checkRefused(api.handle(putJson("{\"spp\": 4096}", {{"Origin", origin}})), 403, "Origin", "is not this server's page");
        checkRefused(api.handle(get("/api/scene", {{"Host", kOwnHost}, {"Origin", origin}})), 403, "Origin", "another site");
    }
    CHECK(sppOf(api) != 4096);
    // The page's own origin, in each of the server's names, and no Origin at all (curl, the tests).
    for (const std::string& origin : std::vector<std::string>{"http://127.0.0.1:" + port, "http://localhost:" + port, "http://[::1]:" + port}) {
        CAPTURE(origin);
        CHECK(api.handle(putJson("{\"spp\": 12}", {{"Origin", origin}})).status == 200);
    }
    CHECK(api.handle(putJson("{\"spp\": 9}")).status == 200);
    CHECK(sppOf(api) == 9);

    // Through the socket: the page's own PUT, as web/app.js sends it.
    const std::string own = "http://127.0.0.1:" + std::to_string(fixture.port);
    const auto r = fixture.client()->Put("/api/settings", {{"Origin", own}}, "{\"spp\": 3}", "application/json");
    REQUIRE(r);
    CHECK(r->status == 200);
    const auto foreign = fixture.client()->Put("/api/settings", {{"Origin", "http://evil.example"}}, "{\"spp\": 5}", "application/json");
    REQUIRE(foreign);
    CHECK(foreign->status == 403);
    CHECK(json::parse(fixture.client()->Get("/api/settings")->body)["settings"]["spp"] == 3);
}
