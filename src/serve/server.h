#pragma once
// The HTTP face of a Session: the API (serve/api.h) on a socket, with cpp-httplib. Only moving
// requests and answers on and off the socket happens here; what they mean is the API's.
#include <atomic>
#include <memory>
#include <mutex>
#include <string>

#include "serve/api.h"
#include "serve/session.h"

namespace httplib {
class Server;
}

namespace lightpath::serve {

inline constexpr int kIoTimeoutSeconds = 5;  // reading a request, writing a response

class Server {
public:
    explicit Server(Session& session);
    ~Server();

    // Binds host:port (0: any free port) and returns the port; throws std::runtime_error. From
    // then on only requests for this host and port are answered (serve/request_guard.h).
    int bind(const std::string& host, int port);
    // Serves until stop(); call after bind().
    void run();
    // From any thread: the listening loop ends and run() returns.
    void stop();

private:
    Api api_;
    std::unique_ptr<httplib::Server> http_;
    // httplib's stop() does nothing until its listening loop has begun, so a stop() that came
    // first would leave run() in accept() for good: run() and stop() meet here instead.
    std::mutex lifecycle_;
    bool stopRequested_ = false;  // under lifecycle_
    bool entered_ = false;        // run() is past its check, under lifecycle_
    std::atomic<bool> returned_{false};
};

}  // namespace lightpath::serve
