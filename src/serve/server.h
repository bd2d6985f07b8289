#pragma once
// The HTTP face of a Session (docs/serve.md): the page's files, and a small JSON API over the
// renderer. No request path is ever a file path; every refused request gets a 4xx and a JSON
// {"error": ...} naming what was wrong.
#include <memory>
#include <string>

#include "serve/session.h"

namespace httplib {
class Server;
}

namespace lightpath::serve {

// Bounds on one request.
inline constexpr std::size_t kMaxBodyBytes = 64 * 1024;
inline constexpr double kMaxWaitSeconds = 10.0;  // GET /api/progress?wait=...
inline constexpr int kIoTimeoutSeconds = 5;       // reading a request, writing a response

class Server {
public:
    explicit Server(Session& session);
    ~Server();

    // Binds host:port (0: any free port) and returns the port; throws std::runtime_error.
    int bind(const std::string& host, int port);
    // Serves until stop(); call after bind().
    void run();
    // From any thread: the listening loop ends and run() returns.
    void stop();

private:
    void routes();

    Session& session_;
    std::unique_ptr<httplib::Server> http_;
    std::mutex automatonMutex_;
    std::uint64_t automatonGeneration_ = 0;
    std::string automatonSvg_;
};

}  // namespace lightpath::serve
