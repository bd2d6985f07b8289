#pragma once
// The HTTP API of `lightpath serve` (docs/serve.md) as a function from a request to its answer:
// the page's files, and a small JSON API over a Session. No request path is ever a file path;
// every refused request gets a 4xx and a JSON {"error": ..., "field": ...} naming what was wrong.
// The server (serve/server.h) puts it on a socket; the fuzz target calls it directly.
#include <cstdint>
#include <mutex>
#include <optional>
#include <string>

#include "serve/http_message.h"
#include "serve/request_guard.h"
#include "serve/session.h"

namespace lightpath::serve {

// Bounds on one request.
inline constexpr std::size_t kMaxBodyBytes = 64 * 1024;
inline constexpr double kMaxWaitSeconds = 10.0;  // GET /api/progress?wait=...

class Api {
public:
    explicit Api(Session& session);

    // Which Host and Origin are this server's (serve/request_guard.h): call once the port is
    // known, before the first request. Until then every request is refused.
    void listenOn(const std::string& host, int port);

    // Never throws: the client's mistakes are 4xx, anything else a 500, all with a JSON body.
    // Safe to call from several threads at once.
    Response handle(const Request& request);

private:
    Response route(const Request& request, const Target& target);
    Response automatonSvg();

    Session& session_;
    std::optional<RequestGuard> guard_;
    std::mutex automatonMutex_;
    std::uint64_t automatonGeneration_ = 0;
    std::string automatonSvg_;
};

// {"error": message} with `status`, as every refusal of the API is written.
Response errorResponse(int status, const std::string& message);

}  // namespace lightpath::serve
